// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using System.Collections.Generic;

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/Component.bindings.cs
    public class Component : Object
    {
        public Transform transform => throw null;

        public GameObject gameObject => throw null;

        public T GetComponent<T>() => throw null;

        public T GetComponentInChildren<T>(bool includeInactive) => throw null;

        public T[] GetComponentsInChildren<T>(bool includeInactive) => throw null;

        public void GetComponentsInChildren<T>(bool includeInactive, List<T> result) => throw null;

        public T GetComponentInParent<T>() => throw null;
    }
}
