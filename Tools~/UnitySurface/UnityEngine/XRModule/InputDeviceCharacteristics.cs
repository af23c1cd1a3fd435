// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    [System.Flags]
    public enum InputDeviceCharacteristics : System.UInt32
    {
        None = 0,
        HeadMounted = 1 << 0,
        Camera = 1 << 1,
        HeldInHand = 1 << 2,
        HandTracking = 1 << 3,
        EyeTracking = 1 << 4,
        TrackedDevice = 1 << 5,
        Controller = 1 << 6,
        TrackingReference = 1 << 7,
        Left = 1 << 8,
        Right = 1 << 9,
        Simulated6DOF = 1 << 10,
    }
}
