// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Public static fields (not readonly, not properties), as Unity declares them; the value is the native usage name.

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    public static class CommonUsages
    {
        public static InputFeatureUsage<bool> isTracked;

        public static InputFeatureUsage<bool> triggerButton;

        public static InputFeatureUsage<InputTrackingState> trackingState;

        public static InputFeatureUsage<float> trigger;

        public static InputFeatureUsage<float> grip;

        public static InputFeatureUsage<Vector3> devicePosition;

        public static InputFeatureUsage<Vector3> centerEyePosition;

        public static InputFeatureUsage<Quaternion> deviceRotation;

        public static InputFeatureUsage<Quaternion> centerEyeRotation;
    }
}
