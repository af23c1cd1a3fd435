// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.Events
{
    // Serializable; its persistent listeners are set in the inspector.
    // UnityCsReference@2021.3 Runtime/Export/UnityEvent/UnityEvent/UnityEvent_0.cs
    public class UnityEvent : UnityEventBase
    {
        public UnityEvent() => throw null;

        public void Invoke() => throw null;
    }
}
