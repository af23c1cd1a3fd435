// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's Pose has isTracked, trackingState, position, rotation, velocity and angularVelocity; the package reads the pose
// through the control's bindings, not this struct.

namespace UnityEngine.XR.OpenXR.Input
{
    // com.unity.xr.openxr@1.0.2 Runtime/input/PoseControl.cs
    public struct Pose
    {
    }
}
