// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's SteamVR_Action_Single also implements ISteamVR_Action_Single and ISerializationCallbackReceiver.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Action_Single.cs
    public class SteamVR_Action_Single : SteamVR_Action_In<SteamVR_Action_Single_Source_Map, SteamVR_Action_Single_Source>
    {
        public float GetAxis(SteamVR_Input_Sources inputSource) => throw null;
    }
}
