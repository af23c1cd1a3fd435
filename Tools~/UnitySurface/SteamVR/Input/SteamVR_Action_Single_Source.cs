// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Its base class and interface are left out: only named as a type argument.

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Action_Single.cs
    public class SteamVR_Action_Single_Source
    {
    }
}
