// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using System;
using UnityEngine.InputSystem.Layouts;

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/InputSystem.cs
    public static class InputSystem
    {
        public static void RegisterLayout(Type type, string name = null, InputDeviceMatcher? matches = null) => throw null;

        public static void RemoveLayout(string name) => throw null;

        public static void SetDeviceUsage(InputDevice device, string usage) => throw null;
    }
}
