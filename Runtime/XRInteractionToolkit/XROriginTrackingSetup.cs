using System.Collections.Generic;
using AvatarGo.Core;
using Unity.XR.CoreUtils;
using UnityEngine;
#if AVATARGO_INPUT_SYSTEM_1_1_OR_NEWER
using UnityEngine.InputSystem;
using UnityEngine.InputSystem.XR;
#endif
#if AVATARGO_XRI_2_4_OR_NEWER
using UnityEngine.XR.Interaction.Toolkit.Inputs;
#endif
#if AVATARGO_XRI_2
using UnityEngine.XR.Interaction.Toolkit;
#endif

namespace AvatarGo
{
    /// <summary>
    /// Connects a tracking source to an XR Interaction Toolkit rig (an <c>XROrigin</c> from <c>com.unity.xr.core-utils</c>;
    /// this assembly compiles only when it is installed). On <c>Start</c> (before the calibrator's first <c>Update</c>
    /// reads the source), unless <see cref="Apply"/> was called before:
    /// <list type="bullet">
    /// <item>the source's <see cref="AvatarGoTrackingSource.TrackingSpaceOrigin"/> (when empty) becomes the origin's
    /// <c>CameraFloorOffsetObject</c>, the parent of the camera and the controllers, whose space the XR runtime tracks in;</item>
    /// <item>a <see cref="TransformTrackingSource"/> also gets the rig's HMD and controllers where it has none: the references
    /// given here first, then the origin's camera, the controllers an <c>XRInputModalityManager</c> names (XRI 2.4 and newer),
    /// the objects under the camera offset whose pose driver (an Input System <c>TrackedPoseDriver</c>, or XRI 2.x's
    /// <c>ActionBasedController</c>) is bound to <c>{LeftHand}</c>/<c>{RightHand}</c>, and last the children's names
    /// (XRI 2.x and 3.x name them differently: <see cref="XrRigRules"/>).</item>
    /// </list>
    /// The trackers are not part of an XRI rig: assign them on the source.
    /// <para>Added at run time with <c>AddComponent</c>: set its fields, then call <see cref="Apply"/> (to have the source
    /// ready at once) or let <c>Start</c> apply them. Nothing is looked for in <c>Awake</c>, which runs inside
    /// <c>AddComponent</c> before any field can be set.</para>
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/XR Origin Tracking Setup")]
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#xr-origin-tracking-setup")]
    [DisallowMultipleComponent]
    public sealed class XROriginTrackingSetup : MonoBehaviour
    {
        [SerializeField, Tooltip("The rig. Empty: the XR Origin above this object, else the first one in the scene.")]
        private XROrigin m_Origin;

        [SerializeField, Tooltip("The source to set up. Empty: the tracking source on this object.")]
        private AvatarGoTrackingSource m_Source;

        [SerializeField, Tooltip("Optional: the HMD's transform. Empty: the XR Origin's camera.")]
        private Transform m_Head;

        [SerializeField, Tooltip("Optional: the left controller's transform. Empty: found in the rig.")]
        private Transform m_LeftController;

        [SerializeField, Tooltip("Optional: the right controller's transform. Empty: found in the rig.")]
        private Transform m_RightController;

        /// <summary>The rig (once applied: the one found).</summary>
        public XROrigin Origin { get => m_Origin; set => m_Origin = value; }

        /// <summary>The source set up (once applied: the one found).</summary>
        public AvatarGoTrackingSource Source { get => m_Source; set => m_Source = value; }

        /// <summary>The HMD transform given instead of the origin's camera, or null.</summary>
        public Transform Head { get => m_Head; set => m_Head = value; }

        /// <summary>The left controller transform given instead of the one found, or null.</summary>
        public Transform LeftController { get => m_LeftController; set => m_LeftController = value; }

        /// <summary>The right controller transform given instead of the one found, or null.</summary>
        public Transform RightController { get => m_RightController; set => m_RightController = value; }

        private bool _applied;

        // Not in Awake: added with AddComponent, Awake runs before the caller can set a field, and would fail (disabling
        // the component) or set the source up from a rig found instead of the one then assigned.
        private void Start()
        {
            if (!_applied) Apply();
        }

        /// <summary>
        /// Finds the rig and sets the source up as described on the class; false (and an error logged once, with this
        /// component disabled) when there is no rig or no source. Called by <c>Start</c> when it has not been called
        /// successfully before.
        /// </summary>
        public bool Apply()
        {
            if (m_Source == null) m_Source = GetComponent<AvatarGoTrackingSource>();
            if (m_Origin == null) m_Origin = GetComponentInParent<XROrigin>();
#if UNITY_2023_1_OR_NEWER
            if (m_Origin == null) m_Origin = FindAnyObjectByType<XROrigin>();
#else
            if (m_Origin == null) m_Origin = FindObjectOfType<XROrigin>();
#endif
            if (m_Source == null || m_Origin == null)
            {
                SetupErrors.Disable(this, "AvatarGo: the XR Origin Tracking Setup found " + (m_Source == null ? "no tracking source on its object" : "no XR Origin in the scene") +
                                          "; assign it. The component is disabled.");
                return false;
            }
            Transform offset = m_Origin.CameraFloorOffsetObject != null ? m_Origin.CameraFloorOffsetObject.transform : m_Origin.transform;
            if (m_Source.TrackingSpaceOrigin == null) m_Source.TrackingSpaceOrigin = offset;
            if (m_Source is TransformTrackingSource transforms)
            {
                if (transforms.Head == null) transforms.Head = m_Head != null ? m_Head : m_Origin.Camera != null ? m_Origin.Camera.transform : null;
                if (transforms.LeftController == null) transforms.LeftController = m_LeftController != null ? m_LeftController : FindController(offset, BodySide.Left);
                if (transforms.RightController == null) transforms.RightController = m_RightController != null ? m_RightController : FindController(offset, BodySide.Right);
            }
            _applied = true;
            return true;
        }

        private Transform FindController(Transform offset, BodySide side)
        {
#if AVATARGO_XRI_2_4_OR_NEWER
            XRInputModalityManager modality = m_Origin.GetComponentInChildren<XRInputModalityManager>(true);
            if (modality != null)
            {
                GameObject named = side == BodySide.Left ? modality.leftController : modality.rightController;
                if (named != null) return named.transform;
            }
#endif
            Transform best = null;
            int bestScore = 0;
#if AVATARGO_INPUT_SYSTEM_1_1_OR_NEWER
            var drivers = new List<TrackedPoseDriver>();
            offset.GetComponentsInChildren(true, drivers);
            foreach (TrackedPoseDriver driver in drivers)
                Consider(driver.transform, driver.positionInput.action, side, ref best, ref bestScore);
#endif
#if AVATARGO_XRI_2
            var controllers = new List<ActionBasedController>();
            offset.GetComponentsInChildren(true, controllers);
            foreach (ActionBasedController controller in controllers)
                Consider(controller.transform, controller.positionAction.action, side, ref best, ref bestScore);
#endif
            if (best != null) return best;
            for (int c = 0; c < offset.childCount; c++)
            {
                Transform child = offset.GetChild(c);
                int score = XrRigRules.NameScore(child.name, out BodySide s);
                if (score > bestScore && s == side)
                {
                    best = child;
                    bestScore = score;
                }
            }
            return best;
        }

#if AVATARGO_INPUT_SYSTEM_1_1_OR_NEWER
        private static void Consider(Transform candidate, InputAction action, BodySide side, ref Transform best, ref int bestScore)
        {
            if (action == null) return;
            for (int b = 0; b < action.bindings.Count; b++)
            {
                int score = XrRigRules.BindingScore(action.bindings[b].path, out BodySide s);
                if (score > bestScore && s == side)
                {
                    best = candidate;
                    bestScore = score;
                }
            }
        }
#endif
    }
}
