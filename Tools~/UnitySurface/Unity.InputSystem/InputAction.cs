// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputAction also implements ICloneable and IDisposable, and has many more members.

using UnityEngine.InputSystem.Utilities;

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Actions/InputAction.cs
    public sealed class InputAction
    {
        public InputAction(string name = null, InputActionType type = default, string binding = null,
            string interactions = null, string processors = null, string expectedControlType = null) => throw null;

        public ReadOnlyArray<InputBinding> bindings => throw null;

        public ReadOnlyArray<InputControl> controls => throw null;

        public bool enabled => throw null;

        public void Dispose() => throw null;

        public void Enable() => throw null;

        public void Disable() => throw null;

        public TValue ReadValue<TValue>() where TValue : struct => throw null;
    }
}
