// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    // limit is a field; boneName and humanName are properties.
    public struct HumanBone
    {
        public HumanLimit limit;

        public string boneName { get => throw null; set => throw null; }

        public string humanName { get => throw null; set => throw null; }
    }
}
