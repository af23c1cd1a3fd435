// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/GameObject.bindings.cs
    public sealed class GameObject : Object
    {
        public Transform transform => throw null;
    }
}
