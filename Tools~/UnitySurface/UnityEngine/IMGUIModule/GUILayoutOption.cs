// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/IMGUI/GUILayoutOption.cs
    // Made only by GUILayout's option functions (its constructor is internal).
    public sealed class GUILayoutOption
    {
        private GUILayoutOption() => throw null;
    }
}
