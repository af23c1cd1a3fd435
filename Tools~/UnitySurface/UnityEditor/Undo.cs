// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/Undo/Undo.bindings.cs
    public partial class Undo
    {
        public static void RegisterCreatedObjectUndo(UnityEngine.Object objectToUndo, string name) => throw null;

        public static T AddComponent<T>(UnityEngine.GameObject gameObject) where T : UnityEngine.Component => throw null;

        public static void RecordObject(UnityEngine.Object objectToUndo, string name) => throw null;
    }
}
