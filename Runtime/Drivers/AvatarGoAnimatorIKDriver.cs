using AvatarGo.Core;
using UnityEngine;
using CoreQuaternion = System.Numerics.Quaternion;
using CoreVector3 = System.Numerics.Vector3;

namespace AvatarGo
{
    /// <summary>
    /// The paper's driver: Unity's humanoid IK reproduces the pipeline's solve. In <c>OnAnimatorIK</c> it sets the four limb
    /// goals (the solved wrists and ankles, position and rotation), a hint per knee and elbow (in front of the solved middle
    /// joints), the hips through <c>bodyPosition</c>/<c>bodyRotation</c>, and the spine, chest, neck, head and clavicles by
    /// <c>SetBoneLocalRotation</c> (the spine's forward kinematics, the head from the HMD). Everything comes from the
    /// pipeline in tracking space and is mapped to world space through the source's tracking space. Allocation-free per
    /// frame.
    /// </summary>
    /// <remarks>
    /// <para>Unity's terms, measured rather than assumed: <c>bodyPosition</c> is the humanoid's centre of mass, not the hips,
    /// so the body set is the solved hips times the body-to-hips relation the Animator produced in the previous IK pass
    /// (<see cref="BodyPoseCompensation"/>); an IK goal's rotation is in the avatar's effector frame, not the bone's, so the
    /// constant rotation between the two is measured in the first IK passes from the goal set and the bone's resulting
    /// rotation (<see cref="EffectorRotationOffsets"/>; until it is known, the rotation goal is the animated effector's own).</para>
    /// <para>The Animator is set up for it: culling <c>AlwaysAnimate</c> (the avatar is animated even when the wearer does not
    /// look at it), update mode <c>Normal</c> if it was the physics mode, no root motion (the root is placed here, in
    /// <c>Update</c>, before the Animator runs), the feet pivot at the body (<c>feetPivotActive</c> 0: the body is placed
    /// explicitly). <c>OnAnimatorIK</c> is only called for a controller layer with IK Pass on: an Animator without a
    /// controller gets the package's <c>AvatarGoIKPass</c> controller (one layer, IK Pass on, one empty state so that the layer
    /// plays: Unity calls OnAnimatorIK only for a playing layer), from the inspector field or else from Resources.</para>
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Animator IK Driver")]
    [HelpURL(AvatarGoDocs.Manual + "animator-ik-driver.md")]
    [DisallowMultipleComponent]
    [RequireComponent(typeof(Animator))]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.AnimatorIKDriver)]
    public sealed class AvatarGoAnimatorIKDriver : MonoBehaviour
    {
        private static readonly HumanoidBone[] GoalBones = { HumanoidBone.LeftFoot, HumanoidBone.RightFoot, HumanoidBone.LeftHand, HumanoidBone.RightHand };

        /// <summary>The package's IK Pass controller, under <c>Runtime/Animation/Resources</c>: one layer with IK Pass on and one empty state.</summary>
        public const string IKPassResource = "AvatarGoIKPass";

        // Frames without an IK pass (while there is a pose to drive) before the missing IK Pass is reported.
        private const int FramesWithoutIKPass = 30;

        [SerializeField, Tooltip("The calibrator whose pipeline drives this avatar (found in the parents when empty).")]
        private AvatarGoCalibrator m_Calibrator;

        [SerializeField, Tooltip("Given to an Animator without a controller: a controller with an IK Pass layer. Empty: the package's AvatarGoIKPass (loaded from Resources).")]
        private RuntimeAnimatorController m_IKPassController = null;

        [SerializeField, Range(0f, 1f), Tooltip("Weight of the hand goals (position and rotation).")]
        private float m_HandWeight = 1f;

        [SerializeField, Range(0f, 1f), Tooltip("Weight of the foot goals (position and rotation).")]
        private float m_FootWeight = 1f;

        [SerializeField, Range(0f, 1f), Tooltip("Weight of the knee and elbow hints.")]
        private float m_HintWeight = 1f;

        [SerializeField, Tooltip("Turn the spine, chest, neck, head and clavicles as the pipeline solved them.")]
        private bool m_DriveSpine = true;

        [SerializeField, Tooltip("Raise a foot goal when its sole (Animator.left/rightFeetBottomHeight below the ankle) would be below the floor.")]
        private bool m_KeepSolesAboveFloor = false;

        private Animator _animator;
        private HumanoidBinding _binding;
        private HumanoidMap _avatar;
        private AnimatorIkTargets _targets;
        private BodyPoseCompensation _body;
        private readonly EffectorRotationOffsets _effectors = new EffectorRotationOffsets();
        private readonly CoreQuaternion[] _goalSet = new CoreQuaternion[4]; // tracking space, the last pass's
        private readonly bool[] _hasGoalSet = new bool[4];
        private readonly float[] _rotationWeightSet = new float[4];
        private readonly Transform[] _goalBones = new Transform[4];
        private Transform _hips;
        private RigidPose _bodySet;
        private bool _hasBodySet, _setUp, _failed, _warnedNoIKPass;
        private int _framesWithoutIK, _measuredFrame = -1, _setFrame = -1;

        /// <summary>
        /// The calibrator whose pipeline drives this avatar. Set at run time, the driver binds to the new one (null: the
        /// nearest in the parents) on its next <c>Update</c>, with the same checks as at start.
        /// </summary>
        public AvatarGoCalibrator Calibrator
        {
            get => m_Calibrator;
            set
            {
                if (value == m_Calibrator) return;
                m_Calibrator = value;
                // Set up again for the new one: its binding (it binds the avatar in its Start), its Animator checked again.
                // A setup error of the old one is forgotten (a component that disabled itself stays off until enabled).
                _setUp = _failed = false;
                _avatar = null;
            }
        }

        /// <summary>Weight of the hand goals (clamped to 0…1; NaN gives the default 1).</summary>
        public float HandWeight { get => m_HandWeight; set => m_HandWeight = Weight(value); }

        /// <summary>Weight of the foot goals (clamped to 0…1; NaN gives the default 1).</summary>
        public float FootWeight { get => m_FootWeight; set => m_FootWeight = Weight(value); }

        // Mathf.Clamp01 lets NaN through (both of its comparisons are false), and the Animator would blend the limbs by it.
        private static float Weight(float value) => float.IsNaN(value) ? 1f : Mathf.Clamp01(value);

        /// <summary>True once both hands' and both feet's effector frames have been measured.</summary>
        public bool EffectorFramesKnown
        {
            get
            {
                for (int g = 0; g < 4; g++) if (!_effectors.IsKnown((IkGoal)g)) return false;
                return true;
            }
        }

        private void OnEnable() => _framesWithoutIK = 0;

        private void Update()
        {
            if (!SetUp()) return;
            // A destroyed calibrator (Unity's == null is true for it; its isActiveAndEnabled would throw every frame): nothing
            // is placed, as OnAnimatorIK sets nothing then.
            if (m_Calibrator == null) return;
            // A stopped (or failed) calibrator has put the bind positions back (its OnDisable): the avatar is its Animator's
            // until it comes back, as with the transform driver (found in review: the last solved pose went on being set).
            if (!m_Calibrator.isActiveAndEnabled) return;
            SelfAvatarPipeline pipeline = m_Calibrator.Pipeline;
            SkeletonPose pose = pipeline?.Pose;
            if (pose == null || pipeline.Profile == null) return;
            if (!ReferenceEquals(pipeline.ScaledAvatar, _avatar)) Retarget(pipeline.ScaledAvatar);
            // The root where the pipeline put it, scaled to the wearer, before the Animator evaluates.
            _binding.ApplyRoot(pose.World[0], m_Calibrator.TrackingSpace, pipeline.Profile.AvatarScale);
            // Only frames in which the Animator would have updated count: with Time.timeScale 0 (a paused game) a Normal
            // Animator gets no time and need not evaluate, so no IK pass then is no sign of a missing IK Pass layer; an
            // UnscaledTime one runs on regardless.
            bool animatorRan = Time.deltaTime > 0f || _animator.updateMode == AnimatorUpdateMode.UnscaledTime;
            if (animatorRan && ++_framesWithoutIK == FramesWithoutIKPass && !_warnedNoIKPass)
            {
                _warnedNoIKPass = true;
                Debug.LogWarning($"{nameof(AvatarGoAnimatorIKDriver)} on '{name}': OnAnimatorIK is not being called. The Animator's controller " +
                                 $"('{(_animator.runtimeAnimatorController != null ? _animator.runtimeAnimatorController.name : "none")}') needs a layer with IK Pass on " +
                                 "(the package's AvatarGoIKPass controller has one), and the Animator must be enabled.", this);
            }
        }

        private void OnAnimatorIK(int layerIndex)
        {
            if (!_setUp || _failed || m_Calibrator == null) return;
            if (!m_Calibrator.isActiveAndEnabled)
            {
                ReleaseGoals();
                return;
            }
            SelfAvatarPipeline pipeline = m_Calibrator.Pipeline;
            SkeletonPose pose = pipeline?.Pose;
            if (pose == null || _targets == null || !ReferenceEquals(pipeline.ScaledAvatar, _avatar)) return;
            _framesWithoutIK = 0;
            TrackingSpace space = m_Calibrator.TrackingSpace;
            // Once a frame (OnAnimatorIK comes once per IK Pass layer): what the last pass produced.
            if (_measuredFrame != Time.frameCount)
            {
                _measuredFrame = Time.frameCount;
                Measure(space);
            }
            _targets.Update(pose);

            // The hips, through the body.
            _setFrame = Time.frameCount;
            _bodySet = _body.BodyFor(_targets.Hips);
            _hasBodySet = true;
            RigidPose body = space.ToWorld(_bodySet);
            _animator.bodyPosition = body.Position.ToUnity();
            _animator.bodyRotation = body.Rotation.ToUnity();

            // The limbs: goals in the effector frames, hints in front of the solved knees and elbows.
            for (int g = 0; g < 4; g++)
            {
                var goal = (IkGoal)g;
                var unityGoal = (AvatarIKGoal)g;
                RigidPose target = _targets.Goal(goal);
                CoreQuaternion rotation;
                if (_effectors.IsKnown(goal)) rotation = _effectors.EffectorFor(goal, target.Rotation);
                else rotation = space.ToTracking(new RigidPose(target.Position, _animator.GetIKRotation(unityGoal).ToCore())).Rotation; // measuring
                _goalSet[g] = rotation;
                _hasGoalSet[g] = true;
                CoreVector3 position = target.Position;
                if (m_KeepSolesAboveFloor && g < 2)
                {
                    float sole = (g == 0 ? _animator.leftFeetBottomHeight : _animator.rightFeetBottomHeight) / space.Scale;
                    position = FootSoles.KeepAboveFloor(position, rotation, sole, 0f);
                }
                RigidPose world = space.ToWorld(new RigidPose(position, rotation));
                float weight = g < 2 ? m_FootWeight : m_HandWeight;
                _animator.SetIKPosition(unityGoal, world.Position.ToUnity());
                _animator.SetIKRotation(unityGoal, world.Rotation.ToUnity());
                _animator.SetIKPositionWeight(unityGoal, weight);
                _animator.SetIKRotationWeight(unityGoal, weight);
                _rotationWeightSet[g] = weight;
                var hint = (AvatarIKHint)g;
                _animator.SetIKHintPosition(hint, space.ToWorld(_targets.Hint((IkHint)g)).ToUnity());
                _animator.SetIKHintPositionWeight(hint, m_HintWeight);
            }

            // The spine's forward kinematics and the head: local rotations, the same in Unity (the binding keeps every
            // transform between the bones).
            if (!m_DriveSpine) return;
            for (int b = 0; b < _targets.TurnedBoneCount; b++)
                _animator.SetBoneLocalRotation((HumanBodyBones)_targets.TurnedBone(b), _targets.TurnedLocalRotation(b).ToUnity());
        }

        // No goal or hint holds the limbs: the animation alone poses them.
        private void ReleaseGoals()
        {
            for (int g = 0; g < 4; g++)
            {
                _animator.SetIKPositionWeight((AvatarIKGoal)g, 0f);
                _animator.SetIKRotationWeight((AvatarIKGoal)g, 0f);
                _animator.SetIKHintPositionWeight((AvatarIKHint)g, 0f);
            }
        }

        // What the Animator made of the last pass: the hips from the body set, each bone from its goal's rotation. Only a
        // pass of the frame before says what the bones are now: after frames without one (this driver disabled, the Animator
        // disabled or culled) the bones are what the animation alone made of them, which would read as a wrong offset.
        private void Measure(TrackingSpace space)
        {
            if (_setFrame != Time.frameCount - 1) return;
            if (_hasBodySet) _body.Observe(_bodySet, space.ToTracking(_hips.GetWorldPose()));
            for (int g = 0; g < 4; g++)
                if (_hasGoalSet[g] && !_effectors.IsKnown((IkGoal)g))
                    _effectors.Observe((IkGoal)g, _goalSet[g], _rotationWeightSet[g], space.ToTracking(_goalBones[g].GetWorldPose()).Rotation);
        }

        private void Retarget(HumanoidMap avatar)
        {
            _avatar = avatar;
            _targets = new AnimatorIkTargets(avatar);
            _body = new BodyPoseCompensation(avatar);
            _hasBodySet = false;
            for (int g = 0; g < 4; g++) _hasGoalSet[g] = false;
        }

        private bool SetUp()
        {
            if (_setUp) return !_failed;
            if (_failed) return false;
            if (!SetupErrors.FindCalibrator(this, ref m_Calibrator, ref _failed)) return false;
            _binding = m_Calibrator.Binding;
            if (_binding == null) return false; // the calibrator binds the avatar in its Start
            _animator = GetComponent<Animator>();
            if (_animator != m_Calibrator.Animator || _binding.Root != _animator.transform)
                return Fail("this component must be on the GameObject of the calibrator's Animator (OnAnimatorIK is only sent there)");
            if (_animator.runtimeAnimatorController == null)
            {
                // The package's controller ships in a Resources folder, so that a driver added at run time (by the calibrator)
                // finds it without a reference.
                if (m_IKPassController == null) m_IKPassController = Resources.Load<RuntimeAnimatorController>(IKPassResource);
                if (m_IKPassController == null) return Fail($"the Animator has no controller and the package's {IKPassResource} controller is missing (assign a controller with an IK Pass layer)");
                _animator.runtimeAnimatorController = m_IKPassController;
            }
            _animator.cullingMode = AnimatorCullingMode.AlwaysAnimate;
            // 1 is AnimatePhysics before 2023.1 and Fixed after: IK would run in the physics loop, out of step with the pipeline.
            if ((int)_animator.updateMode == 1)
            {
                Debug.LogWarning($"{nameof(AvatarGoAnimatorIKDriver)} on '{name}': the Animator updated with physics; set to Normal so that IK follows the frame's devices.", this);
                _animator.updateMode = AnimatorUpdateMode.Normal;
            }
            _animator.applyRootMotion = false;
            _animator.feetPivotActive = 0f;
            _hips = _binding[HumanoidBone.Hips];
            for (int g = 0; g < 4; g++) _goalBones[g] = _binding[GoalBones[g]];
            _setUp = true;
            return true;
        }

        // A setup error: logged once with this component as context; the component disables itself.
        private bool Fail(string message) => SetupErrors.Fail(this, ref _failed, message);
    }
}
