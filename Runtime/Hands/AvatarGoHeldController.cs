using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Draws a controller model where the pipeline says the controller is (<see cref="HandState.ControllerPose"/>): at its
    /// tracked pose while the avatar's hand reaches it, and in the avatar's hand, in the same grip, where the arm cannot
    /// reach (or the controller is lost), as the paper does; the two poses meet where the hand stops reaching, so the model
    /// does not jump either way. Any transform can be the model (the XR Interaction Toolkit's controller model, a mesh).
    /// </summary>
    /// <remarks>
    /// Once calibrated, the model is re-parented under <see cref="ModelParent"/> (by default the tracking source's origin)
    /// so that the rig's own per-frame pose updates no longer move it, and put back under its own parent at its own local
    /// pose (following its device again) when this component is disabled, when the calibration is reset or new devices come,
    /// and while the calibrator is stopped. Its offset from the tracked device is measured on the first calibrated frame the controller is tracked and
    /// reached (the model as the application placed it, relative to the device), or set to none. Runs in <c>LateUpdate</c>
    /// (<see cref="AvatarGoExecutionOrder.HeldController"/>). Allocation-free per frame.
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Held Controller")]
    [HelpURL(AvatarGoDocs.Manual + "held-controller.md")]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.HeldController)]
    public sealed class AvatarGoHeldController : MonoBehaviour
    {
        [SerializeField, Tooltip("The calibrator whose pipeline places the hand (found in the parents when empty).")]
        private AvatarGoCalibrator m_Calibrator;

        [SerializeField, Tooltip("Which hand holds this controller.")]
        private BodySide m_Hand = BodySide.Right;

        [SerializeField, Tooltip("The controller model to draw (any Transform).")]
        private Transform m_Model;

        [SerializeField, Tooltip("Where the model is re-parented once calibrated. Empty: the tracking source's origin (the scene when it has none).")]
        private Transform m_ModelParent;

        [SerializeField, Tooltip("Measure the model's offset from the device on the first calibrated frame it is tracked; off: the model is drawn at the device's pose.")]
        private bool m_MeasureOffset = true;

        private Transform _originalParent;
        private RigidPose _originalLocal = RigidPose.Identity; // the model's local pose under its own parent, before it was moved
        private Vector3 _originalScale = Vector3.one;          // and its local scale (re-parenting keeps the world scale)
        private bool _moved, _hasOffset, _failed;
        private RigidPose _offset = RigidPose.Identity;

        /// <summary>
        /// The calibrator whose pipeline places the hand. Set at run time, the model is given back to its own parent (as for
        /// a new <see cref="Model"/>) and, from the next <c>LateUpdate</c>, placed by the new calibrator (null: the nearest in
        /// the parents), its offset measured again from that calibrator's controller; a setup error of the old one is
        /// forgotten (a component that disabled itself stays off until enabled).
        /// </summary>
        public AvatarGoCalibrator Calibrator
        {
            get => m_Calibrator;
            set
            {
                if (value == m_Calibrator) return;
                // Not kept from the old one: its offset (measured from its controller), the parent it moved the model under
                // (its source's origin).
                GiveBack();
                m_Calibrator = value;
                _hasOffset = false;
                _failed = false;
            }
        }

        /// <summary>
        /// Which hand holds this controller. Changed at run time, the model is given back to its own parent (as for a new
        /// <see cref="Model"/>) and its offset is measured again from the new hand's controller.
        /// </summary>
        public BodySide Hand
        {
            get => m_Hand;
            set
            {
                if (value == m_Hand) return;
                GiveBack(); // where its own parent puts it: the offset is measured from there, not from the old hand's pose
                m_Hand = value;
                _hasOffset = false;
            }
        }

        /// <summary>
        /// The controller model. Setting another one gives the current one back to its own parent first (unless its parents
        /// are being activated or deactivated right then, when Unity refuses: it then stays under <see cref="ModelParent"/>),
        /// and the new one's offset is measured again.
        /// </summary>
        public Transform Model
        {
            get => m_Model;
            set
            {
                if (value == m_Model) return;
                GiveBack();
                m_Model = value;
                _moved = false;
                _hasOffset = false;
            }
        }

        /// <summary>Where the model is re-parented once calibrated (null: the tracking source's origin).</summary>
        public Transform ModelParent { get => m_ModelParent; set => m_ModelParent = value; }

        /// <summary>True while the model is drawn in the avatar's hand rather than at the tracked pose.</summary>
        public bool DrawnInHand { get; private set; }

        private void OnDisable()
        {
            GiveBack();
            _hasOffset = false;
        }

        // The model back under its own parent at its own local pose and scale (under the controller's tracked transform,
        // where it was: not where it was last drawn, which may be in the hand). Unity refuses to re-parent while a parent is
        // being activated or deactivated (the rig or scene going away): then the model stays where it is for now, still
        // counted as moved, so that the next call gives it back and the next calibrated frame does not take where it is as
        // its own parent. A model hidden by itself (the XR Interaction Toolkit's hideControllerModel deactivates it) is
        // given back all the same: only its parents' activity matters.
        private void GiveBack()
        {
            DrawnInHand = false;
            if (!_moved) return;
            if (m_Model == null) { _moved = false; return; }
            Transform current = m_Model.parent;
            if ((current != null && !current.gameObject.activeInHierarchy) || (_originalParent != null && !_originalParent.gameObject.activeInHierarchy)) return;
            m_Model.SetParent(_originalParent, false);
            m_Model.SetLocalPose(_originalLocal);
            m_Model.localScale = _originalScale;
            _moved = false;
        }

        private void LateUpdate()
        {
            if (_failed || m_Model == null) return;
            if (!SetupErrors.FindCalibrator(this, ref m_Calibrator, ref _failed)) return;
            SelfAvatarPipeline pipeline = m_Calibrator.Pipeline;
            if (pipeline == null || pipeline.State != CalibrationState.Calibrated || !m_Calibrator.isActiveAndEnabled)
            {
                GiveBack(); // not calibrated (a reset, new devices) or the calibrator stopped: the model follows its device again
                return;
            }
            HandState hand = pipeline.Hand(m_Hand);
            TrackingSpace space = m_Calibrator.TrackingSpace;
            RigidPose controller = space.ToWorld(hand.ControllerPose);
            if (!_hasOffset)
            {
                if (m_MeasureOffset && (hand.DrawnInHand || !hand.ControllerTracked)) return; // wait for a tracked, reached frame
                _offset = m_MeasureOffset ? m_Model.GetWorldPose().RelativeTo(controller) : RigidPose.Identity;
                _hasOffset = true;
            }
            if (!_moved)
            {
                _originalParent = m_Model.parent;
                _originalLocal = m_Model.GetLocalPose();
                _originalScale = m_Model.localScale;
                Transform parent = m_ModelParent != null ? m_ModelParent : m_Calibrator.Source != null ? m_Calibrator.Source.TrackingSpaceOrigin : null;
                m_Model.SetParent(parent, true);
                _moved = true;
            }
            DrawnInHand = hand.DrawnInHand;
            m_Model.SetWorldPose(controller * _offset);
        }
    }
}
