// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputActionProperty also has a constructor from an InputActionReference, and equality members.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Actions/InputActionProperty.cs
    [System.Serializable]
    public struct InputActionProperty
    {
        public InputAction action => throw null;

        public InputActionReference reference => throw null;

        public InputActionProperty(InputAction action) => throw null;
    }
}
