// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputFeatureUsage also implements IEquatable<InputFeatureUsage> and has type, As<T>, Equals and == / !=; the
// package only reads names.

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    public struct InputFeatureUsage
    {
        public string name { get => throw null; internal set => throw null; }
    }
}
