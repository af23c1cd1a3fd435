// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.XR.OpenXR.Input
{
    // com.unity.xr.openxr@1.0.2 Runtime/input/OpenXRDevice.cs
    public abstract class OpenXRDevice : UnityEngine.InputSystem.InputDevice
    {
        protected override void FinishSetup() => throw null;
    }
}
