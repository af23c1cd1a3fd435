// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Controls/InputControl.cs
    public abstract class InputControl<TValue> : InputControl where TValue : struct
    {
    }
}
