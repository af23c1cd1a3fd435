// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Scripting/Attributes.cs (no AttributeUsage: any target)
    public sealed class AddComponentMenu : System.Attribute
    {
        public AddComponentMenu(string menuName) => throw null;
    }
}
