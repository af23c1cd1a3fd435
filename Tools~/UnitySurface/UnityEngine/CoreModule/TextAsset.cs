// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/TextAsset.bindings.cs
    public partial class TextAsset : Object
    {
        // Decodes the asset's bytes each time it is read (allocates).
        // UnityCsReference@2021.3 Runtime/Export/Scripting/TextAsset.cs
        public string text => throw null;
    }
}
