// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/IMGUI/GUILayout.cs
    // Only the overloads the package calls; the Texture, GUIContent and GUIStyle overloads are left out (leaving them out
    // can only reject valid code).
    public partial class GUILayout
    {
        public static void Label(string text, params GUILayoutOption[] options) => throw null;

        public static bool Button(string text, params GUILayoutOption[] options) => throw null;

        public static void BeginArea(Rect screenRect) => throw null;

        public static void EndArea() => throw null;
    }
}
