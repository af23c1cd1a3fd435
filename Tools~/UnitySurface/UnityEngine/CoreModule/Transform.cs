// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Transform also implements IEnumerable (its children); not declared until the package enumerates children.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Transform/ScriptBindings/Transform.bindings.cs
    public class Transform : Component
    {
        protected Transform() => throw null;

        public Vector3 position { get => throw null; set => throw null; }

        public Vector3 localPosition { get => throw null; set => throw null; }

        public Quaternion rotation { get => throw null; set => throw null; }

        public Quaternion localRotation { get => throw null; set => throw null; }

        // Safe in every 2021.3 patch; SetLocalPositionAndRotation (2021.3.11f1) and GetPositionAndRotation (2021.3.17f1) are not.
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation) => throw null;

        public Vector3 localScale { get => throw null; set => throw null; }

        // Uniform scales only: a non-uniform scale shears the children.
        public Vector3 lossyScale => throw null;

        public Transform parent { get => throw null; set => throw null; }

        public void SetParent(Transform parent, bool worldPositionStays) => throw null;

        public int childCount => throw null;

        public Transform GetChild(int index) => throw null;
    }
}
