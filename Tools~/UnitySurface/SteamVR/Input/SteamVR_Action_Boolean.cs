// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's SteamVR_Action_Boolean also implements ISteamVR_Action_Boolean and ISerializationCallbackReceiver.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Action_Boolean.cs
    public class SteamVR_Action_Boolean : SteamVR_Action_In<SteamVR_Action_Boolean_Source_Map, SteamVR_Action_Boolean_Source>
    {
        public bool GetState(SteamVR_Input_Sources inputSource) => throw null;
    }
}
