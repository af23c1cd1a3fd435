// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem.Layouts
{
    // com.unity.inputsystem@1.0.2 InputSystem/Controls/InputControlAttribute.cs
    [System.AttributeUsage(System.AttributeTargets.Field | System.AttributeTargets.Property, AllowMultiple = true)]
    public sealed class InputControlAttribute : PropertyAttribute
    {
        public string usage { get => throw null; set => throw null; }

        public uint offset { get => throw null; set => throw null; }
    }
}
