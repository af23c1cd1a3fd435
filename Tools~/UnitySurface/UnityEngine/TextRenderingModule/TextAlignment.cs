// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/TextRendering/TextRendering.bindings.cs
    public enum TextAlignment
    {
        Left = 0,
        Center = 1,
        Right = 2,
    }
}
