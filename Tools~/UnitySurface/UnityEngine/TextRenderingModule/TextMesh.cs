// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // Unity also puts [RequireComponent(typeof(Transform), typeof(MeshRenderer))] on it: AddComponent adds the MeshRenderer.
    // UnityCsReference@2021.3 Modules/TextRendering/TextRendering.bindings.cs
    public sealed class TextMesh : Component
    {
        public string text { get => throw null; set => throw null; }

        public Font font { get => throw null; set => throw null; }

        public int fontSize { get => throw null; set => throw null; }

        public TextAlignment alignment { get => throw null; set => throw null; }

        public TextAnchor anchor { get => throw null; set => throw null; }

        public float characterSize { get => throw null; set => throw null; }
    }
}
