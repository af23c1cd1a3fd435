// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // Unity's Material has only constructors with parameters; none is declared here (the package creates no material).
    // UnityCsReference@2021.3 Runtime/Export/Shaders/Material.bindings.cs
    public partial class Material : Object
    {
    }
}
