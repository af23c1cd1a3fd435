// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public class AvatarBuilder
    {
        // A bad description does not throw: Unity logs and returns an Avatar whose isValid/isHuman is false.
        public static Avatar BuildHumanAvatar(GameObject go, HumanDescription humanDescription) => throw null;
    }
}
