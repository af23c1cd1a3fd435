// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/EditorGUILayout.cs
    // Public in its other partial declarations (e.g. Editor/Mono/GUI/AngularDial.cs). Only the overload the package calls.
    public sealed partial class EditorGUILayout
    {
        public static void HelpBox(string message, MessageType type) => throw null;
    }
}
