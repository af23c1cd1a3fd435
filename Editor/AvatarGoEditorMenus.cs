using System;
using System.IO;
using AvatarGo.Core;
using UnityEditor;
using UnityEngine;

namespace AvatarGo.Editor
{
    /// <summary>
    /// The package's menu items (Documentation~/editor-tooling.md): <c>GameObject &gt; XR &gt; AvatarGo Self-Avatar</c> and
    /// <c>Assets &gt; AvatarGo &gt; Import Session or BVH...</c>. No exception leaves a command: it is logged with context
    /// or shown in a dialog.
    /// </summary>
    internal static class AvatarGoEditorMenus
    {
        /// <summary>The package's prefab, as the asset database names it (package name from package.json).</summary>
        internal const string PrefabPath = "Packages/com.avatargo.selfavatar/Runtime/Prefabs/AvatarGo.prefab";

        internal const string CreateMenu = "GameObject/XR/AvatarGo Self-Avatar";

        internal const string ImportMenu = "Assets/AvatarGo/Import Session or BVH...";

        private const string CreateUndo = "Create AvatarGo Self-Avatar";

        private const string DialogTitle = "AvatarGo";

        // Priority 10 puts it in the Hierarchy's context menu (GameObject items up to 49 are shown there).
        [MenuItem(CreateMenu, false, 10)]
        private static void CreateSelfAvatar(MenuCommand command)
        {
            try
            {
                GameObject prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabPath);
                if (prefab == null)
                {
                    Debug.LogError("AvatarGo: the prefab was not found at " + PrefabPath + ". Is the package installed as com.avatargo.selfavatar?", null);
                    return;
                }
                GameObject instance = PrefabUtility.InstantiatePrefab(prefab) as GameObject;
                if (instance == null)
                {
                    Debug.LogError("AvatarGo: the prefab at " + PrefabPath + " could not be instantiated.", prefab);
                    return;
                }
                GameObject parent = command != null ? command.context as GameObject : null;
                if (parent != null) GameObjectUtility.SetParentAndAlign(instance, parent);
                Undo.RegisterCreatedObjectUndo(instance, CreateUndo);
                ConnectToXROrigin(instance);
                Selection.activeObject = instance;
            }
            catch (Exception e)
            {
                Debug.LogError("AvatarGo: " + CreateMenu + " failed: " + e, null);
            }
        }

        private static void ConnectToXROrigin(GameObject instance)
        {
#if AVATARGO_XR_CORE_UTILS
            AvatarGoTrackingSource[] sources = instance.GetComponentsInChildren<AvatarGoTrackingSource>(true);
            AvatarGoTrackingSource source = sources.Length > 0 ? sources[0] : null;
            if (source != null && XROriginConnector.SceneHasXROrigin() && XROriginConnector.Connect(source, CreateUndo))
                Debug.Log("AvatarGo: the self-avatar's tracking source follows the scene's XR Origin (its Camera Offset is the Tracking Space Origin).", source);
#endif
        }

        [MenuItem(ImportMenu, false, 1000)]
        private static void ImportRecording()
        {
            try
            {
                string path = EditorUtility.OpenFilePanel("Import a recorded session or BVH clip", string.Empty, RecordingImport.PanelExtensions);
                if (string.IsNullOrEmpty(path)) return;
                RecordingImportPlan plan = RecordingImport.PlanFile(path);
                if (!plan.IsValid)
                {
                    EditorUtility.DisplayDialog(DialogTitle, "Not imported.\n\n" + plan.Error, "OK");
                    return;
                }
                string project = Path.GetDirectoryName(Application.dataPath);
                string assetPath = RecordingImport.UniqueAssetPath(RecordingImport.DefaultFolder, plan.TargetFileName, p => File.Exists(Path.Combine(project, p)));
                string target = Path.Combine(project, assetPath);
                Directory.CreateDirectory(Path.GetDirectoryName(target));
                File.Copy(path, target, false);
                AssetDatabase.Refresh();
                AssetDatabase.ImportAsset(assetPath);
                TextAsset asset = AssetDatabase.LoadAssetAtPath<TextAsset>(assetPath);
                if (asset == null)
                {
                    EditorUtility.DisplayDialog(DialogTitle, "The file was copied to " + assetPath + " but Unity did not import it as a text asset.", "OK");
                    return;
                }
                Selection.activeObject = asset;
                Debug.Log("AvatarGo: imported " + plan.Summary + " from " + path + " as " + assetPath + ".", asset);
            }
            catch (Exception e)
            {
                Debug.LogError("AvatarGo: " + ImportMenu + " failed: " + e, null);
                EditorUtility.DisplayDialog(DialogTitle, "The import failed: " + e.Message, "OK");
            }
        }
    }
}
