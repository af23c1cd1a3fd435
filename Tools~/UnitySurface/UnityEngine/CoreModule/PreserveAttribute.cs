// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine.Scripting
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/PreserveAttribute.cs
    [System.AttributeUsage(System.AttributeTargets.Method | System.AttributeTargets.Class | System.AttributeTargets.Field | System.AttributeTargets.Property
        | System.AttributeTargets.Constructor | System.AttributeTargets.Interface | System.AttributeTargets.Delegate | System.AttributeTargets.Event
        | System.AttributeTargets.Struct | System.AttributeTargets.Assembly | System.AttributeTargets.Enum, Inherited = false)]
    public class PreserveAttribute : System.Attribute
    {
    }
}
