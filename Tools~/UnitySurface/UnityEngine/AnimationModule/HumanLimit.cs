// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    // Private fields behind public properties.
    public struct HumanLimit
    {
        public bool useDefaultValues { get => throw null; set => throw null; }
    }
}
