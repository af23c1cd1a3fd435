// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's SteamVR also implements IDisposable. GetStringProperty's parameter type comes from openvr_api.cs, compiled into
// this assembly without OPENVR_XR_API and into Unity.XR.OpenVR with it: only the latter is declared (AvatarGo reads serials
// only with the OpenVR XR plug-in). Its default deviceId is OpenVR.k_unTrackedDeviceIndex_Hmd (0); AvatarGo always passes one.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Scripts/SteamVR.cs
    public class SteamVR
    {
        public static bool active => throw null;

        public static SteamVR instance => throw null;

#if OPENVR_XR_API
        public string GetStringProperty(ETrackedDeviceProperty prop, uint deviceId = 0) => throw null;
#endif
    }
}
