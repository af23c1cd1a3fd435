// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's chain goes on: SteamVR_Action_In<,> : SteamVR_Action<,> : SteamVR_Action (with constraints on the type
// parameters); the package calls only GetDeviceIndex at this level, so the chain and its constraints stop here.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Action_In.cs
    public abstract class SteamVR_Action_In<SourceMap, SourceElement>
    {
        public virtual uint GetDeviceIndex(SteamVR_Input_Sources inputSource) => throw null;
    }
}
