// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // GameObject.CreatePrimitive adds one; the package only removes it (markers must not be hit by rays or bodies).
    // UnityCsReference@2021.3 Modules/Physics/ScriptBindings/Dynamics.bindings.cs
    public partial class Collider : Component
    {
    }
}
