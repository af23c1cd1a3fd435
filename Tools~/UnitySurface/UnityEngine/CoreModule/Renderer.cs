// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Graphics/GraphicsRenderers.bindings.cs
    public partial class Renderer : Component
    {
        public Material sharedMaterial { get => throw null; set => throw null; }

        public bool forceRenderingOff { get => throw null; set => throw null; }
    }
}
