// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// In the runtime assembly Unity.XR.OpenXR, inside #if UNITY_EDITOR (not in Unity.XR.OpenXR.Editor), namespace UnityEditor.
// Unity's attribute also has Hidden, CustomRuntimeLoaderBuildTargets, BuildTargetGroups (UnityEditor.BuildTargetGroup[];
// left null by AvatarGo: the feature is offered on every platform), Required and Priority.

#if UNITY_EDITOR
namespace UnityEditor.XR.OpenXR.Features
{
    // com.unity.xr.openxr@1.0.2 Runtime/Features/OpenXRFeatureAttribute.cs
    [System.AttributeUsage(System.AttributeTargets.Class)]
    public class OpenXRFeatureAttribute : System.Attribute
    {
        public string UiName;

        public string Desc;

        public string OpenxrExtensionStrings;

        public string Company;

        public string DocumentationLink;

        public string Version;

        public string Category = "";

        public string FeatureId = "";
    }
}
#endif
