// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputFeatureUsage<T> also has a constructor, name, equality and an explicit conversion; the package only passes
// CommonUsages' values on.

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    public struct InputFeatureUsage<T>
    {
    }
}
