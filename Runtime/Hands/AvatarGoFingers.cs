using System;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// The fingers around the controllers: gives each hand's controller profile, grip mode and placement to the pipeline
    /// (whose finger IK closes the fingers on the controller's surface), and writes the solved finger bones in
    /// <c>LateUpdate</c>, after the Animator's IK has posed the body (<see cref="AvatarGoExecutionOrder.Fingers"/>): the
    /// Animator writes the humanoid finger bones every frame, so they are set after it. The grip follows the trigger and
    /// grip values by default (<see cref="GripMode.InputDriven"/>). Allocation-free per frame.
    /// </summary>
    /// <remarks>
    /// A controller profile is a <see cref="TextAsset"/>: one of the package's <c>Runtime/ControllerProfiles/*.json</c>
    /// (VIVE wand, Valve Index, Quest Touch) or any JSON in that format; it is parsed once, when the pipeline is made or
    /// the profile is changed. No file is read at runtime.
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Fingers")]
    [HelpURL(AvatarGoDocs.Manual + "avatargo-fingers.md")]
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.Fingers)]
    public sealed class AvatarGoFingers : MonoBehaviour
    {
        [SerializeField, Tooltip("The calibrator whose pipeline solves the fingers (found in the parents when empty).")]
        private AvatarGoCalibrator m_Calibrator;

        [SerializeField, Tooltip("The controller in the left hand: a controller profile JSON (Runtime/ControllerProfiles). Empty: no finger IK on that hand.")]
        private TextAsset m_LeftController;

        [SerializeField, Tooltip("The controller in the right hand: a controller profile JSON (Runtime/ControllerProfiles). Empty: no finger IK on that hand.")]
        private TextAsset m_RightController;

        [SerializeField, Tooltip("What the left hand's fingers do: hold the controller, open, point, or follow the trigger and grip.")]
        private GripMode m_LeftGrip = GripMode.InputDriven;

        [SerializeField, Tooltip("What the right hand's fingers do: hold the controller, open, point, or follow the trigger and grip.")]
        private GripMode m_RightGrip = GripMode.InputDriven;

        [SerializeField, Tooltip("How the wrists are placed from the controllers: the palm on the grip (the paper's) or the walk-in's measured offset.")]
        private HandPlacement m_Placement = HandPlacement.PalmOnController;

        private readonly ControllerProfile[] _profiles = new ControllerProfile[2];
        private readonly TextAsset[] _parsed = new TextAsset[2];
        private readonly int[][] _fingerJoints = new int[2][];
        private HumanoidBinding _binding;
        private bool _failed, _attached;

        /// <summary>
        /// The calibrator whose pipeline solves the fingers. Set at run time, the hands are taken off the current one and
        /// given to the new one (null: the nearest in the parents) on the next <c>LateUpdate</c>.
        /// </summary>
        public AvatarGoCalibrator Calibrator
        {
            get => m_Calibrator;
            set
            {
                if (value == m_Calibrator) return;
                if (m_Calibrator != null) m_Calibrator.Detach(this);
                m_Calibrator = value;
                _attached = false; // attached again, to the new one, by the next LateUpdate (or Start)
            }
        }

        /// <summary>A hand's grip mode (read by the pipeline every frame).</summary>
        public GripMode Grip(BodySide side) => side == BodySide.Left ? m_LeftGrip : m_RightGrip;

        /// <summary>
        /// Sets a hand's grip mode, in the pipeline's settings at once: it takes effect on the pipeline's next solve (this
        /// frame's when called before the calibrator's <c>Update</c>, <see cref="AvatarGoExecutionOrder.Calibrator"/>; the next
        /// frame's otherwise).
        /// </summary>
        public void SetGrip(BodySide side, GripMode grip)
        {
            if (side == BodySide.Left) m_LeftGrip = grip;
            else m_RightGrip = grip;
            SelfAvatarPipeline pipeline = m_Calibrator != null ? m_Calibrator.Pipeline : null;
            if (pipeline != null) pipeline.Settings.Hand(side).Grip = grip;
        }

        /// <summary>A hand's controller profile asset.</summary>
        public TextAsset Controller(BodySide side) => side == BodySide.Left ? m_LeftController : m_RightController;

        /// <summary>Sets a hand's controller profile and rebuilds the hands' finger IK (allocates, about a millisecond per hand).</summary>
        public void SetController(BodySide side, TextAsset profile)
        {
            if (side == BodySide.Left) m_LeftController = profile;
            else m_RightController = profile;
            SelfAvatarPipeline pipeline = m_Calibrator != null ? m_Calibrator.Pipeline : null;
            if (pipeline == null) return;
            ConfigureHands(pipeline.Settings);
            pipeline.ApplyHandSettings();
        }

        /// <summary>Writes both hands' settings (controller profiles, grip modes, placement) into the pipeline's settings.</summary>
        public void ConfigureHands(PipelineSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            foreach (BodySide side in Sides)
            {
                HandSettings hand = settings.Hand(side);
                hand.Controller = Profile(side);
                hand.Grip = Grip(side);
                hand.Placement = m_Placement;
            }
        }

        private static readonly BodySide[] Sides = { BodySide.Left, BodySide.Right };

        private void OnEnable() => _attached = false;

        // Attached before the calibrator's first Update (Start runs for every new component before any Update), so that the
        // first pipeline already has the hands' settings.
        private void Start() => Attach();

        private void OnDisable()
        {
            if (m_Calibrator != null) m_Calibrator.Detach(this);
            _attached = false;
        }

        private void LateUpdate()
        {
            if (_failed || !Attach()) return;
            // A destroyed calibrator (Unity's == null is true for it; its isActiveAndEnabled would throw every frame): its
            // pipeline is gone with it, nothing is written.
            if (m_Calibrator == null) return;
            // A stopped (or failed) calibrator gave the avatar back to its Animator: the last grip is not written over it.
            if (!m_Calibrator.isActiveAndEnabled) return;
            SelfAvatarPipeline pipeline = m_Calibrator.Pipeline;
            if (pipeline == null) return;
            pipeline.Settings.LeftHand.Grip = m_LeftGrip;
            pipeline.Settings.RightHand.Grip = m_RightGrip;
            HumanoidBinding binding = m_Calibrator.Binding;
            SkeletonPose pose = pipeline.Pose;
            // binding.Root == null: the avatar was destroyed (the calibrator stops, but its pipeline keeps its calibration).
            if (binding == null || binding.Root == null || pose == null || pipeline.State != CalibrationState.Calibrated) return;
            if (!ReferenceEquals(binding, _binding))
            {
                _binding = binding;
                _fingerJoints[0] = binding.Hierarchy.JointsBelow(HumanoidBone.LeftHand);
                _fingerJoints[1] = binding.Hierarchy.JointsBelow(HumanoidBone.RightHand);
            }
            for (int s = 0; s < 2; s++)
                if (pipeline.Hand((BodySide)s).HasFingerIk) binding.ApplyLocalRotations(pose, _fingerJoints[s]);
        }

        private bool Attach()
        {
            if (_attached) return true;
            if (_failed) return false;
            if (!SetupErrors.FindCalibrator(this, ref m_Calibrator, ref _failed)) return false;
            m_Calibrator.Attach(this);
            _attached = true;
            return true;
        }

        // The hand's profile, parsed once per asset; a profile that does not parse is reported once and that hand has none.
        private ControllerProfile Profile(BodySide side)
        {
            int s = (int)side;
            TextAsset asset = side == BodySide.Left ? m_LeftController : m_RightController;
            if (asset == null) return null;
            if (ReferenceEquals(asset, _parsed[s])) return _profiles[s];
            _parsed[s] = asset;
            try
            {
                _profiles[s] = ControllerProfile.Parse(asset.text, asset.name);
            }
            catch (FormatException e)
            {
                _profiles[s] = null;
                Debug.LogError($"{nameof(AvatarGoFingers)} on '{name}': the {side} controller profile '{asset.name}' is not a valid profile ({e.Message}); that hand has no finger IK.", this);
            }
            return _profiles[s];
        }
    }
}
