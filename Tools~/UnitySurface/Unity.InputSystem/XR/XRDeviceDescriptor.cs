// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using UnityEngine.XR;

namespace UnityEngine.InputSystem.XR
{
    // com.unity.inputsystem@1.0.2 InputSystem/Plugins/XR/XRSupport.cs
    public class XRDeviceDescriptor
    {
        public InputDeviceCharacteristics characteristics;

        public static XRDeviceDescriptor FromJson(string json) => throw null;
    }
}
