// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // A struct, not a static class.
    // UnityCsReference@2021.3 Runtime/Export/Math/Mathf.cs
    public partial struct Mathf
    {
        public static float Clamp01(float value) => throw null;
    }
}
