// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.Events
{
    // Unity's UnityEventBase also implements ISerializationCallbackReceiver; not declared until the package uses it.
    // UnityCsReference@2021.3 Runtime/Export/UnityEvent/UnityEvent.cs
    public abstract class UnityEventBase
    {
    }
}
