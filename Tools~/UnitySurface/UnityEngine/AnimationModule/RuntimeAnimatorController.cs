// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/RuntimeAnimatorController.bindings.cs
    public partial class RuntimeAnimatorController : Object
    {
        protected RuntimeAnimatorController() => throw null;
    }
}
