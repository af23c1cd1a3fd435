// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Obsolete (a warning, an error here) from XRI 3.0.0; AvatarGo uses the XRI 2.x controllers only with XRI 2.x (AVATARGO_XRI_2).

namespace UnityEngine.XR.Interaction.Toolkit
{
    // com.unity.xr.interaction.toolkit@2.0.0 Runtime/Interaction/Controllers/XRBaseController.cs
#if XRI_3_OR_NEWER
    [System.Obsolete("XRBaseController has been deprecated in version 3.0.0. Its functionality has been distributed into different components.")]
#endif
    public abstract class XRBaseController : MonoBehaviour
    {
    }
}
