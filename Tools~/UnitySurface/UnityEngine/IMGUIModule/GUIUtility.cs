// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/IMGUI/GUIUtility.cs
    public partial class GUIUtility
    {
        // Ends the current IMGUI event by throwing ExitGUIException, which Unity's GUI code catches: call it after
        // changing the scene from a button so that the rest of the inspector is not laid out against the old state.
        public static void ExitGUI() => throw null;
    }
}
