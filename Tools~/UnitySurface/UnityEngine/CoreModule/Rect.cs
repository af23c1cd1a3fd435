// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Geometry/Rect.cs
    // Unity's Rect also implements IEquatable<Rect> and IFormattable; not declared until the package uses them.
    public partial struct Rect
    {
        public Rect(float x, float y, float width, float height) => throw null;
    }
}
