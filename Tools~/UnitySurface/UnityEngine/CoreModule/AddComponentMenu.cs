// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // no AttributeUsage: any target
    // UnityCsReference@2021.3 Runtime/Export/Scripting/Attributes.cs
    public sealed class AddComponentMenu : System.Attribute
    {
        public AddComponentMenu(string menuName) => throw null;
    }
}
