// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // AnimatePhysics (1) became Fixed (1) in 2023.1, the old name obsolete as an error: trap T2.
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum AnimatorUpdateMode
    {
        Normal = 0,
#if UNITY_2023_1_OR_NEWER
        // UnityCsReference@2023.1 Modules/Animation/ScriptBindings/Animator.bindings.cs
        Fixed = 1,
#endif
        UnscaledTime = 2,
#if UNITY_2023_1_OR_NEWER
        // UnityCsReference@2023.1 Modules/Animation/ScriptBindings/Animator.bindings.cs
        [System.Obsolete("Enum member AnimatorUpdateMode.AnimatePhysics has been deprecated. Use AnimatorUpdateMode.Fixed to evaluate in FixedUpdate time and Animator.animatePhysics to sync transforms for physics. (UnityUpgradable) -> Fixed", true)]
#endif
        AnimatePhysics = 1,
    }
}
