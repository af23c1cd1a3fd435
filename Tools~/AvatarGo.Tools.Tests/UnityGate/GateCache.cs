using System.IO;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// The compile cache the gate tests share (Tools~/out/gate-cache), emptied once per test run: an assembly compiled
/// successfully earlier in the run from the same bytes, options and references is referenced instead of compiled
/// again, so planted copies only compile what the plant changed. Nothing survives from an earlier run.
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
