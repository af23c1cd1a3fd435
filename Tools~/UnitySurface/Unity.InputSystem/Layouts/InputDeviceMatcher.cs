// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputDeviceMatcher also implements IEquatable<InputDeviceMatcher>.

namespace UnityEngine.InputSystem.Layouts
{
    // com.unity.inputsystem@1.0.2 InputSystem/Devices/InputDeviceMatcher.cs
    public struct InputDeviceMatcher
    {
        public InputDeviceMatcher WithInterface(string pattern, bool supportRegex = true) => throw null;

        public InputDeviceMatcher WithProduct(string pattern, bool supportRegex = true) => throw null;
    }
}
