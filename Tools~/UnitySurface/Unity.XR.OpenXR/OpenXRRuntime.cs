// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.XR.OpenXR
{
    // com.unity.xr.openxr@1.0.2 Runtime/OpenXRRuntime.cs
    public static class OpenXRRuntime
    {
        public static bool IsExtensionEnabled(string extensionName) => throw null;
    }
}
