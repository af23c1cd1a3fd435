// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.InputSystem.XR
{
    // com.unity.inputsystem@1.0.2 InputSystem/Plugins/XR/XRSupport.cs
    public static class XRUtilities
    {
        public const string InterfaceMatchAnyVersion = "^(XRInput)";
    }
}
