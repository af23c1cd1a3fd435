// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Object also overrides Equals and GetHashCode; the package calls neither, so they are not declared here.
#pragma warning disable CS0660, CS0661

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public class Object
    {
        public string name { get => throw null; set => throw null; }

#if UNITY_2023_1_OR_NEWER
        [System.Obsolete("Object.FindObjectOfType has been deprecated. Use Object.FindFirstObjectByType instead or if finding any instance is acceptable the faster Object.FindAnyObjectByType", false)]
#endif
        public static T FindObjectOfType<T>() where T : Object => throw null;

        // From 2021.3.18f1 (engine-api.md T5); declared where every release has it.
#if UNITY_2023_1_OR_NEWER
        public static T FindAnyObjectByType<T>() where T : Object => throw null;
#endif

        public static bool operator ==(Object x, Object y) => throw null;

        public static bool operator !=(Object x, Object y) => throw null;

        public static T Instantiate<T>(T original, Transform parent) where T : Object => throw null;

        // Deferred to the end of the frame.
        public static void Destroy(Object obj) => throw null;

        public static void DestroyImmediate(Object obj) => throw null;
    }
}
