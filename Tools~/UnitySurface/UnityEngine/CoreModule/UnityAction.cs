// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.Events
{
    // UnityCsReference@2021.3 Runtime/Export/UnityEvent/UnityEvent/UnityEvent_0.cs
    public delegate void UnityAction();
}
