// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Editor/Mono/Prefabs/PrefabUtility.cs
    // Only the overload the package calls (the Scene and Transform overloads are left out).
    public sealed partial class PrefabUtility
    {
        public static UnityEngine.Object InstantiatePrefab(UnityEngine.Object assetComponentOrGameObject) => throw null;
    }
}
