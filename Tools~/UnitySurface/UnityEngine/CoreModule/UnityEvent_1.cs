// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.Events
{
    // A generic UnityEvent field is serialized directly from Unity 2020.1.
    // UnityCsReference@2021.3 Runtime/Export/UnityEvent/UnityEvent/UnityEvent_1.cs
    public class UnityEvent<T0> : UnityEventBase
    {
        public UnityEvent() => throw null;

        public void Invoke(T0 arg0) => throw null;
    }
}
