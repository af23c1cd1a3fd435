// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// openvr_api.cs is wrapped in #if !OPENVR_XR_API; Unity.XR.OpenVR's asmdef never defines it, so it always compiles here.
// Only the value the package uses is declared.

namespace Valve.VR
{
    // unity-xr-plugin@v1.1.4 com.valve.openvr/Runtime/openvr_api.cs
    public enum ETrackedDeviceProperty
    {
        Prop_SerialNumber_String = 1002,
    }
}
