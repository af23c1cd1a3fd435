// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Camera/Camera.bindings.cs
    public sealed class Camera : Behaviour
    {
    }
}
