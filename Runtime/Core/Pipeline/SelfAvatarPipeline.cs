using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The whole system in one object: device samples, analog inputs and trigger events in; the calibration's state and
    /// the avatar's solved pose (body and fingers) out. Until calibrated it runs the Walk-In-Avatar
    /// <see cref="Calibrator"/> (or takes a saved profile, <see cref="TryRestore(CalibrationProfile)"/>); from then on every frame maps the
    /// devices to targets with the exact offsets (<see cref="BodyTargetMapper"/>), solves the body
    /// (<see cref="FullBodyIk"/>), puts each hand on its controller and closes its fingers on the controller's surface
    /// (<see cref="FingerSolver"/>). Unity components call <see cref="Update(double, ReadOnlySpan{DeviceSample}, ReadOnlySpan{float}, ReadOnlySpan{float}, IReadOnlyList{DeviceEvent})"/>
    /// once a frame and copy <see cref="Pose"/> to the avatar.
    /// </summary>
    /// <remarks>
    /// <para>Hands: the wrist's goal is the controller's pose times the palm's exact offset from the controller's grip
    /// (<see cref="HandPlacement.PalmOnController"/>, the paper's: needs the hand's controller profile and finger bones),
    /// or the controller-to-wrist offset measured at the walk-in (<see cref="HandPlacement.CalibratedOffset"/>, and for
    /// hands without finger IK). Where the arm cannot reach, the hand goes as far as it can and the virtual controller is
    /// drawn in the hand, in the same grip (<see cref="HandState.ControllerPose"/>), back at the tracked pose as soon as the
    /// hand reaches it again; the fingers close on the controller where it is drawn.</para>
    /// <para>Per frame after calibration: nothing is allocated (but in the frame a swap of devices is found and, with
    /// <see cref="TrackingSettings.ReassignSwappedDevices"/>, reassigned: <see cref="SwapDevices"/> rebuilds the
    /// per-calibration objects), nothing throws on bad samples (NaN, non-unit quaternions,
    /// lost tracking: the affected part keeps its last pose), the output is finite (a frame that would not be is replaced by
    /// the last good one), and nothing depends on the frame rate. Trigger presses after calibration are left to the
    /// application.</para>
    /// </remarks>
    public sealed class SelfAvatarPipeline
    {
        private readonly DeviceInfo[] _devices;
        private readonly Calibrator _calibrator;
        private readonly HandState[] _handStates = { new HandState(BodySide.Left), new HandState(BodySide.Right) };
        private readonly HandModel[] _hands = new HandModel[2];
        private readonly FingerSolver[] _fingers = new FingerSolver[2];
        private readonly RigidPose[] _controllerInWrist = new RigidPose[2];
        private BodyTargetMapper _mapper;
        private SampleSanitizer _sanitizer;
        private TrackingContinuity _continuity;
        private RoleSwapDetector _swaps;
        private OneEuroFilter _smoothing;                 // null when TrackingSettings.Smoothing is off
        private SampleWindow _window;                     // the last half second after calibration, for RecalibrateDevice
        private DeviceSample[] _accepted, _effective;
        private double _lastFiniteTime;                   // the last frame time that was a finite number
        private CalibrationProfile _measured;             // the calibration, with later swaps and re-measured devices
        private readonly PerRole<int> _roles = new PerRole<int>(-1);
        private float _armLength;
        private SwapEvidence _evidence;
        private readonly SteadyClock _clock = new SteadyClock(); // the tracking stages' time, once calibrated (Solve)
        private FullBodyIk _ik;
        private SkeletonPose _pose, _lastGood;
        private BodyTargets _targets;
        private IkReport _report;
        private ProportionRefinement _refinement;         // while the refinement exercise is recorded

        /// <summary>Creates the pipeline for these devices (in the order every frame's samples come) and this avatar.</summary>
        /// <exception cref="ArgumentException">The avatar lacks a required humanoid bone, or two devices share an id.</exception>
        public SelfAvatarPipeline(IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, PipelineSettings settings = null)
        {
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            Avatar = avatar ?? throw new ArgumentNullException(nameof(avatar));
            Settings = settings ?? new PipelineSettings();
            _devices = new DeviceInfo[devices.Count];
            for (int i = 0; i < _devices.Length; i++) _devices[i] = devices[i];
            _calibrator = new Calibrator(_devices, avatar, Settings.Calibration);
        }

        /// <summary>The settings. Grip modes are read every frame; controllers and the offset mode when calibration completes
        /// (or at <see cref="ApplyHandSettings"/>).</summary>
        public PipelineSettings Settings { get; }

        /// <summary>The devices, in sample order.</summary>
        public IReadOnlyList<DeviceInfo> Devices => _devices;

        /// <summary>The avatar as given (unscaled).</summary>
        public HumanoidMap Avatar { get; }

        /// <summary>The avatar scaled to the wearer, once the T-pose step has run (else null); <see cref="Pose"/> belongs to it.</summary>
        public HumanoidMap ScaledAvatar => _calibrator.ScaledAvatar;

        /// <summary>The calibration's state.</summary>
        public CalibrationState State => _calibrator.State;

        /// <summary>The last calibration step that did something (its message is what the wearer should be told).</summary>
        public CalibrationStep LastCalibrationStep => _calibrator.LastStep;

        /// <summary>
        /// The measured calibration (exact offsets, what to save), once calibrated or restored, with any later swaps of
        /// devices and re-measured devices; during the walk-in its scale and placement.
        /// </summary>
        public CalibrationProfile Profile => _measured ?? _calibrator.Profile;

        /// <summary>The calibration the body is driven with: <see cref="Profile"/>, or its fixed-offset baseline (<see cref="PipelineSettings.Offsets"/>).</summary>
        public CalibrationProfile ActiveProfile { get; private set; }

        /// <summary>The index (in <see cref="Devices"/>) of the device playing <paramref name="role"/>, or -1 before identification.</summary>
        public int DeviceIndexOf(DeviceRole role) => _mapper != null ? _roles[role] : _calibrator.DeviceIndexOf(role);

        /// <summary>
        /// The last pair of devices found swapped after calibration (controllers between the hands, trackers between the
        /// feet), or <see cref="RoleSwap.None"/>; <see cref="LastSwapTime"/> says when. With
        /// <see cref="TrackingSettings.ReassignSwappedDevices"/> the devices were given each other's roles then.
        /// </summary>
        public RoleSwap LastSwap { get; private set; }

        /// <summary>When <see cref="LastSwap"/> was found (the frame's time), or NaN.</summary>
        public double LastSwapTime { get; private set; } = double.NaN;

        /// <summary>
        /// The avatar's pose, world and local, of <see cref="ScaledAvatar"/>'s skeleton: null before the T-pose step; the
        /// scaled avatar standing in T-pose where the wearer stood during the walk-in (what the mirror shows); the solved
        /// pose, fingers included, once calibrated. A new object after each calibration.
        /// </summary>
        public SkeletonPose Pose => _pose ?? _calibrator.AvatarPose;

        /// <summary>This frame's targets (root, head, spine bend, limb goals and knee/elbow hints), once calibrated.</summary>
        public BodyTargets Targets => _targets;

        /// <summary>What the body IK achieved this frame, per limb.</summary>
        public IkReport Ik => _report;

        /// <summary>One hand's state after this frame: reach, where to draw its controller, its fingers.</summary>
        public HandState Hand(BodySide side) => _handStates[(int)side];

        /// <summary>
        /// Runs one frame. <paramref name="samples"/>: every device's sample, in <see cref="Devices"/> order.
        /// <paramref name="trigger"/> and <paramref name="grip"/>: each device's analog values 0..1 (NaN: not given), or empty
        /// spans when there are none. <paramref name="events"/>: this frame's trigger events, or null. Returns the
        /// calibration's result for this frame. Allocation-free once calibrated, but for the frame a swap of devices is
        /// reassigned (<see cref="SwapDevices"/>).
        /// </summary>
        /// <exception cref="ArgumentException">A span's length is not the number of devices (a programming error, not bad data).</exception>
        public CalibrationStep Update(double time, ReadOnlySpan<DeviceSample> samples, ReadOnlySpan<float> trigger, ReadOnlySpan<float> grip, IReadOnlyList<DeviceEvent> events)
        {
            if (samples.Length != _devices.Length) throw new ArgumentException($"Expected {_devices.Length} samples, got {samples.Length}.", nameof(samples));
            if (trigger.Length != 0 && trigger.Length != _devices.Length) throw new ArgumentException($"Expected {_devices.Length} trigger values or none, got {trigger.Length}.", nameof(trigger));
            if (grip.Length != 0 && grip.Length != _devices.Length) throw new ArgumentException($"Expected {_devices.Length} grip values or none, got {grip.Length}.", nameof(grip));
            // A time that is not a number or infinite (a broken clock, a bad recording) is a frame in which no time passed:
            // taken on, it would hold a part lost on that frame for good and open the glitch filter.
            if (double.IsNaN(time) || double.IsInfinity(time)) time = _lastFiniteTime;
            else _lastFiniteTime = time;
            if (_mapper == null)
            {
                CalibrationStep step = _calibrator.Update(time, samples, events);
                if (State == CalibrationState.Calibrated) Setup(); // solving starts with the next frame
                return step;
            }
            Solve(time, samples, trigger, grip);
            CalibrationStep last = _calibrator.LastStep;
            return new CalibrationStep(State, CalibrationStepOutcome.Waiting, last.Error, last.Message, null);
        }

        /// <summary>Runs one frame of a recorded or synthetic session (its samples, analog inputs and events).</summary>
        public CalibrationStep Update(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            return Update(frame.Time, frame.Samples, frame.Trigger, frame.Grip, frame.Events);
        }

        /// <summary>
        /// Takes a saved calibration instead of calibrating, when the same devices are worn (matched by serial): solving
        /// starts with the next frame (a refinement exercise being recorded is dropped). False, with nothing changed, when a
        /// device of the profile is not connected.
        /// </summary>
        public bool TryRestore(CalibrationProfile profile) => TryRestore(profile, out _);

        /// <summary>As <see cref="TryRestore(CalibrationProfile)"/>, with why not (a role without a serial, two with one, a device not connected).</summary>
        public bool TryRestore(CalibrationProfile profile, out string reason)
        {
            if (!_calibrator.TryRestore(profile, out reason)) return false;
            _refinement = null; // an exercise recorded on the previous avatar does not apply to the restored one
            Setup();
            return true;
        }

        /// <summary>Back to the T-pose step (cancel or redo the calibration).</summary>
        public void Reset()
        {
            _calibrator.Reset();
            _mapper = null;
            _ik = null;
            _pose = _lastGood = null;
            ActiveProfile = _measured = null;
            _refinement = null;
            LastSwap = RoleSwap.None;
            LastSwapTime = double.NaN;
            _targets = default;
            _report = default;
            for (int s = 0; s < 2; s++)
            {
                _hands[s] = null;
                _fingers[s] = null;
                // The hand as before its first calibration: no fingers solved, nothing held or reached (the next calibration
                // sets them up again; kept, they told a reader of the state of a grip no longer solved).
                HandState state = _handStates[s];
                state.Solver = null;
                state.Fingers.Clear();
                state.HasFingerIk = false;
                state.NoFingerIkReason = HandState.NotCalibrated;
                state.Holding = false;
                state.Reached = false;
                state.DistanceLeft = 0f;
                state.ControllerTracked = false;
                state.DrawnInHand = false;
                state.Placement = HandPlacement.CalibratedOffset;
            }
        }

        /// <summary>
        /// Gives the devices of <paramref name="a"/> and <paramref name="b"/> each other's roles (controllers in the other
        /// hands, trackers on the other feet), as <see cref="RoleSwapDetector"/> does by itself; the avatar blends to the new
        /// assignment. Allocates (the per-calibration objects are rebuilt). False before calibration.
        /// </summary>
        public bool SwapDevices(DeviceRole a, DeviceRole b)
        {
            if (_mapper == null || a == b) return false;
            _measured = _measured.WithSwappedDevices(a, b);
            Bind(true);
            return true;
        }

        /// <summary>
        /// Measures one device's offset again (a tracker re-strapped, perhaps after a swap of the feet), without redoing the
        /// calibration: the wearer stands still in the calibration's T-pose for half a second, then this is called. The joint
        /// is put where the calibration pose has it relative to the pelvis (the head, for the pelvis), placed by the pelvis's
        /// (head's) device now. Fails (false, with <paramref name="reason"/>) when the device or its reference was not tracked
        /// and still through the last half second, or when the hand's wrist is placed from the palm rather than measured.
        /// Allocates.
        /// </summary>
        public bool RecalibrateDevice(DeviceRole role, out string reason)
        {
            reason = null;
            if (_mapper == null) { reason = "not calibrated yet"; return false; }
            if ((role == DeviceRole.LeftHand || role == DeviceRole.RightHand) && _handStates[role == DeviceRole.LeftHand ? 0 : 1].Placement == HandPlacement.PalmOnController)
            {
                reason = "this hand's wrist is placed from the palm on the controller, not from a measured offset";
                return false;
            }
            DeviceRole referenceRole = role == DeviceRole.Pelvis ? DeviceRole.Head : DeviceRole.Pelvis;
            WindowAverage device = _window.Average(_roles[role], _clock.Now), reference = _window.Average(_roles[referenceRole], _clock.Now);
            if (!device.IsTracked || !reference.IsTracked) { reason = "the device or the " + referenceRole + " device was not tracked through the last half second"; return false; }
            if (!device.IsStill || !reference.IsStill) { reason = "the wearer was not still through the last half second"; return false; }
            // Where the calibration pose puts the joint relative to its reference joint, placed by the reference now.
            SkeletonPose calibrationPose = _calibrator.AvatarPose;
            HumanoidMap scaled = _calibrator.ScaledAvatar;
            RigidPose reference0 = calibrationPose.World[scaled[BodyRoles.JointOf(referenceRole)]];
            RigidPose joint0 = calibrationPose.World[scaled[BodyRoles.JointOf(role)]];
            // The measured offset of the reference, whatever the offset mode (the fixed ones would write their error into the
            // profile that is saved).
            RigidPose referenceNow = reference.Mean * _measured.JointInDevice(referenceRole);
            _measured = _measured.WithRemeasuredDevice(role, device.Mean, referenceNow * joint0.RelativeTo(reference0));
            Bind(true);
            return true;
        }

        /// <summary>
        /// Starts the refinement exercise (<see cref="ProportionRefinement"/>): from the next frame on, every solved frame is
        /// recorded (allocation-free) until <see cref="EndRefinement"/>. False before calibration. Allocates the recorder
        /// (<paramref name="capacity"/> frames, 20 s at 90 Hz by default).
        /// </summary>
        public bool BeginRefinement(int capacity = 1800)
        {
            if (_mapper == null) return false;
            _refinement = new ProportionRefinement(_calibrator.ScaledAvatar, _calibrator.Profile.Proportions, Settings.Calibration.Proportions, capacity,
                HandleRadius(AppliedController(BodySide.Left) ?? Settings.Hand(BodySide.Left).Controller),
                HandleRadius(AppliedController(BodySide.Right) ?? Settings.Hand(BodySide.Right).Controller));
            _refinement.Begin();
            return true;
        }

        // The controller the hand's settings were last applied with (its finger solver's), not the setting as it is now: a
        // setting changed or cleared takes effect at ApplyHandSettings or the next calibration, not at a swap or a re-measured
        // device (found in review: cleared, the next swap threw; changed, the wrist moved onto the new controller's grip while
        // the fingers still closed on the old one).
        private ControllerProfile AppliedController(BodySide side) => _fingers[(int)side]?.Profile;

        private static float HandleRadius(ControllerProfile controller) =>
            controller != null ? -controller.Shape.Distance(Vector3.Zero) : ProportionFitter.DefaultHandleRadius;

        /// <summary>True between <see cref="BeginRefinement"/> and <see cref="EndRefinement"/>.</summary>
        public bool IsRefining => _refinement != null && _refinement.IsRecording;

        /// <summary>
        /// Ends the refinement exercise and applies it: the arms' lengths refined from their reach, the avatar rebuilt with
        /// them and the exact offsets computed again on it from the walk-in (<see cref="ScaledAvatar"/>, <see cref="Pose"/> and
        /// the solver are new objects when anything changed; the calibration's <see cref="Profile"/> is the same object, its
        /// proportions and offsets updated, so compare proportions by value, not the profile by reference; later swaps and
        /// re-measured devices are undone, as by a new calibration; the new avatar goes on from the old one's pose, a lost part
        /// from where it was shown). Returns the report with each limb's residual before and
        /// after, or null when no exercise was started. Allocates.
        /// </summary>
        public RefinementReport EndRefinement()
        {
            if (_refinement == null) return null;
            RefinementReport report = _refinement.Solve();
            _refinement = null;
            if (_mapper == null || !report.Changed) return report;
            HumanoidMap before = _calibrator.ScaledAvatar;
            _calibrator.Refit(report.After);
            Setup(continueFrom: before);
            return report;
        }

        /// <summary>
        /// Drops a refinement exercise without applying it (the recorded frames are forgotten; nothing changes). True when one
        /// was being recorded.
        /// </summary>
        public bool CancelRefinement()
        {
            bool was = IsRefining;
            _refinement = null;
            return was;
        }

        /// <summary>
        /// Applies the hands' <see cref="HandSettings.Controller"/> and <see cref="HandSettings.Placement"/> (and the offset
        /// mode) now instead of at the next calibration: builds the finger solvers (allocates, about 1 ms per hand). Swaps and
        /// re-measured devices since the calibration are kept, and the avatar goes on from the pose it shows (a lost part from
        /// where it is shown).
        /// </summary>
        public void ApplyHandSettings()
        {
            if (_mapper != null) Setup(keepMeasured: true, continueFrom: _calibrator.ScaledAvatar);
        }

        // ---- Setup, once per calibration ----------------------------------------------------------------------

        // keepMeasured: the hands' settings changed, not the calibration, so the swaps and re-measured devices since it stay.
        // continueFrom: the avatar (map) the session was solved on until now, when it goes on (the hands' settings applied, the
        // refinement's arms): the avatar continues from the pose it showed, a lost part from where it was shown, not from the
        // calibration pose (found in review: a hand lost when the settings were applied jumped 0.76 m to the T-pose).
        private void Setup(bool keepMeasured = false, HumanoidMap continueFrom = null)
        {
            if (!keepMeasured || _measured == null) _measured = _calibrator.Profile;
            HumanoidMap scaled = _calibrator.ScaledAvatar;
            SkeletonPose calibrationPose = _calibrator.AvatarPose;
            SkeletonPose shown = continueFrom != null && _pose != null && _pose.Skeleton == continueFrom.Skeleton ? _pose : null, shownGood = _lastGood;
            bool sameAvatar = shown != null && continueFrom == scaled;
            _pose = new SkeletonPose(scaled.Skeleton);
            _pose.CopyFrom(calibrationPose);
            _lastGood = new SkeletonPose(scaled.Skeleton);
            _lastGood.CopyFrom(calibrationPose);
            if (shown != null)
            {
                CarryPose(shown, _pose);
                CarryPose(shownGood, _lastGood);
            }
            if (!sameAvatar)
            {
                // The same avatar keeps its solver (the held shrugs), its targets and the window a device is re-measured from.
                _targets = default;
                _report = default;
                _ik = new FullBodyIk(scaled, calibrationPose);
                _window = new SampleWindow(_devices.Length, Settings.Calibration);
            }
            _ik.ShrugReleaseSeconds = Settings.ShrugReleaseSeconds;
            _ik.ChordNoiseMetres = Settings.SpineChordNoiseMetres;
            _ik.ChordCutoffHz = Settings.SpineChordCutoffHz;
            _ik.StraightLegCutoffHz = Settings.StraightLegCutoffHz;
            _ik.StraightArmCutoffHz = Settings.StraightArmCutoffHz;
            TrackingSettings tracking = Settings.Tracking;
            _smoothing = tracking.Smoothing ? new OneEuroFilter(_devices.Length, tracking.SmoothingMinCutoff, tracking.SmoothingBeta) : null;
            _accepted = new DeviceSample[_devices.Length];
            _effective = new DeviceSample[_devices.Length];
            RigidPose[] w = calibrationPose.World;
            _armLength = Length(w, scaled, HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, HumanoidBone.RightHand);
            Vector3 right = Vector3.Transform(Vector3.UnitX, _measured.Placement.Rotation);
            float ankles = Math.Min(w[scaled[HumanoidBone.LeftFoot]].Position.Y, w[scaled[HumanoidBone.RightFoot]].Position.Y);
            _swaps = new RoleSwapDetector(Vector3.Transform(right, Quaternion.Conjugate(w[scaled[HumanoidBone.Hips]].Rotation)),
                w[scaled[HumanoidBone.Head]].Position.Y - ankles, Settings.Tracking);
            if (!keepMeasured)
            {
                LastSwap = RoleSwap.None;
                LastSwapTime = double.NaN;
            }
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                SetUpFingers(side);
                // The paper's hands: the palm on the controller's grip, where the hand has a model and a controller.
                HandState state = _handStates[(int)side];
                state.Placement = state.HasFingerIk && Settings.Hand(side).Placement == HandPlacement.PalmOnController
                    ? HandPlacement.PalmOnController : HandPlacement.CalibratedOffset;
            }
            Bind(shown != null, shown, continueFrom);
        }

        // The pose shown on one avatar carried to another of the same joints (the refinement changes bone lengths only): the
        // joints' rotations and the roots' places; the same avatar's, copied.
        private static void CarryPose(SkeletonPose from, SkeletonPose to)
        {
            if (from.Skeleton == to.Skeleton) { to.CopyFrom(from); return; }
            if (from.Local.Length != to.Local.Length) return;
            Skeleton s = to.Skeleton;
            for (int j = 0; j < to.Local.Length; j++)
                to.Local[j] = new RigidPose(s.GetParent(j) < 0 ? from.Local[j].Position : to.Local[j].Position, from.Local[j].Rotation);
            to.Origin = from.Origin;
            to.UpdateWorld();
        }

        // Everything that depends on which device plays which role and on the offsets: rebuilt after a calibration, a
        // swap or a re-measured device. After the last two the avatar blends from its current pose (or from
        // shownPose on shownAvatar: the pose shown until a new avatar replaced it).
        private void Bind(bool blendFromCurrentPose, SkeletonPose shownPose = null, HumanoidMap shownAvatar = null)
        {
            HumanoidMap scaled = _calibrator.ScaledAvatar;
            SkeletonPose calibrationPose = _calibrator.AvatarPose;
            CalibrationProfile active = Settings.Offsets == OffsetMode.Fixed ? _measured.WithFixedOffsets() : _measured;
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                if (_handStates[(int)side].Placement == HandPlacement.PalmOnController)
                    active = active.WithJointInDevice(BodyRoles.Hand(side), _hands[(int)side].WristInController(AppliedController(side)));
            ActiveProfile = active;
            foreach (DeviceRole role in BodyRoles.All)
                for (int d = 0; d < _devices.Length; d++)
                    if (_devices[d].Id == active.DeviceId(role)) _roles[role] = d;
            _mapper = new BodyTargetMapper(active, _devices, scaled, calibrationPose, Settings.KneeHints, Settings.ElbowHints);
            var reach = new float[_devices.Length];
            for (int d = 0; d < reach.Length; d++) reach[d] = -1f; // devices no role uses are not checked
            // The body's reach, as the walk-in measured it: a device re-measured elsewhere later (RecalibrateDevice) keeps
            // the walk-in's distances; measured from a headset re-measured a metre away, good samples of the others were
            // rejected (found in review).
            CalibrationProfile walkIn = _calibrator.Profile ?? active;
            Vector3 head0 = walkIn.DeviceAtCalibration(DeviceRole.Head).Position;
            foreach (DeviceRole role in BodyRoles.All) reach[_roles[role]] = Vector3.Distance(walkIn.DeviceAtCalibration(role).Position, head0);
            _sanitizer = new SampleSanitizer(_devices.Length, _roles[DeviceRole.Head], reach, Settings.Tracking);
            _continuity = new TrackingContinuity(active, _roles, scaled, calibrationPose, Settings.Tracking);
            if (blendFromCurrentPose) _continuity.StartFrom(shownPose ?? _pose, shownAvatar ?? scaled);
            _swaps.Clear();
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int s = (int)side;
                _controllerInWrist[s] = active.JointInDevice(BodyRoles.Hand(side)).Inverse();
                if (blendFromCurrentPose) continue;
                _handStates[s].ControllerPose = _pose.World[scaled[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]] * _controllerInWrist[s];
                _handStates[s].DrawnInHand = false;
            }
        }

        private void SetUpFingers(BodySide side)
        {
            int s = (int)side;
            HandState state = _handStates[s];
            ControllerProfile controller = Settings.Hand(side).Controller;
            _hands[s] = null;
            _fingers[s] = null;
            state.Fingers.Clear();
            state.Holding = false;
            if (controller == null) state.NoFingerIkReason = "no controller profile is set for this hand";
            else if (HandModel.CanModel(_calibrator.ScaledAvatar, side, _calibrator.AvatarPose, out string reason))
            {
                _hands[s] = new HandModel(_calibrator.ScaledAvatar, side, _calibrator.AvatarPose); // the T-pose's straight fingers open the hand
                _fingers[s] = new FingerSolver(_hands[s], controller);
                state.NoFingerIkReason = null;
            }
            else state.NoFingerIkReason = reason;
            state.HasFingerIk = _fingers[s] != null;
            state.Solver = _fingers[s];
        }

        // ---- Every frame once calibrated ----------------------------------------------------------------------

        private void Solve(double time, ReadOnlySpan<DeviceSample> samples, ReadOnlySpan<float> trigger, ReadOnlySpan<float> grip)
        {
            // The tracking stages measure the time between frames on their own clock (SteadyClock: a recording's clock
            // that jumps neither holds a lost part for good, nor eases it in one frame, nor opens the glitch filter).
            double now = _clock.Advance(time);
            float dt = (float)_clock.LastStep;
            _window.Add(now, samples);
            // Bad samples out, lost devices' parts held and eased, returning ones blended back; without the HMD, freeze.
            _sanitizer.Filter(now, _clock.RegularStep, samples, _accepted);
            _smoothing?.Apply(now, _accepted);
            if (!_continuity.Apply(now, _accepted, _pose, _effective))
            {
                Freeze();
                return;
            }
            _mapper.Compute(_effective, ref _targets);
            _report = _ik.Solve(in _targets, _pose, dt);
            PlaceHand(BodySide.Left, in _targets.LeftHand, _report.LeftHand, _effective, trigger, grip);
            PlaceHand(BodySide.Right, in _targets.RightHand, _report.RightHand, _effective, trigger, grip);
            _pose.UpdateWorld();
            if (IsFinite(_pose)) _lastGood.CopyFrom(_pose);
            else _pose.CopyFrom(_lastGood); // never a NaN on a bone: keep the last good frame
            if (_refinement != null && _refinement.IsRecording)
            {
                // The arms' targets are the controllers themselves: unlike the wrists' goals (placed by the walk-in's offset
                // on most hands) they do not depend on the avatar's arm length.
                BodyTargets reach = _targets;
                ReachTarget(ref reach.LeftHand, DeviceRole.LeftHand);
                ReachTarget(ref reach.RightHand, DeviceRole.RightHand);
                _refinement.Add(in reach, _pose);
            }
            CheckForSwaps(time, dt);
        }

        // The refinement's target for one hand: the controller's pose, as the frame's target used it. Inactive when the
        // frame's hand target is.
        private void ReachTarget(ref LimbTarget target, DeviceRole role)
        {
            if (!target.IsActive) return;
            DeviceSample controller = _effective[_roles[role]];
            if (!controller.Pose.IsValid) { target.IsActive = false; return; }
            target.Goal = controller.Pose;
        }

        // Controllers in the other hands, or trackers on the other feet: found from where the devices are.
        private void CheckForSwaps(double time, float dt)
        {
            HumanoidMap avatar = _calibrator.ScaledAvatar;
            CalibrationProfile p = ActiveProfile;
            DeviceSample lh = _accepted[_roles[DeviceRole.LeftHand]], rh = _accepted[_roles[DeviceRole.RightHand]];
            DeviceSample lf = _accepted[_roles[DeviceRole.LeftFoot]], rf = _accepted[_roles[DeviceRole.RightFoot]];
            ref SwapEvidence e = ref _evidence;
            e.LeftHand = (lh.Pose * p.JointInDevice(DeviceRole.LeftHand)).Position;
            e.RightHand = (rh.Pose * p.JointInDevice(DeviceRole.RightHand)).Position;
            e.LeftHandIfSwapped = (rh.Pose * p.JointInDevice(DeviceRole.LeftHand)).Position;
            e.RightHandIfSwapped = (lh.Pose * p.JointInDevice(DeviceRole.RightHand)).Position;
            e.LeftShoulder = _pose.World[avatar[HumanoidBone.LeftUpperArm]].Position;
            e.RightShoulder = _pose.World[avatar[HumanoidBone.RightUpperArm]].Position;
            e.ArmLength = _armLength;
            e.HandsTracked = lh.IsTracked && rh.IsTracked;
            e.LeftFoot = (lf.Pose * p.JointInDevice(DeviceRole.LeftFoot)).Position;
            e.RightFoot = (rf.Pose * p.JointInDevice(DeviceRole.RightFoot)).Position;
            e.FeetTracked = lf.IsTracked && rf.IsTracked;
            RoleSwap swap = _swaps.Update(dt, _targets.Hips, _targets.Head.Position, in _evidence);
            if (swap == RoleSwap.None) return;
            LastSwap = swap;
            LastSwapTime = time;
            if (!Settings.Tracking.ReassignSwappedDevices) return;
            if (swap == RoleSwap.Hands) SwapDevices(DeviceRole.LeftHand, DeviceRole.RightHand);
            else SwapDevices(DeviceRole.LeftFoot, DeviceRole.RightFoot);
        }

        // Where the controller is drawn (tracked, or in the hand where the arm cannot reach), then the fingers on it.
        private void PlaceHand(BodySide side, in LimbTarget target, LimbResult reach, ReadOnlySpan<DeviceSample> samples,
            ReadOnlySpan<float> trigger, ReadOnlySpan<float> grip)
        {
            int s = (int)side;
            HandState state = _handStates[s];
            HumanoidMap avatar = _calibrator.ScaledAvatar;
            RigidPose wrist = _pose.World[avatar[side == BodySide.Left ? HumanoidBone.LeftHand : HumanoidBone.RightHand]];
            RigidPose inHand = wrist * _controllerInWrist[s];
            int device = _roles[BodyRoles.Hand(side)];
            state.ControllerTracked = _continuity.IsTracked(BodyRoles.Hand(side));
            state.Reached = target.IsActive && reach.Reached;
            state.DistanceLeft = target.IsActive ? reach.DistanceLeft : 0f;
            // At the tracked pose only while the hand is really there; in the hand while it cannot reach, while the
            // controller is lost, and while its part is blended back after a loss.
            state.DrawnInHand = !(state.Reached && state.ControllerTracked && !_continuity.IsRecovering(BodyRoles.Hand(side)));
            state.ControllerPose = state.DrawnInHand ? inHand : samples[device].Pose;
            HandSettings settings = Settings.Hand(side);

            FingerSolver fingers = _fingers[s];
            if (fingers == null) return;
            float triggerValue = trigger.Length > 0 ? trigger[device] : float.NaN;
            float gripValue = grip.Length > 0 ? grip[device] : float.NaN;
            fingers.Solve(wrist, state.ControllerPose, settings.Grip, triggerValue, gripValue);
            state.Fingers.CopyFrom(fingers.Parameters);
            state.Holding = !fingers.OutOfReach && settings.Grip != GripMode.Open;
            _hands[s].Apply(fingers.Parameters, _pose);
        }

        // No HMD: the avatar keeps its last pose; the controllers stay in the hands.
        private void Freeze()
        {
            HumanoidMap avatar = _calibrator.ScaledAvatar;
            for (int s = 0; s < 2; s++)
            {
                HandState state = _handStates[s];
                state.ControllerTracked = _continuity.IsTracked(BodyRoles.Hand(state.Side));
                state.Reached = false;
                state.DrawnInHand = true;
                state.ControllerPose = _pose.World[avatar[HumanoidBones.OnSide(HumanoidBone.LeftHand, state.Side)]] * _controllerInWrist[s];
            }
        }

        private static float Length(RigidPose[] w, HumanoidMap avatar, HumanoidBone root, HumanoidBone middle, HumanoidBone end) =>
            Vector3.Distance(w[avatar[root]].Position, w[avatar[middle]].Position) + Vector3.Distance(w[avatar[middle]].Position, w[avatar[end]].Position);

        private static bool IsFinite(SkeletonPose pose)
        {
            RigidPose[] world = pose.World;
            for (int j = 0; j < world.Length; j++)
                if (!Vectors.IsFinite(world[j].Position) || !Rotations.IsFinite(world[j].Rotation)) return false;
            return true;
        }
    }
}
