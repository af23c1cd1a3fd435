// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Quaternion also implements IEquatable<Quaternion> and IFormattable; not declared until the package uses them.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Math/Quaternion.cs
    public struct Quaternion
    {
        public float x;

        public float y;

        public float z;

        public float w;

        public Quaternion(float x, float y, float z, float w) => throw null;
    }
}
