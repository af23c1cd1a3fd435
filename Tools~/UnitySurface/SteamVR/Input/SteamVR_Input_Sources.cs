// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// The values of 2.7.3 (the oldest plug-in AvatarGo supports); 2.8.0 adds knees, elbows, wrists and ankles after Treadmill.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Input_Sources.cs
    public enum SteamVR_Input_Sources
    {
        Any,
        LeftHand,
        RightHand,
        LeftFoot,
        RightFoot,
        LeftShoulder,
        RightShoulder,
        Waist,
        Chest,
        Head,
        Gamepad,
        Camera,
        Keyboard,
        Treadmill,
    }
}
