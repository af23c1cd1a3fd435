using System;
using System.Collections.Generic;
using System.IO;
using AvatarGo.Core;
using UnityEngine;
using UnityEngine.Events;
using CoreScaleMode = AvatarGo.Core.ScaleMode; // UnityEngine has a ScaleMode of its own

namespace AvatarGo
{
    /// <summary>
    /// The Walk-In-Avatar calibration for one avatar: owns the <see cref="SelfAvatarPipeline"/>, reads the tracking source
    /// once a frame before any other script (<see cref="AvatarGoExecutionOrder.Calibrator"/>) and runs the pipeline on it.
    /// In the headset it shows the wearer's instructions and every calibration message (world-space text), a marker on
    /// every device, the scaled avatar in T-pose where the wearer stood with its mirror image beyond a mirror in front of
    /// it during the walk-in, and hides the avatar until then. It saves each calibration to
    /// <c>Application.persistentDataPath</c> (atomically) and restores it on start when the same devices are worn.
    /// The avatar's bones are written by a driver: <see cref="AvatarGoAnimatorIKDriver"/> (added when missing, the default)
    /// or <see cref="AvatarGoTransformDriver"/>. With fitted proportions (<see cref="AvatarScaleMode"/>) this component moves
    /// the avatar's knee, ankle, elbow and wrist transforms along their bones (<see cref="ProportionedBones"/>) from the
    /// T-pose step on, and puts them back at their bind positions on reset and when disabled.
    /// </summary>
    /// <remarks>
    /// Frame order: this component's <c>Update</c> (source read, pipeline) → the IK driver's <c>Update</c> (the avatar's
    /// root placed) → the Animator and its IK pass (<c>OnAnimatorIK</c>) → <c>LateUpdate</c>: transform driver, fingers,
    /// held controllers → <c>Application.onBeforeRender</c>: the mirrored copy. Poses are sampled in <c>Update</c>, after the
    /// XR input update of the frame and before the Animator, so the body is solved and drawn from the same sample; the
    /// camera's render pose, refreshed again before rendering, can be a few milliseconds newer.
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Calibrator")]
    [HelpURL(AvatarGoDocs.Manual + "calibrator.md")]
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.Calibrator)]
    public sealed class AvatarGoCalibrator : MonoBehaviour
    {
        /// <summary>Which component writes the avatar's bones.</summary>
        public enum DriverKind
        {
            /// <summary>Unity's humanoid IK (<see cref="AvatarGoAnimatorIKDriver"/>, added to the Animator when missing): the paper's driver.</summary>
            AnimatorIK = 0,

            /// <summary>The core's full-body solve written to the transforms (<see cref="AvatarGoTransformDriver"/>, added when missing).</summary>
            Transforms = 1,

            /// <summary>None added: the application brings its own.</summary>
            None = 2,
        }

        [SerializeField, Tooltip("Where the devices come from (Unity XR devices, Input System actions, transforms, a recorded session...).")]
        private AvatarGoTrackingSource m_Source;

        [SerializeField, Tooltip("The avatar: an Animator with a humanoid Avatar.")]
        private Animator m_Animator;

        [SerializeField, Tooltip("For an avatar without a humanoid Animator: its root transform (the bones are found from their names). Ignored when an Animator is set.")]
        private Transform m_AvatarRoot;

        [SerializeField, Tooltip("Which component writes the avatar's bones (added when missing).")]
        private DriverKind m_Driver = DriverKind.AnimatorIK;

        [SerializeField, Tooltip("Exact offsets (the paper's method) or the fixed-offset baseline.")]
        private OffsetMode m_Offsets = OffsetMode.Exact;

        [SerializeField, Tooltip("Uniform: the avatar scaled by the wearer's eye height (the paper). Fitted: its legs and arms also fitted to the wearer's measured proportions, " +
            "applied at run time by moving its knee, ankle, elbow and wrist bones along their bones (skinned meshes stretch around those joints; see calibration.md). Read when the pipeline is made.")]
        private CoreScaleMode m_ScaleMode = CoreScaleMode.Uniform;

        [SerializeField, Range(0f, 10f), Tooltip("How slowly (s) a shoulder lets go of the shrug its hand needed to reach the controller: held, it keeps shoulders that sit lower or " +
            "further forward than in the T-pose where they are (solver.md, the held shrug). 0: none held. Read when the pipeline is made.")]
        private float m_ShrugReleaseSeconds = 3f; // FullBodyIk.DefaultShrugReleaseSeconds (the prefab generator reads literals only)

        [SerializeField, Range(0f, 10f), Tooltip("The cutoff (Hz) of the filter that steadies a leg held straight against the trackers' noise (near full reach the knee's " +
            "offset from the hip-ankle line grows with the square root of the slack, so millimetres of noise swing a straight knee by centimetres; solver.md, " +
            "a straight limb shivers). Lower is steadier and lags more as the knee starts to bend. 0: off, the exact reach every frame. Read when the pipeline is made.")]
        private float m_StraightLegCutoffHz = 1f; // FullBodyIk.DefaultStraightLegCutoffHz

        [SerializeField, Range(0f, 10f), Tooltip("The cutoff (Hz) of the filter that steadies an arm held straight against the trackers' noise, as for the legs; the clavicle " +
            "turns by up to 3 degrees to take up what the filter takes out, so the hand stays on its controller and the shoulder moves by about a millimetre. It cannot steady " +
            "an arm held out sideways along its clavicle. 0: off. Read when the pipeline is made.")]
        private float m_StraightArmCutoffHz = 1f; // FullBodyIk.DefaultStraightArmCutoffHz

        [SerializeField, Range(0f, 0.02f), Tooltip("The change (m) in the hips-to-head distance that the back does not flex for: the noise of the pelvis tracker and the " +
            "HMD together (1.4 mm for two 1 mm devices). Larger steadies the chest and ignores small real bends; 0 flexes for every change. Read when the pipeline is made.")]
        private float m_SpineChordNoiseMetres = 0.0014f; // FullBodyIk.DefaultChordNoiseMetres

        [SerializeField, Range(0f, 10f), Tooltip("The cutoff (Hz) of the filter on the hips-to-head distance the back bends for: near a straight back that distance changes " +
            "with the square of the bend, so tracker noise flexed the back to and fro and the chest jittered. Lower is steadier and lags more in a quick bow (the head " +
            "stays on the HMD either way). 0: off. Read when the pipeline is made.")]
        private float m_SpineChordCutoffHz = 1f; // FullBodyIk.DefaultChordCutoffHz

        [SerializeField, Tooltip("On start, reuse the calibration saved for this avatar when the same devices (by serial) are connected.")]
        private bool m_RestoreSavedProfile = true;

        [SerializeField, Tooltip("Save each new calibration to Application.persistentDataPath/AvatarGo (atomically).")]
        private bool m_SaveProfile = true;

        [SerializeField, Tooltip("After each new calibration (not a restored one), guide the wearer through a short exercise (arm circles with the arms stretched, reaches forward and overhead, two squats) " +
            "and refine the avatar's arm lengths from their reach (calibration.md, Refinement from motion). Changed arms move the elbow and wrist bones as Scale Mode Fitted does. Off: the calibration is final.")]
        private bool m_RefineAfterCalibration = false;

        [SerializeField, Range(RefinementFlow.MinimumExerciseSeconds, RefinementFlow.MaximumExerciseSeconds), Tooltip("How long the refinement exercise lasts (s); a controller's trigger press after its first 2 s ends it early.")]
        private float m_ExerciseSeconds = 8f; // RefinementFlow.DefaultExerciseSeconds (the prefab generator reads literals only)

        [SerializeField, Tooltip("Hide the avatar until the T-pose step has scaled and placed it.")]
        private bool m_HideAvatarUntilTPose = true;

        [SerializeField, Tooltip("Show the wearer's instructions and the calibration's messages in front of the head.")]
        private bool m_ShowInstructions = true;

        [SerializeField, Tooltip("Show a sphere on every device until calibrated.")]
        private bool m_ShowDeviceMarkers = true;

        [SerializeField, Tooltip("Show the avatar's mirror image during the walk-in.")]
        private bool m_ShowMirror = true;

        [SerializeField, Tooltip("How far in front of the avatar the mirror stands (m, 0 to 10); the mirror image is twice as far.")]
        private float m_MirrorDistance = 1.5f; // MirrorPlane.DefaultDistance (a literal: the prefab generator reads it)

        [SerializeField, Tooltip("Keep the mirror once calibrated.")]
        private bool m_KeepMirrorAfterCalibration = false;

        [SerializeField, Tooltip("Diameter of the device markers (m).")]
        private float m_MarkerSize = 0.06f; // CalibrationDisplaySizes.DefaultMarkerSize (a literal: the prefab generator reads it)

        [SerializeField, Tooltip("TextMesh character size of the instructions (world units per font unit).")]
        private float m_TextSize = 0.0025f; // CalibrationDisplaySizes.DefaultTextSize

        [SerializeField, Tooltip("The T-pose step succeeded: the avatar is shown for the walk-in.")]
        private UnityEvent m_OnTPoseAccepted = new UnityEvent();

        [SerializeField, Tooltip("The walk-in step succeeded: the avatar follows the wearer.")]
        private UnityEvent m_OnCalibrated = new UnityEvent();

        [SerializeField, Tooltip("A saved calibration was restored.")]
        private UnityEvent m_OnRestored = new UnityEvent();

        [SerializeField, Tooltip("A step was refused; the argument is the message shown to the wearer.")]
        private UnityEvent<string> m_OnStepRefused = new UnityEvent<string>();

        [SerializeField, Tooltip("The calibration was reset (cancel or redo).")]
        private UnityEvent m_OnCalibrationReset = new UnityEvent();

        [SerializeField, Tooltip("The refinement exercise ended and was applied; the argument is true when the arms changed (the avatar was rebuilt with them, the profile saved again).")]
        private UnityEvent<bool> m_OnRefined = new UnityEvent<bool>();

        private readonly CalibrationFlow _flow = new CalibrationFlow();
        private readonly RefinementFlow _refinement = new RefinementFlow();
        private SelfAvatarPipeline _pipeline;
        private SessionFrame _frame;
        private int _headerVersion = int.MinValue;
        private AvatarGoTrackingSource _builtFor;     // the source the pipeline was made for
        private CalibrationDisplay _display;
        private AvatarGoFingers _fingers;
        private bool _failed, _resetByUser, _hasFrame;
        private MirrorPlane _mirror;
        private bool _hasMirror, _mirrorFailed;
        private ProportionedBones _bones;

        /// <summary>Where the devices come from. May be set at run time: the next frame makes a pipeline for the new source's devices.</summary>
        public AvatarGoTrackingSource Source { get => m_Source; set => m_Source = value; }

        /// <summary>
        /// The avatar's Animator (humanoid). Read in <c>Start</c>, where the avatar is bound: set it before (a setup error
        /// found there disables the component for good; fix the setup and add the component again).
        /// </summary>
        public Animator Animator { get => m_Animator; set => m_Animator = value; }

        /// <summary>The root of an avatar without a humanoid Animator. Read in <c>Start</c>, as <see cref="Animator"/> is.</summary>
        public Transform AvatarRoot { get => m_AvatarRoot; set => m_AvatarRoot = value; }

        /// <summary>
        /// Exact or fixed offsets; read when the pipeline is made and at each calibration (set at run time, it reaches the
        /// pipeline's settings at once: the next calibration, or the next restored profile, uses it).
        /// </summary>
        public OffsetMode Offsets
        {
            get => m_Offsets;
            set
            {
                m_Offsets = value;
                if (_pipeline != null) _pipeline.Settings.Offsets = value; // the pipeline reads it when a calibration completes
            }
        }

        /// <summary>
        /// Uniform (the paper's eye-height scaling) or fitted proportions (legs and arms fitted to the wearer, applied to the
        /// avatar's knee, ankle, elbow and wrist bones); read when the pipeline is made. A restored calibration keeps the
        /// proportions it was measured with.
        /// </summary>
        public CoreScaleMode AvatarScaleMode { get => m_ScaleMode; set => m_ScaleMode = value; }

        /// <summary>How slowly a shoulder releases a held shrug (s, clamped to 0…10, NaN gives the default 3; 0 holds none; <c>PipelineSettings.ShrugReleaseSeconds</c>); read when the pipeline is made.</summary>
        public float ShrugReleaseSeconds { get => m_ShrugReleaseSeconds; set => m_ShrugReleaseSeconds = Clamped(value, 10f, FullBodyIk.DefaultShrugReleaseSeconds); }

        /// <summary>The straight leg's filter cutoff (Hz, clamped to 0…10, NaN gives the default 1; 0 turns it off; <c>PipelineSettings.StraightLegCutoffHz</c>); read when the pipeline is made.</summary>
        public float StraightLegCutoffHz { get => m_StraightLegCutoffHz; set => m_StraightLegCutoffHz = Clamped(value, 10f, FullBodyIk.DefaultStraightLegCutoffHz); }

        /// <summary>The straight arm's filter cutoff (Hz, clamped to 0…10, NaN gives the default 1; 0 turns it off; <c>PipelineSettings.StraightArmCutoffHz</c>); read when the pipeline is made.</summary>
        public float StraightArmCutoffHz { get => m_StraightArmCutoffHz; set => m_StraightArmCutoffHz = Clamped(value, 10f, FullBodyIk.DefaultStraightArmCutoffHz); }

        /// <summary>The hips-to-head change the back does not flex for (m, clamped to 0…0.02, NaN gives the default 0.0014; <c>PipelineSettings.SpineChordNoiseMetres</c>); read when the pipeline is made.</summary>
        public float SpineChordNoiseMetres { get => m_SpineChordNoiseMetres; set => m_SpineChordNoiseMetres = Clamped(value, 0.02f, FullBodyIk.DefaultChordNoiseMetres); }

        /// <summary>The back's chord filter cutoff (Hz, clamped to 0…10, NaN gives the default 1; 0 turns it off; <c>PipelineSettings.SpineChordCutoffHz</c>); read when the pipeline is made.</summary>
        public float SpineChordCutoffHz { get => m_SpineChordCutoffHz; set => m_SpineChordCutoffHz = Clamped(value, 10f, FullBodyIk.DefaultChordCutoffHz); }

        // A tuning value set from code: NaN gives the default, anything else is clamped to 0…max (the inspector's range).
        private static float Clamped(float value, float max, float fallback) => float.IsNaN(value) ? fallback : Math.Min(max, Math.Max(0f, value));

        // A serialized tuning value as the pipeline takes it: outside 0…max (a hand-edited asset) gives the default.
        private static float InRangeOr(float value, float max, float fallback) => value >= 0f && value <= max ? value : fallback;

        /// <summary>Whether each new calibration is followed by the refinement exercise (<see cref="Refinement"/>); read when a calibration completes.</summary>
        public bool RefinesAfterCalibration { get => m_RefineAfterCalibration; set => m_RefineAfterCalibration = value; }

        /// <summary>How long the refinement exercise lasts (s, 2…60); read when it starts.</summary>
        public float ExerciseSeconds { get => m_ExerciseSeconds; set => m_ExerciseSeconds = value; }

        /// <summary>The refinement exercise: its phase, what the wearer reads, the last report (<see cref="RefinementFlow.LastReport"/>).</summary>
        public RefinementFlow Refinement => _refinement;

        /// <summary>Which bone transforms take the calibration's proportions, and where they are (null before <c>Start</c> binds the avatar).</summary>
        public ProportionedBones Bones => _bones;

        /// <summary>Whether a saved calibration is restored when the pipeline is made for the source's devices (at start and whenever they change); samples and tests that must calibrate turn it off.</summary>
        public bool RestoresSavedProfileOnStart { get => m_RestoreSavedProfile; set => m_RestoreSavedProfile = value; }

        /// <summary>Whether each new calibration is saved to <see cref="ProfilePath"/>.</summary>
        public bool SavesProfile { get => m_SaveProfile; set => m_SaveProfile = value; }

        /// <summary>Diameter of the device markers (m; NaN, zero or negative gives the default 0.06, at most 0.5: <c>CalibrationDisplaySizes.ValidMarkerSize</c>).</summary>
        public float MarkerSize => CalibrationDisplaySizes.ValidMarkerSize(m_MarkerSize);

        /// <summary>Character size of the instructions (NaN, zero or negative gives the default 0.0025, at most 0.05: <c>CalibrationDisplaySizes.ValidTextSize</c>).</summary>
        public float TextSize => CalibrationDisplaySizes.ValidTextSize(m_TextSize);

        /// <summary>The avatar's transforms bound to the core, once started (null if the avatar cannot be bound).</summary>
        public HumanoidBinding Binding { get; private set; }

        /// <summary>The pipeline, once the source has devices; made again when the source's devices change.</summary>
        public SelfAvatarPipeline Pipeline => _pipeline;

        /// <summary>This frame's devices as read from the source (valid when <see cref="HasFrame"/>).</summary>
        public SessionFrame CurrentFrame => _frame;

        /// <summary>True once a frame has been read.</summary>
        public bool HasFrame => _hasFrame;

        /// <summary>Where tracking space lies in the scene this frame.</summary>
        public TrackingSpace TrackingSpace { get; private set; } = TrackingSpace.World;

        /// <summary>What is shown and announced.</summary>
        public CalibrationFlow Flow => _flow;

        /// <summary>Where this avatar's calibration is saved.</summary>
        public string ProfilePath => Path.Combine(AvatarGoFiles.Folder(Application.persistentDataPath), AvatarGoFiles.ProfileFileName(AvatarName));

        /// <summary>Raised every frame after the pipeline ran, with the frame it was fed (AvatarGoRecorder records it).</summary>
        public event Action<SessionFrame> FrameRead
        {
            add
            {
                if (value == null) return;
                _frameRead.Add(value);
                _frameReadNow = _frameRead.ToArray();
            }
            remove
            {
                if (_frameRead.Remove(value)) _frameReadNow = _frameRead.ToArray();
            }
        }

        // The listeners of FrameRead, kept as a list so that each is called on its own; the frame is dispatched to a copy made
        // when they change (not per frame), so that a listener that unsubscribes while called does not make the next miss it.
        private readonly List<Action<SessionFrame>> _frameRead = new List<Action<SessionFrame>>(2);
        private Action<SessionFrame>[] _frameReadNow = Array.Empty<Action<SessionFrame>>();

        /// <summary>The T-pose step succeeded.</summary>
        public UnityEvent OnTPoseAccepted => m_OnTPoseAccepted;

        /// <summary>The walk-in step succeeded.</summary>
        public UnityEvent OnCalibrated => m_OnCalibrated;

        /// <summary>A saved calibration was restored.</summary>
        public UnityEvent OnRestored => m_OnRestored;

        /// <summary>A step was refused, with the wearer's message.</summary>
        public UnityEvent<string> OnStepRefused => m_OnStepRefused;

        /// <summary>The calibration was reset.</summary>
        public UnityEvent OnCalibrationReset => m_OnCalibrationReset;

        /// <summary>The refinement exercise ended and was applied; true when the arms changed (<see cref="RefinementFlow.LastReport"/> has the details).</summary>
        public UnityEvent<bool> OnRefined => m_OnRefined;

        private string AvatarName => m_Animator != null && m_Animator.avatar != null ? m_Animator.avatar.name
            : Binding != null ? Binding.Root.name : name;

        /// <summary>Cancels or redoes the calibration: back to the T-pose step; the saved calibration is not restored again.</summary>
        public void ResetCalibration()
        {
            _resetByUser = true;
            if (_pipeline == null) return;
            _pipeline.Reset();
            ApplyProportions();
            AnnounceRefinement(_refinement.AfterUpdate(_hasFrame ? _frame.Time : 0.0, _pipeline,
                _flow.Reset(_hasFrame ? _frame.Time : 0.0, _pipeline.LastCalibrationStep.Message)));
            Debug.Log($"{nameof(AvatarGoCalibrator)}: calibration reset. {_pipeline.LastCalibrationStep.Message}", this);
            Raise(m_OnCalibrationReset);
        }

        /// <summary>
        /// Restores this avatar's saved calibration now, if there is one, it was measured on this avatar, and its devices are
        /// connected (matched by serial). Returns true when restored.
        /// </summary>
        public bool RestoreSavedProfile()
        {
            if (_pipeline == null || Binding == null || Binding.Root == null) return false; // a destroyed avatar has no file name
            string path = ProfilePath;
            if (!File.Exists(path)) return false;
            CalibrationProfile profile;
            try
            {
                profile = CalibrationProfileStore.Load(path);
            }
            catch (Exception e) when (e is IOException || e is FormatException || e is UnauthorizedAccessException)
            {
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the saved calibration {path} cannot be read ({e.Message}); calibrate again.", this);
                return false;
            }
            if (!AvatarGoFiles.ProfileFits(profile, Binding.Map, SpineJointsAsBound, out string reason))
            {
                Debug.Log($"{nameof(AvatarGoCalibrator)}: the saved calibration {path} is not for this avatar ({reason}).", this);
                return false;
            }
            if (!_pipeline.TryRestore(profile, out string why))
            {
                Debug.Log($"{nameof(AvatarGoCalibrator)}: the saved calibration {path} is not used: {why}; calibrate, or wait for its devices.", this);
                return false;
            }
            AnnounceRefinement(_refinement.AfterUpdate(_hasFrame ? _frame.Time : 0.0, _pipeline, _flow.Restored(_hasFrame ? _frame.Time : 0.0)));
            Debug.Log($"{nameof(AvatarGoCalibrator)}: calibration restored from {path}.", this);
            Raise(m_OnRestored);
            return true;
        }

        /// <summary>
        /// Saves the current calibration to <see cref="ProfilePath"/> (atomically). Returns false, with a warning, when it
        /// cannot, and with an error when the avatar has been destroyed (the file is named after it).
        /// </summary>
        public bool SaveProfile()
        {
            if (_pipeline == null || _pipeline.State != CalibrationState.Calibrated || _pipeline.Profile == null) return false;
            // The profile's file is named after the avatar, which a destroyed one no longer has (its name would throw).
            if (Binding == null || Binding.Root == null)
            {
                Debug.LogError($"{nameof(AvatarGoCalibrator)} on '{name}': the avatar was destroyed; its calibration is not saved.", this);
                return false;
            }
            try
            {
                CalibrationProfileStore.Save(_pipeline.Profile, ProfilePath);
                return true;
            }
            // ArgumentException: the store refuses a profile it could not load back (proportions beyond its limits).
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the calibration could not be saved to {ProfilePath} ({e.Message}).", this);
                return false;
            }
        }

        internal void Attach(AvatarGoFingers fingers)
        {
            _fingers = fingers;
            if (_pipeline == null) return;
            fingers.ConfigureHands(_pipeline.Settings);
            _pipeline.ApplyHandSettings();
        }

        internal void Detach(AvatarGoFingers fingers)
        {
            if (_fingers == fingers) _fingers = null;
        }

        private void OnEnable() => Application.onBeforeRender += UpdateMirror;

        private void OnDisable()
        {
            Application.onBeforeRender -= UpdateMirror;
            _display?.HideAll();
            if (_bones != null && _bones.Restore()) CopyBones(); // the bind positions back
        }

        // The bones the calibration's proportions move, to where the core says (bind positions while there is no profile).
        private void ApplyProportions()
        {
            if (_bones != null && _bones.Update(_pipeline != null ? _pipeline.Profile : null, enabled)) CopyBones();
        }

        private void CopyBones()
        {
            if (Binding == null) return;
            for (int i = 0; i < _bones.Count; i++)
            {
                Transform t = Binding.Joint(_bones.Joint(i));
                if (t != null) t.localPosition = _bones.LocalPosition(i).ToUnity();
            }
        }

        // After the Animator: the fitted positions again, in case it wrote the bones' bind positions back while animating.
        private void LateUpdate()
        {
            if (_failed || _bones == null || _bones.Applied.IsUniform) return;
            CopyBones();
        }

        private void Start()
        {
            if (m_Source == null)
            {
                Fail("no tracking source is assigned");
                return;
            }
            bool bound = m_Animator != null
                ? HumanoidBinding.TryBind(m_Animator, out HumanoidBinding binding, out string error)
                : HumanoidBinding.TryBindByNames(m_AvatarRoot, out binding, out error);
            if (!bound)
            {
                Fail(m_Animator == null && m_AvatarRoot == null ? "no avatar is assigned (an Animator, or the root of an avatar without one)" : error);
                return;
            }
            Binding = binding;
            var bind = new System.Numerics.Vector3[binding.Hierarchy.JointCount];
            for (int j = 0; j < bind.Length; j++) bind[j] = binding.BindLocalPose(j).Position;
            _bones = new ProportionedBones(binding.Map, bind);
            _display = new CalibrationDisplay(this, binding);
            AddDriver();
        }

        private void Update()
        {
            if (_failed || Binding == null) return;
            if (Binding.Root == null)
            {
                Fail("the avatar was destroyed");
                return;
            }
            SessionHeader header = m_Source != null ? m_Source.Header : null;
            if (header == null) return; // no devices yet
            // Another source (the Source property set at run time) may report the same header version: the source itself is compared too.
            if (_pipeline == null || m_Source.HeaderVersion != _headerVersion || !ReferenceEquals(m_Source, _builtFor)) Rebuild(header);
            if (_failed) return;
            CalibrationStep step;
            RefinementFlowEvents refinement;
            try
            {
                m_Source.Read(_frame);
                TrackingSpace = m_Source.GetTrackingSpace();
                // A refinement exercise that is over ends before the pipeline runs the frame, which is then solved on the
                // refined avatar (every consumer picks the new ScaledAvatar and Pose up this frame).
                refinement = _refinement.BeforeUpdate(_frame, _pipeline);
                step = _pipeline.Update(_frame);
            }
            catch (Exception e)
            {
                Debug.LogException(e, this);
                Fail("the tracking source or the pipeline failed (see the exception above)");
                return;
            }
            _hasFrame = true;
            CalibrationFlowEvents events = _flow.Update(_frame.Time, step, _pipeline.State);
            _refinement.Enabled = m_RefineAfterCalibration;
            _refinement.ExerciseSeconds = m_ExerciseSeconds;
            refinement |= _refinement.AfterUpdate(_frame.Time, _pipeline, events);
            ApplyProportions(); // the refined arms too, the frame they change
            Announce(events, step);
            AnnounceRefinement(refinement);
            ShowFrame();
            // Each listener on its own: one that throws is logged and neither stops the others nor escapes Update.
            Action<SessionFrame>[] listeners = _frameReadNow;
            for (int i = 0; i < listeners.Length; i++)
            {
                try
                {
                    listeners[i](_frame);
                }
                catch (Exception e)
                {
                    Debug.LogException(e, this);
                }
            }
        }

        private void OnDestroy()
        {
            _display?.Dispose();
            _display = null;
        }

        // The devices changed (or first came): a new pipeline for them; a calibration in use is carried over when its devices
        // are still there, else the saved one is tried.
        private void Rebuild(SessionHeader header)
        {
            SelfAvatarPipeline old = _pipeline;
            AnnounceRefinement(_refinement.Cancel(old)); // an exercise recorded on the old pipeline is dropped
            var settings = new PipelineSettings { Offsets = m_Offsets };
            settings.ShrugReleaseSeconds = InRangeOr(m_ShrugReleaseSeconds, 10f, FullBodyIk.DefaultShrugReleaseSeconds);
            settings.StraightLegCutoffHz = InRangeOr(m_StraightLegCutoffHz, 10f, FullBodyIk.DefaultStraightLegCutoffHz);
            settings.StraightArmCutoffHz = InRangeOr(m_StraightArmCutoffHz, 10f, FullBodyIk.DefaultStraightArmCutoffHz);
            settings.SpineChordNoiseMetres = InRangeOr(m_SpineChordNoiseMetres, 0.02f, FullBodyIk.DefaultChordNoiseMetres);
            settings.SpineChordCutoffHz = InRangeOr(m_SpineChordCutoffHz, 10f, FullBodyIk.DefaultChordCutoffHz);
            settings.Calibration.Proportions.Mode = m_ScaleMode;
            settings.Calibration.SpineJointsAsBound = SpineJointsAsBound;
            if (_fingers != null) _fingers.ConfigureHands(settings);
            try
            {
                _pipeline = new SelfAvatarPipeline(header.Devices, Binding.Map, settings);
            }
            catch (ArgumentException e)
            {
                Fail($"the pipeline cannot be made for the source's devices: {e.Message}");
                return;
            }
            _frame = new SessionFrame(header);
            _headerVersion = m_Source.HeaderVersion;
            _builtFor = m_Source;
            _display.SetDeviceCount(header.Devices.Count);
            double now = _hasFrame ? _frame.Time : 0.0;
            if (old != null && old.State == CalibrationState.Calibrated && old.Profile != null)
            {
                if (_pipeline.TryRestore(old.Profile, out string why))
                {
                    _refinement.AfterUpdate(now, _pipeline, _flow.Restored(now));
                    Debug.Log($"{nameof(AvatarGoCalibrator)}: the devices changed; the calibration is kept (its devices are all still there).", this);
                    return;
                }
                // Why, as the profile says it (not always a device gone: without serials, as with OpenXR, none can be recognised).
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the devices changed and the calibration cannot be kept: {why}; calibrate again.", this);
            }
            _flow.Reset(now, _pipeline.LastCalibrationStep.Message);
            if (m_RestoreSavedProfile && !_resetByUser) RestoreSavedProfile();
        }

        private void Announce(CalibrationFlowEvents events, CalibrationStep step)
        {
            if (events == CalibrationFlowEvents.None) return;
            string explanation = step.Explanation.Length > 0 ? " [" + step.Explanation + "]" : "";
            if ((events & CalibrationFlowEvents.PressIgnored) != 0) Debug.Log($"{nameof(AvatarGoCalibrator)}: {step.Explanation}", this);
            if ((events & CalibrationFlowEvents.StepRefused) != 0)
            {
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: {step.State} step refused ({step.Error}): {step.Message}{explanation}", this);
                Raise(m_OnStepRefused, step.Message);
            }
            if ((events & CalibrationFlowEvents.TPoseAccepted) != 0)
            {
                Debug.Log($"{nameof(AvatarGoCalibrator)}: T-pose accepted (avatar scale {_pipeline.Profile.AvatarScale:0.000}). {step.Message}{explanation}", this);
                Raise(m_OnTPoseAccepted);
            }
            if ((events & CalibrationFlowEvents.Calibrated) != 0)
            {
                Debug.Log($"{nameof(AvatarGoCalibrator)}: calibrated.{explanation}", this);
                if ((events & CalibrationFlowEvents.SaveProfile) != 0 && m_SaveProfile) SaveProfile();
                Raise(m_OnCalibrated);
            }
        }

        private void AnnounceRefinement(RefinementFlowEvents events)
        {
            if (events == RefinementFlowEvents.None) return;
            string log = $"{nameof(AvatarGoCalibrator)}: {_refinement.Explanation}";
            if ((events & RefinementFlowEvents.BeginRefused) != 0) Debug.LogWarning(log, this);
            if ((events & (RefinementFlowEvents.Began | RefinementFlowEvents.PressIgnored | RefinementFlowEvents.Cancelled)) != 0) Debug.Log(log, this);
            if ((events & RefinementFlowEvents.Ended) == 0) return;
            Debug.Log(log, this);
            if ((events & RefinementFlowEvents.SaveProfile) != 0 && m_SaveProfile) SaveProfile();
            Raise(m_OnRefined, (events & RefinementFlowEvents.ArmsChanged) != 0);
        }

        private void ShowFrame()
        {
            _flow.KeepMirrorAfterCalibration = m_KeepMirrorAfterCalibration;
            SkeletonPose pose = _pipeline.Pose;
            _display.ShowAvatar(pose != null || !m_HideAvatarUntilTPose);
            _hasMirror = false;
            if (m_ShowMirror && _flow.ShowsMirror && pose != null && _pipeline.Profile != null)
            {
                MirrorPlane tracking = MirrorPlane.InFrontOf(_pipeline.Profile.Placement, MirrorPlane.ValidDistance(m_MirrorDistance));
                TrackingSpace space = TrackingSpace;
                _mirror = new MirrorPlane(space.ToWorld(tracking.Point), System.Numerics.Vector3.Transform(tracking.Normal, space.Origin.Rotation));
                _hasMirror = true;
            }
            _display.UpdateMarkers(_frame, TrackingSpace, m_ShowDeviceMarkers && _flow.ShowsMarkers, _hasMirror, _mirror);
            _display.UpdateText(_refinement.Shown(_flow.Message), m_ShowInstructions, HeadSample(), TrackingSpace, Time.unscaledDeltaTime); // the panel follows the head in a paused game too
        }

        // The HMD's sample: the device playing the head once identified, else the first HMD of the source.
        private DeviceSample HeadSample()
        {
            int head = _pipeline.DeviceIndexOf(DeviceRole.Head);
            if (head < 0)
                for (int d = 0; d < _pipeline.Devices.Count && head < 0; d++)
                    if (_pipeline.Devices[d].Class == DeviceClass.Hmd) head = d;
            return head >= 0 ? _frame.Samples[head] : DeviceSample.Lost;
        }

        // Before rendering, once every bone is final: the mirrored copy takes the avatar's pose.
        private void UpdateMirror()
        {
            if (_display == null || _failed || _mirrorFailed) return;
            // Application.onBeforeRender calls its subscribers in turn without a guard: an exception here would skip the
            // later ones (the XR Interaction Toolkit's among them), so it is logged once and the mirror given up.
            try
            {
                _display.UpdateMirror(_hasMirror, _mirror);
            }
            catch (Exception e)
            {
                Debug.LogException(e, this);
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the calibration mirror failed (see the exception above) and is no longer shown.", this);
                _mirrorFailed = true;
            }
        }

        // Unity's Animator leaves the joints between the humanoid spine bones as they are bound: so does the core's pose when
        // the Animator IK driver writes the bones (CalibrationSettings.SpineJointsAsBound).
        private bool SpineJointsAsBound => m_Driver == DriverKind.AnimatorIK && m_Animator != null;

        private void AddDriver()
        {
            switch (m_Driver)
            {
                case DriverKind.AnimatorIK when m_Animator != null:
                    AvatarGoAnimatorIKDriver ik = m_Animator.GetComponent<AvatarGoAnimatorIKDriver>();
                    if (ik == null) ik = m_Animator.gameObject.AddComponent<AvatarGoAnimatorIKDriver>();
                    if (ik.Calibrator == null) ik.Calibrator = this;
                    // Unity's humanoid IK solves with the Avatar's own bone lengths; the fitted (or refined) lengths are written
                    // to the bones afterwards, which may pull the hands and feet off their goals (not confirmed in Unity yet).
                    if (m_ScaleMode == CoreScaleMode.Fitted || m_RefineAfterCalibration)
                        Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: {(m_ScaleMode == CoreScaleMode.Fitted ? "Scale Mode Fitted" : "Refine After Calibration")} with the Animator IK driver: Unity's IK uses the Avatar's bind lengths, so the hands and feet may miss their goals by the change of the limbs' lengths. The Transforms driver applies the fitted or refined solve exactly (calibrator.md).", this);
                    break;
                case DriverKind.AnimatorIK:
                case DriverKind.Transforms:
                    if (m_Driver == DriverKind.AnimatorIK)
                        Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the avatar has no humanoid Animator; its bones are written by an {nameof(AvatarGoTransformDriver)} instead of Animator IK.", this);
                    AvatarGoTransformDriver transforms = Binding.Root.GetComponent<AvatarGoTransformDriver>();
                    if (transforms == null) transforms = Binding.Root.gameObject.AddComponent<AvatarGoTransformDriver>();
                    if (transforms.Calibrator == null) transforms.Calibrator = this;
                    break;
            }
        }

        private void Raise(UnityEvent e)
        {
            try
            {
                e?.Invoke();
            }
            catch (Exception x)
            {
                Debug.LogException(x, this);
            }
        }

        private void Raise(UnityEvent<bool> e, bool argument)
        {
            try
            {
                e?.Invoke(argument);
            }
            catch (Exception x)
            {
                Debug.LogException(x, this);
            }
        }

        private void Raise(UnityEvent<string> e, string argument)
        {
            try
            {
                e?.Invoke(argument);
            }
            catch (Exception x)
            {
                Debug.LogException(x, this);
            }
        }

        // A setup error: logged once with this component as context; the component disables itself.
        private void Fail(string message) => SetupErrors.Fail(this, ref _failed, message);
    }
}
