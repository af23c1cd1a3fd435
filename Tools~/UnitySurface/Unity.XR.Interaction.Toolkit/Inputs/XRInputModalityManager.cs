// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// From XRI 2.4.0; AvatarGo uses it only with XRI 2.4.0 or newer (AVATARGO_XRI_2_4_OR_NEWER). It does not exist in 2.0.0, the
// oldest version the surface's other types are checked against.

#if XRI_2_4_OR_NEWER
namespace UnityEngine.XR.Interaction.Toolkit.Inputs
{
    // com.unity.xr.interaction.toolkit@2.4.0 Runtime/Inputs/XRInputModalityManager.cs
    public class XRInputModalityManager : MonoBehaviour
    {
        public GameObject leftController { get => throw null; set => throw null; }

        public GameObject rightController { get => throw null; set => throw null; }
    }
}
#endif
