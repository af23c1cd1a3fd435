using System.IO;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>The package root and the mocap clips the package ships for its tests (Tests/Core/Data~).</summary>
public static class Paths
{
    public static string PackageRoot { get; } = Find();

    /// <summary>A clip of Tests/Core/Data~ (mocapbank_30fps.bvh, mixamo_fingers_30fps.bvh, rigify_6channel_24fps_first240.bvh).</summary>
    public static string Mocap(string file)
    {
        string path = Path.Combine(PackageRoot, "Tests", "Core", "Data~", file);
        if (!File.Exists(path)) Assert.Fail($"Tests/Core/Data~/{file} is missing from the package");
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
