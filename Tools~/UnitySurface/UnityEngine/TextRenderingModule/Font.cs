// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/TextRendering/TextRendering.bindings.cs
    public sealed class Font : Object
    {
        public Material material { get => throw null; set => throw null; }
    }
}
