// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/Attributes.cs
    [System.AttributeUsage(System.AttributeTargets.Class)]
    public class DefaultExecutionOrder : System.Attribute
    {
        public DefaultExecutionOrder(int order) => throw null;
    }
}
