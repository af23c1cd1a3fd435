// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/GameObjectUtility.bindings.cs
    public sealed partial class GameObjectUtility
    {
        public static void SetParentAndAlign(UnityEngine.GameObject child, UnityEngine.GameObject parent) => throw null;
    }
}
