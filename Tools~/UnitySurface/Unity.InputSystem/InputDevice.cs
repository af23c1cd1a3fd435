// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// The Input System's InputDevice (a class), not UnityEngine.XR.InputDevice (a struct).

using UnityEngine.InputSystem.Layouts;

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Devices/InputDevice.cs
    public class InputDevice : InputControl
    {
        public InputDeviceDescription description => throw null;
    }
}
