// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Declared "public partial class" (the generated SteamVR_Input_Actions part adds the actions).

namespace Valve.VR
{
    // steamvr_unity_plugin@2.7.3 Assets/SteamVR/Input/SteamVR_Input.cs
    public class SteamVR_Input
    {
        public static bool initialized;

        public static SteamVR_Action_Pose GetPoseActionFromPath(string path, bool caseSensitive = false) => throw null;

        // Since 2.2b5 (e8956c1); 2.8.2 line 535. GetPoseActionFromPath never returns null: an unknown path gives a placeholder.
        public static bool HasActionPath(string path, bool caseSensitive = false) => throw null;

        public static SteamVR_Action_Single GetSingleActionFromPath(string path, bool caseSensitive = false) => throw null;

        public static SteamVR_Action_Boolean GetBooleanActionFromPath(string path, bool caseSensitive = false) => throw null;
    }
}
