// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's OpenXRFeature has many more (mostly protected internal) hooks; AvatarGo's feature overrides only OnInstanceCreate,
// through OpenXRInteractionFeature.

namespace UnityEngine.XR.OpenXR.Features
{
    // com.unity.xr.openxr@1.0.2 Runtime/Features/OpenXRFeature.cs
    public abstract class OpenXRFeature : ScriptableObject
    {
        protected internal virtual bool OnInstanceCreate(ulong xrInstance) => throw null;
    }
}
