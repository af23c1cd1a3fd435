using System.Collections.Generic;
using System.IO;

namespace AvatarGo.UnityGate;

/// <summary>Checks the surface's declarations against Unity's own sources (placeholder).</summary>
public static class SurfaceVerifier
{
    /// <summary>Problems found.</summary>
    public static List<string> Verify(string surfaceRoot, IReadOnlyDictionary<string, string> sources, TextWriter log) => new();
}
