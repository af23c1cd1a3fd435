// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/EditorUtility.bindings.cs
    // Public in Editor/Mono/EditorUtility.cs. Only the overloads the package calls.
    public partial class EditorUtility
    {
        // An empty string when the user cancels; extension is comma-separated, without dots.
        public static string OpenFilePanel(string title, string directory, string extension) => throw null;

        public static bool DisplayDialog(string title, string message, string ok) => throw null;
    }
}
