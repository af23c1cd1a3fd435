// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/Inspector/CustomEditor.cs
    // Unity's class has no AttributeUsage (so the default: every target, inherited, not multiple).
    public class CustomEditor : System.Attribute
    {
        public CustomEditor(System.Type inspectedType) => throw null;
    }
}
