// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputActionReference also has action, asset, Set, ToInputAction and Create members; the package only asks
// whether an InputActionProperty holds one.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Actions/InputActionReference.cs
    public class InputActionReference : ScriptableObject
    {
    }
}
