// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Marked [Obsolete] (a warning) in 1.6 and later when the project defines USE_INPUT_SYSTEM_POSE_CONTROL (a global define the
// gate does not set); XRViveTracker disables that warning.

using UnityEngine.InputSystem;

namespace UnityEngine.XR.OpenXR.Input
{
    // com.unity.xr.openxr@1.0.2 Runtime/input/PoseControl.cs
    public class PoseControl : InputControl<Pose>
    {
    }
}
