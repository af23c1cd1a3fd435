using System.IO;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// MSBuild's compile cache for the gate tests that build with it (<see cref="CompilerAgreementTests"/>):
/// Tools~/out/gate-cache, emptied once per test run. A project whose content (bytes, options and references) MSBuild
/// built successfully earlier in the run is referenced as a DLL instead of built again. The in-process compiler keeps
/// its own cache in memory. Nothing survives from an earlier run.
/// </summary>
public static class GateCache
{
    private static readonly object Gate = new();
    private static bool _cleared;

    /// <summary>The cache folder, emptied the first time it is asked for in this process.</summary>
    public static string Dir
    {
        get
        {
            string dir = Path.Combine(Paths.PackageRoot, "Tools~", "out", "gate-cache");
            lock (Gate)
            {
                if (!_cleared && Directory.Exists(dir)) Directory.Delete(dir, recursive: true);
                _cleared = true;
            }
            return dir;
        }
    }
}
