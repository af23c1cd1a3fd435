// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using UnityObject = UnityEngine.Object;

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/Inspector/Editor.cs
    // The interfaces Unity's class has (IPreviewable, IToolModeOwner) are left out: the package only derives from it.
    public partial class Editor : UnityEngine.ScriptableObject
    {
        // Setting it throws InvalidOperationException ("You can't set the target on an editor").
        public UnityObject target { get => throw null; set => throw null; }

        public bool DrawDefaultInspector() => throw null;

        public virtual void OnInspectorGUI() => throw null;
    }
}
