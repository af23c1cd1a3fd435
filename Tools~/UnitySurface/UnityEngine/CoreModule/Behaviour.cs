// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/Behaviour.bindings.cs
    public class Behaviour : Component
    {
        public bool enabled { get => throw null; set => throw null; }

        public bool isActiveAndEnabled => throw null;
    }
}
