using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// The Walk-In-Avatar calibration as a small state machine fed with device samples and trigger events:
    /// <see cref="CalibrationState.WaitingForTPose"/> → (trigger: identify the devices, validate the T-pose, scale and place
    /// the avatar) → <see cref="CalibrationState.WalkIn"/> → (trigger: exact offsets) → <see cref="CalibrationState.Calibrated"/>.
    /// Every measurement is an average over the last <see cref="CalibrationSettings.WindowSeconds"/> before the press
    /// (<see cref="SampleWindow"/>) and requires the wearer to be still; the work of a step is done by
    /// <see cref="DeviceIdentifier"/> and <see cref="TPoseValidator"/>. Each <see cref="Update"/> returns what happened as a
    /// <see cref="CalibrationStep"/>. Never blocks; <see cref="Update"/> allocates nothing while no trigger is pressed.
    /// </summary>
    /// <remarks>
    /// Trigger rules: only a controller's press runs a step (unless <see cref="CalibrationSettings.AcceptTriggerFromAnyDevice"/>);
    /// at most one step runs per frame; and a step runs only when its window lies wholly after the previous step, so both
    /// triggers pressed together (or within the window) can never skip the walk-in. Ignored presses are reported.
    /// </remarks>
    public sealed class Calibrator
    {
        private readonly DeviceInfo[] _devices;
        private readonly HumanoidMap _avatar;
        private readonly CalibrationSettings _settings;
        private readonly SampleWindow _window;
        private readonly DeviceIdentifier _identifier;
        private readonly TPoseValidator _validator;
        private readonly WindowAverage[] _averages;
        private readonly Dictionary<int, int> _indexById = new Dictionary<int, int>();
        private readonly PerRole<int> _deviceByRole = new PerRole<int>(-1);
        private double _lastAdvance = double.NegativeInfinity;
        private readonly SteadyClock _clock = new SteadyClock();
        private BodyFeatures _tposeFeatures;

        /// <summary>Creates a calibrator for these devices (in the order samples will come) and this avatar.</summary>
        /// <exception cref="ArgumentException">The avatar lacks a required humanoid bone, or two devices share an id.</exception>
        public Calibrator(IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, CalibrationSettings settings = null)
        {
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            _avatar = avatar ?? throw new ArgumentNullException(nameof(avatar));
            avatar.RequireComplete(nameof(avatar));
            _settings = settings ?? new CalibrationSettings();
            _devices = new DeviceInfo[devices.Count];
            for (int i = 0; i < _devices.Length; i++)
            {
                _devices[i] = devices[i] ?? throw new ArgumentException($"Device {i} is null.", nameof(devices));
                if (_indexById.ContainsKey(_devices[i].Id)) throw new ArgumentException($"Device id {_devices[i].Id} is used twice.", nameof(devices));
                _indexById.Add(_devices[i].Id, i);
            }
            _window = new SampleWindow(_devices.Length, _settings);
            _identifier = new DeviceIdentifier(_devices, _settings);
            _validator = new TPoseValidator(_settings);
            _averages = new WindowAverage[_devices.Length];
            Reset();
        }

        /// <summary>The current step.</summary>
        public CalibrationState State { get; private set; }

        /// <summary>
        /// The result of the last frame that did something (a step that ran, a press ignored, a restore or a reset): its
        /// error and message stay what the wearer should be told until the next one.
        /// </summary>
        public CalibrationStep LastStep { get; private set; }

        /// <summary>The index (in the device list) of the device playing <paramref name="role"/>, or -1 before identification.</summary>
        public int DeviceIndexOf(DeviceRole role) => _deviceByRole[role];

        /// <summary>After identification: the avatar scaled to the wearer, with its humanoid map.</summary>
        public HumanoidMap ScaledAvatar { get; private set; }

        /// <summary>After identification: the scaled avatar in T-pose where the wearer stood (what to show in the mirror).</summary>
        public SkeletonPose AvatarPose { get; private set; }

        /// <summary>After identification the scale and placement, after the walk-in step the whole calibration; else null.</summary>
        public CalibrationProfile Profile { get; private set; }

        /// <summary>Goes back to the T-pose step, forgetting roles, scale and offsets (cancel or redo).</summary>
        public void Reset()
        {
            State = CalibrationState.WaitingForTPose;
            ScaledAvatar = null;
            AvatarPose = null;
            Profile = null;
            _deviceByRole.Fill(-1);
            _lastAdvance = double.NegativeInfinity;
            LastStep = new CalibrationStep(State, CalibrationStepOutcome.Advanced, CalibrationError.None, CalibrationMessages.Instruction(State), null);
        }

        /// <summary>
        /// Reuses a saved profile instead of calibrating: when the same devices are worn (matched by serial), the roles,
        /// the scaled avatar and its calibration pose are rebuilt and the state becomes <see cref="CalibrationState.Calibrated"/>.
        /// Returns false (and changes nothing) when a device of the profile is not connected.
        /// </summary>
        public bool TryRestore(CalibrationProfile profile) => TryRestore(profile, out _);

        /// <summary>As <see cref="TryRestore(CalibrationProfile)"/>, with why not (<see cref="CalibrationProfile.MatchesDevices(System.Collections.Generic.IReadOnlyList{DeviceInfo}, out string)"/>).</summary>
        public bool TryRestore(CalibrationProfile profile, out string reason)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            if (!profile.MatchesDevices(_devices, out reason)) return false;
            var roles = new PerRole<int>(-1);
            foreach (DeviceRole role in BodyRoles.All)
                for (int d = 0; d < _devices.Length; d++)
                    if (_devices[d].Serial == profile.Serial(role)) roles[role] = d;
            _deviceByRole.CopyFrom(roles);
            ShowAvatar(profile.AvatarScale, profile.Placement, profile.Proportions);
            Profile = profile.WithDeviceIds(_devices, _deviceByRole);
            State = CalibrationState.Calibrated;
            LastStep = new CalibrationStep(State, CalibrationStepOutcome.Advanced, CalibrationError.None, "Calibration restored from a saved profile.", null);
            return true;
        }

        /// <summary>
        /// Feeds one frame: the samples of every device (in constructor order) and this frame's events (null for none).
        /// A controller's trigger press runs the current step. Returns what this frame did; allocates nothing without a press.
        /// </summary>
        /// <exception cref="ArgumentException">Not one sample per device.</exception>
        public CalibrationStep Update(double time, ReadOnlySpan<DeviceSample> samples, IReadOnlyList<DeviceEvent> events)
        {
            // The averaging windows and the spacing of presses run on a steady clock: a time that is not finite, or a clock
            // that restarts, would otherwise let a second press skip the walk-in or ignore every press until it came back.
            time = _clock.Advance(time);
            _window.Add(time, samples);
            CalibrationStep result = default;
            bool acted = false;
            for (int e = 0; events != null && e < events.Count; e++)
            {
                if (events[e].Kind != DeviceEventKind.TriggerPressed) continue;
                bool stepRan = acted && result.Outcome != CalibrationStepOutcome.PressIgnored;
                string ignored = WhyIgnored(events[e].DeviceId, time, stepRan);
                if (ignored != null && stepRan)
                {
                    // The step this frame ran stays what the frame did (the other trigger is often pressed with it): reported
                    // as ignored instead, the step was never announced, saved or followed by the refinement (found in review).
                    result = new CalibrationStep(result.State, result.Outcome, result.Error, result.Message,
                        result.Explanation != null ? result.Explanation + "; " + ignored : ignored);
                }
                else
                {
                    result = ignored != null
                        ? new CalibrationStep(State, CalibrationStepOutcome.PressIgnored, LastStep.Error, LastStep.Message, ignored)
                        : State == CalibrationState.WaitingForTPose ? Identify(time) : ComputeOffsets(time);
                }
                acted = true;
                LastStep = result;
            }
            return acted ? result : new CalibrationStep(State, CalibrationStepOutcome.Waiting, LastStep.Error, LastStep.Message, null);
        }

        // Why a trigger press on this device at this time runs no step, or null when it runs one.
        private string WhyIgnored(int deviceId, double time, bool stepRanThisFrame)
        {
            if (!_indexById.TryGetValue(deviceId, out int index)) return $"a trigger press came from unknown device id {deviceId}";
            DeviceInfo device = _devices[index];
            if (!_settings.AcceptTriggerFromAnyDevice && device.Class != DeviceClass.Controller)
                return $"a trigger press from {device} was ignored: only a controller's trigger advances calibration";
            if (stepRanThisFrame) return $"a second trigger press in the same frame ({device}) was ignored: one step per press";
            if (State == CalibrationState.Calibrated) return $"a trigger press from {device} was ignored: already calibrated (reset to calibrate again)";
            if (time - _lastAdvance < _settings.WindowSeconds)
                return $"a trigger press from {device} was ignored: it came {time - _lastAdvance:0.00} s after the previous step, " +
                       $"sooner than the {_settings.WindowSeconds:0.0#} s the next step averages over";
            return null;
        }

        private CalibrationStep Refuse(CalibrationError error, string detail, string explanation = null)
        {
            _deviceByRole.Fill(-1);
            string message = CalibrationMessages.For(error) + (detail != null ? " (" + detail + ")" : "");
            return new CalibrationStep(State, CalibrationStepOutcome.Refused, error, message, explanation);
        }

        private CalibrationStep Advance(double time, string explanation = null)
        {
            _lastAdvance = time;
            return new CalibrationStep(State, CalibrationStepOutcome.Advanced, CalibrationError.None, CalibrationMessages.Instruction(State), explanation);
        }

        private void AverageWindow(double now)
        {
            for (int d = 0; d < _devices.Length; d++) _averages[d] = _window.Average(d, now);
        }

        // ---- Step 1: identification, validation, scale, placement ----------------------------------------

        private CalibrationStep Identify(double now)
        {
            AverageWindow(now);
            var explanation = new StringBuilder();
            CalibrationError error = _identifier.Select(_averages, out DeviceSelection chosen, out string detail, explanation);
            if (error == CalibrationError.None && _validator.CheckStill(chosen, _averages, out int moving) != CalibrationError.None)
            {
                error = CalibrationError.DevicesMoving;
                detail = _devices[moving].ToString();
            }
            if (error == CalibrationError.None) error = _validator.CheckPosture(chosen, _averages, out detail);
            System.Numerics.Vector3 forward = System.Numerics.Vector3.UnitZ;
            if (error == CalibrationError.None) error = _validator.FitBodyPlane(chosen, _averages, out forward, out detail);
            if (error == CalibrationError.None)
                error = _identifier.AssignSides(chosen, _averages, System.Numerics.Vector3.Cross(System.Numerics.Vector3.UnitY, forward), _deviceByRole, out detail);
            if (error == CalibrationError.None) error = _validator.CheckLevels(_deviceByRole, _averages, chosen.Floor, chosen.EyeHeight, out detail);
            if (error != CalibrationError.None) return Refuse(error, detail, explanation.ToString());

            // Scale: the wearer's eye height over the avatar's; with fitted proportions, legs and arms to the measurement.
            var unscaled = new SkeletonPose(_avatar.Skeleton);
            TPoser.Apply(_avatar, unscaled, RigidPose.Identity, null, _settings.SpineJointsAsBound);
            float avatarEye = TPoser.EyePosition(_avatar, unscaled, System.Numerics.Quaternion.Identity).Y;
            float scale = TPoser.ScaleForEyeHeight(_avatar, unscaled, chosen.EyeHeight);
            _tposeFeatures = Features(chosen.Floor);
            ProportionFit fit = ProportionFitter.Fit(_avatar, _tposeFeatures, _settings.Proportions);
            BodyProportions proportions = BodyProportions.Uniform;
            if (_settings.Proportions.Mode == ScaleMode.Fitted)
            {
                proportions = fit.Proportions;
                scale = fit.Scale;
            }
            explanation.Append(explanation.Length > 0 ? "; " : "").Append(fit.Explanation);
            // What a profile cannot hold is refused here, not when the profile is saved (an avatar 10 % taller than the
            // wearer, modelled in millimetres, is 0.00095).
            if (!(scale >= CalibrationProfileStore.MinAvatarScale && scale <= CalibrationProfileStore.MaxAvatarScale))
                return Refuse(CalibrationError.AvatarScaleOutOfRange,
                    FormattableString.Invariant($"the avatar would be scaled by {scale:G3}, outside {CalibrationProfileStore.MinAvatarScale:G3}–{CalibrationProfileStore.MaxAvatarScale:G3} (its eye height {avatarEye:G4} in its units)"),
                    explanation.ToString());
            if (!(avatarEye > 0f && avatarEye <= CalibrationProfileStore.MaxHeight))
                return Refuse(CalibrationError.AvatarScaleOutOfRange,
                    FormattableString.Invariant($"the avatar's eyes are at {avatarEye:G5} in its units, beyond the {CalibrationProfileStore.MaxHeight:G3} a saved profile holds (model it in larger units)"),
                    explanation.ToString());
            RigidPose placement = _validator.Placement(_deviceByRole, _averages, chosen.Floor, forward);
            ShowAvatar(scale, placement, proportions);
            Profile = new CalibrationProfile
            {
                AvatarScale = scale, WearerEyeHeight = chosen.EyeHeight, AvatarEyeHeight = avatarEye, FloorHeight = chosen.Floor, Placement = placement,
                ScaleMode = _settings.Proportions.Mode, Proportions = proportions, Measurements = fit.Measurements,
            };
            foreach (DeviceRole role in BodyRoles.All) Profile.SetDevice(role, _devices[_deviceByRole[role]]);
            State = CalibrationState.WalkIn;
            return Advance(now, explanation.ToString());
        }

        // The avatar scaled (and fitted) and in T-pose at the placement (what the wearer walks into).
        private void ShowAvatar(float scale, RigidPose placement, BodyProportions proportions)
        {
            ScaledAvatar = proportions.IsUniform ? new HumanoidMap(_avatar.Skeleton.Scaled(scale), _avatar.Pairs()) : proportions.Apply(_avatar, scale);
            AvatarPose = new SkeletonPose(ScaledAvatar.Skeleton);
            TPoser.Apply(ScaledAvatar, AvatarPose, placement, null, _settings.SpineJointsAsBound);
        }

        // ---- Step 2: exact offsets -----------------------------------------------------------------------

        private CalibrationStep ComputeOffsets(double now)
        {
            AverageWindow(now);
            foreach (DeviceRole role in BodyRoles.All)
            {
                int d = _deviceByRole[role];
                if (!_averages[d].IsTracked) return Keep(CalibrationError.DeviceNotTracked, _devices[d].ToString());
                if (!_averages[d].IsStill) return Keep(CalibrationError.DevicesMoving, _devices[d].ToString());
            }
            // Inside the avatar: the offsets measured now would otherwise take in however far the wearer stands from it.
            Vector3 hmd = _averages[_deviceByRole[DeviceRole.Head]].Position;
            Vector3 eyes = TPoser.EyePosition(ScaledAvatar, AvatarPose, Profile.Placement.Rotation);
            float apart = Vectors.HorizontalDistance(hmd, eyes);
            if (apart > MaxWalkInDistance)
                return Keep(CalibrationError.NotInsideAvatar, FormattableString.Invariant($"the headset is {apart:0.00} m from the avatar's eyes"));
            string note = Remeasure();
            foreach (DeviceRole role in BodyRoles.All)
            {
                RigidPose joint = AvatarPose.World[ScaledAvatar[BodyRoles.JointOf(role)]];
                Profile.SetOffsets(role, _averages[_deviceByRole[role]].Mean, joint);
            }
            Profile.RootToHead = _averages[_deviceByRole[DeviceRole.Head]].Position - _averages[_deviceByRole[DeviceRole.Pelvis]].Position;
            State = CalibrationState.Calibrated;
            return Advance(now, note);
        }

        /// <summary>
        /// How far (m) the HMD may be from the avatar's eyes, horizontally, when the walk-in is confirmed (0.3 m): standing in
        /// the avatar it is within a few centimetres (the HMD sits a little ahead of the eyes); farther, the wearer has not
        /// walked in, and every offset would take that distance in.
        /// </summary>
        public const float MaxWalkInDistance = 0.3f;

        // The largest difference between the T-pose's and the walk-in's features for the two to count as the same T-pose.
        private const float SamePoseTolerance = 0.05f;

        // The device features of this window's averages (the roles known).
        private BodyFeatures Features(float floor) => BodyFeatures.FromDevices(
            _averages[_deviceByRole[DeviceRole.Head]].Position, _averages[_deviceByRole[DeviceRole.Pelvis]].Position,
            _averages[_deviceByRole[DeviceRole.LeftHand]].Position, _averages[_deviceByRole[DeviceRole.RightHand]].Position,
            floor, _settings.Proportions.PelvisTrackerAboveHips);

        // The walk-in is the same T-pose inside the avatar: its window and the T-pose's measure the wearer together. With
        // fitted proportions the avatar is refitted to both (the offsets are then computed on it); a uniform avatar keeps the
        // T-pose's scale (the paper's). A walk-in pose that differs from the T-pose's is not pooled.
        private string Remeasure()
        {
            BodyFeatures walkIn = Features(Profile.FloorHeight);
            float difference = BodyFeatures.Difference(_tposeFeatures, walkIn);
            if (!walkIn.IsFinite || !(difference <= SamePoseTolerance))
                return FormattableString.Invariant($"the walk-in pose differs from the T-pose by {difference * 100:0.0} cm: measured from the T-pose alone");
            ProportionFit fit = ProportionFitter.Fit(_avatar, BodyFeatures.Mean(_tposeFeatures, walkIn), _settings.Proportions, 0.5f * difference, 2);
            Profile.Measurements = fit.Measurements;
            if (_settings.Proportions.Mode != ScaleMode.Fitted) return null;
            // Proportions still uniform: the T-pose's scale stays (the paper's), so fitting changes nothing for such a wearer.
            if (fit.Proportions.IsUniform && Profile.Proportions.IsUniform) return "refitted to the T-pose and the walk-in: " + fit.Explanation;
            if (!fit.Proportions.Equals(Profile.Proportions) || fit.Scale != Profile.AvatarScale)
            {
                ShowAvatar(fit.Scale, Profile.Placement, fit.Proportions);
                Profile.AvatarScale = fit.Scale;
                Profile.Proportions = fit.Proportions;
            }
            return "refitted to the T-pose and the walk-in: " + fit.Explanation;
        }

        /// <summary>
        /// After calibration: the avatar rebuilt with <paramref name="proportions"/> (same overall scale and placement) and
        /// the exact offsets computed again on it from the devices' walk-in poses, as step 2 did (the refinement from motion,
        /// <see cref="ProportionRefinement"/>). Allocates.
        /// </summary>
        internal void Refit(BodyProportions proportions)
        {
            ShowAvatar(Profile.AvatarScale, Profile.Placement, proportions);
            Profile.Proportions = proportions;
            foreach (DeviceRole role in BodyRoles.All)
                Profile.SetOffsets(role, Profile.DeviceAtCalibration(role), AvatarPose.World[ScaledAvatar[BodyRoles.JointOf(role)]]);
            // The offsets just set are exact: a profile of the fixed-offset baseline gets its fixed ones back, as
            // WithRemeasuredDevice does (it ran on exact offsets and saved as fixed; found in review).
            if (Profile.Mode == OffsetMode.Fixed) Profile = Profile.WithFixedOffsets();
        }

        // A refused walk-in step keeps the roles: the wearer only has to hold still and press again.
        private CalibrationStep Keep(CalibrationError error, string detail) =>
            new CalibrationStep(State, CalibrationStepOutcome.Refused, error, CalibrationMessages.For(error) + " (" + detail + ")", null);
    }
}
