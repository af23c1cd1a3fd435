// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Object also overrides Equals and GetHashCode; the package calls neither, so they are not declared here.
#pragma warning disable CS0660, CS0661

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public class Object
    {
        public static bool operator ==(Object x, Object y) => throw null;

        public static bool operator !=(Object x, Object y) => throw null;

        public string name { get => throw null; set => throw null; }

        public static T Instantiate<T>(T original, Transform parent) where T : Object => throw null;

        // Deferred to the end of the frame.
        public static void Destroy(Object obj) => throw null;

        public static void DestroyImmediate(Object obj) => throw null;
    }
}
