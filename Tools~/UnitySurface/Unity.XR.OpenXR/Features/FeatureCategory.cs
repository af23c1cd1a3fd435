// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

#if UNITY_EDITOR
namespace UnityEditor.XR.OpenXR.Features
{
    // com.unity.xr.openxr@1.0.2 Runtime/Features/OpenXRFeatureAttribute.cs
    public class FeatureCategory
    {
        public const string Interaction = "Interaction";
    }
}
#endif
