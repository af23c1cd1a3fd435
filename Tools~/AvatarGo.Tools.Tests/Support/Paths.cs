using System.IO;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>The package root and the shared data folder beside the repository.</summary>
public static class Paths
{
    public static string PackageRoot { get; } = Find();

    public static string SharedMocap(string file)
    {
        string path = Path.GetFullPath(Path.Combine(PackageRoot, "..", "shared", "mocap", file));
        if (!File.Exists(path)) Assert.Ignore($"shared clip {file} is not available");
        return path;
    }

    private static string Find()
    {
        for (string dir = TestContext.CurrentContext.TestDirectory; dir != null; dir = Path.GetDirectoryName(dir))
        {
            string manifest = Path.Combine(dir, "package.json");
            if (File.Exists(manifest) && File.ReadAllText(manifest).Contains("\"com.avatargo.selfavatar\"")) return dir;
        }
        throw new DirectoryNotFoundException("package root (package.json of com.avatargo.selfavatar) not found above the test directory");
    }
}
