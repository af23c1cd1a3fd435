// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Resources/Resources.bindings.cs
    public sealed partial class Resources
    {
        // Throws ArgumentException for a name the editor does not have: the built-in font is "Arial.ttf" until 2022.1 and
        // "LegacyRuntime.ttf" from 2022.2 (trap T9).
        public static T GetBuiltinResource<T>(string path) where T : Object => throw null;

        // A path under any Resources folder (packages' included), without its extension; null when there is none.
        public static T Load<T>(string path) where T : Object => throw null;
    }
}
