// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/GameObject.bindings.cs
    public sealed partial class GameObject : Object
    {
        // Adds a Collider (PhysicsModule) and the render pipeline's default material.
        public static GameObject CreatePrimitive(PrimitiveType type) => throw null;

        public T GetComponent<T>() => throw null;

        public T[] GetComponentsInChildren<T>(bool includeInactive) => throw null;

        public T AddComponent<T>() where T : Component => throw null;

        public Transform transform => throw null;

        public void SetActive(bool value) => throw null;

        public bool activeInHierarchy => throw null;

        public GameObject(string name) => throw null;
    }
}
