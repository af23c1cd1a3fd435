// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // The obsolete-as-error BasedOnRenderers = 1 is left out.
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum AnimatorCullingMode
    {
        AlwaysAnimate = 0,
        CullUpdateTransforms = 1,
        CullCompletely = 2,
    }
}
