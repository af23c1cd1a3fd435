// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/MenuCommand.cs
    // A menu function's parameter; for a GameObject menu item, context is the object right-clicked in the Hierarchy (or null).
    public sealed class MenuCommand
    {
        public UnityEngine.Object context;
    }
}
