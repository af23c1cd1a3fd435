// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // no AttributeUsage: any target
    // UnityCsReference@2021.3 Runtime/Export/Serialization/Serialization.cs
    public sealed class SerializeField : System.Attribute
    {
    }
}
