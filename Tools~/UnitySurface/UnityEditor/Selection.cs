// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/Selection.bindings.cs
    public sealed partial class Selection
    {
        public static UnityEngine.Object activeObject { get => throw null; set => throw null; }
    }
}
