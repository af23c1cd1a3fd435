// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/HumanTrait.bindings.cs
    public class HumanTrait
    {
        // Indexed by the HumanBodyBones value; finger names are spaced words ("Left Thumb Proximal"), not the enum's names.
        public static string[] BoneName => throw null;
    }
}
