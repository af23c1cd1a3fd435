// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using System;

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/MenuItem.cs
    // Only the constructor the package calls; the public fields (menuItem, validate, priority, editorModes) are left out.
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName, bool isValidateFunction, int priority) => throw null;
    }
}
