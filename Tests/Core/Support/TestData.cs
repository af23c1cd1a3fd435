using System;
using System.IO;
using System.Runtime.CompilerServices;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Finds test data. The mocap clips the default tests need ship with the package in <c>Tests/Core/Data~</c> (a
    /// <c>~</c> folder, so Unity never imports them), and are found both under <c>dotnet test</c> and in a Unity project
    /// that installed the package: from this source file's compile-time path, from the test assembly's location
    /// (Unity's <c>Library/ScriptAssemblies</c> lies under the project, whose <c>Packages/</c> or
    /// <c>Library/PackageCache/</c> holds the package), or from the working directory. Only slow suites may use the
    /// larger clips of <c>../shared/mocap</c> beside a checkout; they are ignored where that folder is absent.
    /// </summary>
    public static class TestData
    {
        private const string PackageName = "com.avatargo.selfavatar";
        private const string DataFolder = "Tests/Core/Data~";
        private static string _packageRoot;

        /// <summary>The package root (the folder holding this package's package.json and its test data).</summary>
        public static string PackageRoot => _packageRoot ??= FindPackageRoot();

        /// <summary>
        /// The full path of a clip shipped in <c>Tests/Core/Data~</c>: <c>mocapbank_30fps.bvh</c>,
        /// <c>mixamo_fingers_30fps.bvh</c> or <c>rigify_6channel_24fps_first240.bvh</c> (origins in Third Party Notices.md).
        /// The test fails when it is missing: the package ships it.
        /// </summary>
        public static string Mocap(string fileName)
        {
            string root = PackageRoot;
            if (root == null) Assert.Fail($"the package {PackageName} (with its {DataFolder} folder) was not found from the test assembly");
            string path = Path.Combine(root, DataFolder, fileName);
            if (!File.Exists(path)) Assert.Fail($"{DataFolder}/{fileName} is missing from the package");
            return path;
        }

        /// <summary>The full path of a clip of <c>../shared/mocap</c> beside a checkout; for slow suites only (ignored when absent).</summary>
        public static string SharedMocap(string fileName)
        {
            string root = PackageRoot;
            string path = root == null ? null : Path.GetFullPath(Path.Combine(root, "..", "shared", "mocap", fileName));
            if (path == null || !File.Exists(path)) Assert.Ignore($"shared mocap clip {fileName} is not available here");
            return path;
        }

        /// <summary>The full path of a file inside the package; the test fails when it is missing.</summary>
        public static string InPackage(string relativePath)
        {
            string root = PackageRoot;
            string path = root == null ? null : Path.Combine(root, relativePath);
            if (path == null || !File.Exists(path)) Assert.Fail($"{relativePath} is missing from the package");
            return path;
        }

        private static string FindPackageRoot([CallerFilePath] string thisFile = null)
        {
            // 1. This file's path as the compiler saw it: <package>/Tests/Core/Support/TestData.cs.
            if (!string.IsNullOrEmpty(thisFile))
            {
                string fromSource = Path.GetDirectoryName(Path.GetDirectoryName(Path.GetDirectoryName(Path.GetDirectoryName(thisFile))));
                if (IsPackageRoot(fromSource)) return fromSource;
            }
            // 2. Up from the assembly and the working directory: the package itself, or a Unity project holding it.
            foreach (string start in new[] { Path.GetDirectoryName(typeof(TestData).Assembly.Location), TestContext.CurrentContext.TestDirectory, Directory.GetCurrentDirectory() })
                for (string dir = start; !string.IsNullOrEmpty(dir); dir = Path.GetDirectoryName(dir))
                {
                    if (IsPackageRoot(dir)) return dir;
                    string embedded = Path.Combine(dir, "Packages", PackageName);
                    if (IsPackageRoot(embedded)) return embedded;
                    string cache = Path.Combine(dir, "Library", "PackageCache");
                    if (Directory.Exists(cache))
                        foreach (string candidate in Directory.GetDirectories(cache, PackageName + "@*"))
                            if (IsPackageRoot(candidate)) return candidate;
                }
            return null;
        }

        private static bool IsPackageRoot(string dir)
        {
            if (string.IsNullOrEmpty(dir)) return false;
            string manifest = Path.Combine(dir, "package.json");
            return File.Exists(manifest) && Directory.Exists(Path.Combine(dir, DataFolder))
                   && File.ReadAllText(manifest).Contains("\"" + PackageName + "\"");
        }
    }
}
