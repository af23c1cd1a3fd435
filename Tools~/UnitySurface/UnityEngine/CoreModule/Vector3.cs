// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Vector3 also implements IEquatable<Vector3> and IFormattable; not declared until the package uses them.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Math/Vector3.cs
    public struct Vector3
    {
        public float x;

        public float y;

        public float z;

        public Vector3(float x, float y, float z) => throw null;

        public static Vector3 one => throw null;
    }
}
