// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem.Layouts
{
    // com.unity.inputsystem@1.0.2 InputSystem/Devices/InputDeviceDescription.cs
    public struct InputDeviceDescription
    {
        public string capabilities { get => throw null; set => throw null; }
    }
}
