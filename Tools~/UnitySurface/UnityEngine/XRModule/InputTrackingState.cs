// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    [System.Flags]
    public enum InputTrackingState : System.UInt32
    {
        None = 0,
        Position = 1 << 0,
        Rotation = 1 << 1,
        Velocity = 1 << 2,
        AngularVelocity = 1 << 3,
        Acceleration = 1 << 4,
        AngularAcceleration = 1 << 5,
        All = (1 << 6) - 1,
    }
}
