using System;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Finds test data: the package root (the folder holding this package's package.json) and the shared
    /// mocap clips in <c>../shared/mocap</c> beside the repository. Tests that need a file that is not
    /// there (a Unity project that installed the package from git) are ignored, not failed.
    /// </summary>
    public static class TestData
    {
        private static string _packageRoot;

        /// <summary>The package root, found by walking up from the test assembly and the working directory.</summary>
        public static string PackageRoot => _packageRoot ??= FindPackageRoot();

        /// <summary>The full path of a shared mocap clip; the test is ignored when the clip is absent.</summary>
        public static string SharedMocap(string fileName)
        {
            string root = PackageRoot;
            string path = root == null ? null : Path.GetFullPath(Path.Combine(root, "..", "shared", "mocap", fileName));
            if (path == null || !File.Exists(path)) Assert.Ignore($"shared mocap clip {fileName} is not available here");
            return path;
        }

        /// <summary>The full path of a file inside the package; the test is ignored when absent.</summary>
        public static string InPackage(string relativePath)
        {
            string root = PackageRoot;
            string path = root == null ? null : Path.Combine(root, relativePath);
            if (path == null || !File.Exists(path)) Assert.Ignore($"{relativePath} is not available here");
            return path;
        }

        private static string FindPackageRoot()
        {
            foreach (string start in new[] { TestContext.CurrentContext.TestDirectory, Directory.GetCurrentDirectory() })
            {
                for (string dir = start; !string.IsNullOrEmpty(dir); dir = Path.GetDirectoryName(dir))
                {
                    string manifest = Path.Combine(dir, "package.json");
                    if (File.Exists(manifest) && File.ReadAllText(manifest).Contains("\"com.avatargo.selfavatar\""))
                        return dir;
                }
            }
            return null;
        }
    }
}
