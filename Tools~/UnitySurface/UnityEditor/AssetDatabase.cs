// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEditor
{
    // UnityCsReference@2021.3 Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs
    // Sealed in Editor/Mono/AssetDatabase/AssetDatabase.cs. Only the overloads the package calls (ImportAsset and Refresh
    // without ImportAssetOptions).
    public sealed partial class AssetDatabase
    {
        public static void ImportAsset(string path) => throw null;

        public static T LoadAssetAtPath<T>(string assetPath) where T : UnityEngine.Object => throw null;

        public static void Refresh() => throw null;
    }
}
