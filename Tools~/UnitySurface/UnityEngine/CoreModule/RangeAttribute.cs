// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // Field only in 2021.3; Field | Property from 6000.0: trap T10
    // UnityCsReference@2021.3 Runtime/Export/PropertyDrawer/PropertyAttribute.cs
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class RangeAttribute : PropertyAttribute
    {
        public RangeAttribute(float min, float max) => throw null;
    }
}
