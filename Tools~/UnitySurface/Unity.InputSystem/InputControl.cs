// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputControl declares abstract members its concrete controls implement; none is used here, so none is declared.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Controls/InputControl.cs
    public abstract class InputControl
    {
        public TControl GetChildControl<TControl>(string path) where TControl : InputControl => throw null;

        protected virtual void FinishSetup() => throw null;
    }
}
