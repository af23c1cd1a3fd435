// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/IMGUI/GUILayoutOption.cs
    // Made only by GUILayout's option functions: its constructor is internal, so package code cannot call it.
    public sealed class GUILayoutOption
    {
        internal enum Type
        {
            fixedWidth, fixedHeight, minWidth, maxWidth, minHeight, maxHeight, stretchWidth, stretchHeight,
            alignStart, alignMiddle, alignEnd, alignJustify, equalSize, spacing,
        }

        internal GUILayoutOption(Type type, object value) => throw null;
    }
}
