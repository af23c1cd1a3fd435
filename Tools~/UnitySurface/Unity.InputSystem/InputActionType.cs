// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Actions/InputActionType.cs
    public enum InputActionType
    {
        Value,
        Button,
        PassThrough,
    }
}
