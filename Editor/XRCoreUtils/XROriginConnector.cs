using Unity.XR.CoreUtils;
using UnityEditor;
using UnityEngine;

namespace AvatarGo.Editor
{
    /// <summary>
    /// The Editor's link to an XR Origin (compiled only with XR Core Utilities): whether the open scenes have one, and
    /// connecting a tracking source to it through the runtime's <see cref="XROriginTrackingSetup"/> (its
    /// <see cref="XROriginTrackingSetup.Apply"/> sets the source's tracking-space origin to the origin's camera offset and
    /// finds the rig's HMD and controllers by the same rules it uses at run time), with Undo.
    /// </summary>
    public static class XROriginConnector
    {
        /// <summary>True when a loaded scene has an XR Origin.</summary>
        public static bool SceneHasXROrigin() => FindOrigin() != null;

        /// <summary>True when <paramref name="source"/>'s object carries an XR Origin Tracking Setup.</summary>
        public static bool HasTrackingSetup(AvatarGoTrackingSource source) =>
            source != null && source.GetComponent<XROriginTrackingSetup>() != null;

        /// <summary>
        /// Connects <paramref name="source"/> to the scene's XR Origin: an XR Origin Tracking Setup on the source's object
        /// (added when missing) names the origin and the source and is applied now, so the source's Tracking Space Origin
        /// is the origin's camera offset in the saved scene; each change is recorded under <paramref name="undoName"/>.
        /// False when there is no source or no XR Origin.
        /// </summary>
        public static bool Connect(AvatarGoTrackingSource source, string undoName)
        {
            if (source == null) return false;
            XROrigin origin = FindOrigin();
            if (origin == null) return false;
            XROriginTrackingSetup setup = source.GetComponent<XROriginTrackingSetup>();
            if (setup == null) setup = Undo.AddComponent<XROriginTrackingSetup>(source.gameObject);
            Undo.RecordObject(setup, undoName);
            Undo.RecordObject(source, undoName);
            setup.Origin = origin;
            setup.Source = source;
            return setup.Apply();
        }

        private static XROrigin FindOrigin()
        {
#if UNITY_2023_1_OR_NEWER
            return Object.FindAnyObjectByType<XROrigin>();
#else
            return Object.FindObjectOfType<XROrigin>();
#endif
        }
    }
}
