// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem
{
    // com.unity.inputsystem@1.0.2 InputSystem/Actions/InputBinding.cs
    public struct InputBinding
    {
        public string path { get => throw null; set => throw null; }
    }
}
