// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem.Layouts
{
    // com.unity.inputsystem@1.0.2 InputSystem/Controls/InputControlLayoutAttribute.cs
    [System.AttributeUsage(System.AttributeTargets.Class, Inherited = false)]
    public sealed class InputControlLayoutAttribute : System.Attribute
    {
        public string[] commonUsages { get => throw null; set => throw null; }

        public string displayName { get => throw null; set => throw null; }
    }
}
