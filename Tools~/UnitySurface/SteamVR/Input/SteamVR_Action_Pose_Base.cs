// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using UnityEngine;

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Action_Pose.cs
    public abstract class SteamVR_Action_Pose_Base<SourceMap, SourceElement> : SteamVR_Action_In<SourceMap, SourceElement>
    {
        public Vector3 GetLocalPosition(SteamVR_Input_Sources inputSource) => throw null;

        public Quaternion GetLocalRotation(SteamVR_Input_Sources inputSource) => throw null;

        public bool GetDeviceIsConnected(SteamVR_Input_Sources inputSource) => throw null;

        public bool GetPoseIsValid(SteamVR_Input_Sources inputSource) => throw null;
    }
}
