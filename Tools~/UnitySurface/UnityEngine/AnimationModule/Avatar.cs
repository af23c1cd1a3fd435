// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/Avatar.bindings.cs
    public class Avatar : Object
    {
        private Avatar() => throw null;

        public bool isValid => throw null;

        public bool isHuman => throw null;
    }
}
