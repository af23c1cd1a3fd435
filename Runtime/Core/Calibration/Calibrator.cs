using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The Walk-In-Avatar calibration as a state machine fed with device samples and trigger events:
    /// <see cref="CalibrationState.WaitingForTPose"/> → (trigger: identify devices, validate the T-pose, scale and place
    /// the avatar) → <see cref="CalibrationState.WalkIn"/> → (trigger: exact offsets) → <see cref="CalibrationState.Calibrated"/>.
    /// Every measurement is an average over the last <see cref="CalibrationSettings.WindowSeconds"/> before the press,
    /// and requires the wearer to be still. Never blocks; <see cref="Update"/> allocates nothing while waiting.
    /// </summary>
    public sealed class Calibrator
    {
        private const int Capacity = 256;
        private readonly DeviceInfo[] _devices;
        private readonly HumanoidMap _avatar;
        private readonly CalibrationSettings _settings;
        private readonly double[] _times = new double[Capacity];
        private readonly RigidPose[,] _history;
        private readonly bool[,] _tracked;
        private int _head, _count;
        private readonly int[] _deviceByRole = new int[7];
        private readonly Vector3[] _positionScratch = new Vector3[Capacity];
        private readonly Quaternion[] _rotationScratch = new Quaternion[Capacity];

        /// <summary>Creates a calibrator for these devices (in the order samples will come) and this avatar.</summary>
        public Calibrator(IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, CalibrationSettings settings = null)
        {
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            _devices = new DeviceInfo[devices.Count];
            for (int i = 0; i < _devices.Length; i++) _devices[i] = devices[i];
            _avatar = avatar ?? throw new ArgumentNullException(nameof(avatar));
            var missing = avatar.MissingRequired();
            if (missing.Count > 0) throw new ArgumentException($"The avatar lacks required bones: {string.Join(", ", missing)}.", nameof(avatar));
            _settings = settings ?? new CalibrationSettings();
            _history = new RigidPose[_devices.Length, Capacity];
            _tracked = new bool[_devices.Length, Capacity];
            ResetRoles();
        }

        /// <summary>The current step.</summary>
        public CalibrationState State { get; private set; }

        /// <summary>Why the last trigger press was refused; <see cref="CalibrationError.None"/> after a successful step.</summary>
        public CalibrationError LastError { get; private set; }

        /// <summary>A message for the wearer about <see cref="LastError"/>, with details.</summary>
        public string LastMessage { get; private set; } = "Stand in a T-pose and press a trigger.";

        /// <summary>Notes on choices made in identification (for example which extra trackers were ignored), or empty.</summary>
        public string Explanation { get; private set; } = string.Empty;

        /// <summary>The index (in the device list) of the device playing <paramref name="role"/>, or -1 before identification.</summary>
        public int DeviceIndexOf(DeviceRole role) => _deviceByRole[(int)role];

        /// <summary>After identification: the avatar scaled to the wearer, with its humanoid map.</summary>
        public HumanoidMap ScaledAvatar { get; private set; }

        /// <summary>After identification: the scaled avatar in T-pose where the wearer stood (what to show in the mirror).</summary>
        public SkeletonPose AvatarPose { get; private set; }

        /// <summary>After the walk-in step: the calibration result.</summary>
        public CalibrationProfile Profile { get; private set; }

        /// <summary>Goes back to the T-pose step, forgetting roles, scale and offsets (cancel or redo).</summary>
        public void Reset()
        {
            State = CalibrationState.WaitingForTPose;
            LastError = CalibrationError.None;
            LastMessage = "Stand in a T-pose and press a trigger.";
            Explanation = string.Empty;
            ScaledAvatar = null;
            AvatarPose = null;
            Profile = null;
            ResetRoles();
        }

        /// <summary>
        /// Reuses a saved profile instead of calibrating: when the same devices are worn (matched by serial), the
        /// roles, the scaled avatar and its calibration pose are rebuilt and the state becomes
        /// <see cref="CalibrationState.Calibrated"/>. Returns false (and changes nothing) when a device is missing.
        /// </summary>
        public bool TryRestore(CalibrationProfile profile)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            if (!profile.MatchesDevices(_devices)) return false;
            ResetRoles();
            foreach (DeviceRole role in BodyRoles.All)
                for (int d = 0; d < _devices.Length; d++)
                    if (_devices[d].Serial == profile.Serial(role)) _deviceByRole[(int)role] = d;
            Skeleton scaled = _avatar.Skeleton.Scaled(profile.AvatarScale);
            ScaledAvatar = new HumanoidMap(scaled, _avatar.Pairs());
            AvatarPose = new SkeletonPose(scaled);
            TPoser.Apply(ScaledAvatar, AvatarPose, profile.Placement);
            var restored = profile.WithDeviceIds(_devices, _deviceByRole);
            Profile = restored;
            State = CalibrationState.Calibrated;
            LastError = CalibrationError.None;
            LastMessage = "Calibration restored from a saved profile.";
            return true;
        }

        /// <summary>
        /// Feeds one frame: the samples of every device (in constructor order) and this frame's events.
        /// A trigger press on any controller runs the current step.
        /// </summary>
        public void Update(double time, ReadOnlySpan<DeviceSample> samples, IReadOnlyList<DeviceEvent> events)
        {
            if (samples.Length != _devices.Length) throw new ArgumentException($"Expected {_devices.Length} samples, got {samples.Length}.", nameof(samples));
            _head = (_head + 1) % Capacity;
            _times[_head] = time;
            for (int d = 0; d < _devices.Length; d++)
            {
                _tracked[d, _head] = samples[d].IsUsable;
                _history[d, _head] = samples[d].IsUsable ? samples[d].Pose : RigidPose.Identity;
            }
            if (_count < Capacity) _count++;
            if (events == null) return;
            for (int e = 0; e < events.Count; e++)
            {
                if (events[e].Kind != DeviceEventKind.TriggerPressed) continue;
                if (State == CalibrationState.WaitingForTPose) Identify(time);
                else if (State == CalibrationState.WalkIn) ComputeOffsets(time);
            }
        }

        private void ResetRoles()
        {
            for (int i = 0; i < _deviceByRole.Length; i++) _deviceByRole[i] = -1;
        }

        private bool Fail(CalibrationError error, string detail = null)
        {
            LastError = error;
            LastMessage = CalibrationMessages.For(error) + (detail != null ? " (" + detail + ")" : "");
            return false;
        }

        // ---- Averaging over the window -------------------------------------------------------------------

        private bool TryAverage(int device, double now, out RigidPose mean, out bool still, out int trackedFraction)
        {
            int n = 0, total = 0;
            for (int k = 0; k < _count; k++)
            {
                int i = (_head - k + Capacity) % Capacity;
                if (now - _times[i] > _settings.WindowSeconds + 1e-9) break;
                total++;
                if (!_tracked[device, i]) continue;
                _positionScratch[n] = _history[device, i].Position;
                _rotationScratch[n] = _history[device, i].Rotation;
                n++;
            }
            trackedFraction = total == 0 ? 0 : n * 100 / total;
            still = false;
            mean = RigidPose.Identity;
            if (n == 0) return false;
            Vector3 p = Vector3.Zero;
            for (int i = 0; i < n; i++) p += _positionScratch[i];
            p /= n;
            Quaternion q = Rotations.Average(new ReadOnlySpan<Quaternion>(_rotationScratch, 0, n));
            still = true;
            for (int i = 0; i < n; i++)
                if (Vector3.Distance(_positionScratch[i], p) > _settings.StillPosition || Rotations.AngleDegrees(_rotationScratch[i], q) > _settings.StillRotationDegrees)
                    still = false;
            mean = new RigidPose(p, q);
            return true;
        }

        // ---- Step 1: identification, validation, scale, placement ----------------------------------------

        private bool Identify(double now)
        {
            Explanation = string.Empty;
            var hmds = new List<int>();
            var controllers = new List<int>();
            var trackers = new List<int>();
            for (int d = 0; d < _devices.Length; d++)
            {
                var list = _devices[d].Class == DeviceClass.Hmd ? hmds : _devices[d].Class == DeviceClass.Controller ? controllers : trackers;
                list.Add(d);
            }
            if (hmds.Count < 1 || controllers.Count < 2 || trackers.Count < 3)
                return Fail(CalibrationError.DeviceMissing, $"found {hmds.Count} HMD, {controllers.Count} controllers, {trackers.Count} trackers");

            var mean = new RigidPose[_devices.Length];
            var usable = new bool[_devices.Length];
            var still = new bool[_devices.Length];
            for (int d = 0; d < _devices.Length; d++)
                usable[d] = TryAverage(d, now, out mean[d], out still[d], out int fraction) && fraction >= 80;

            int hmd = hmds.Find(d => usable[d]);
            if (!usable[hmd]) return Fail(CalibrationError.DeviceNotTracked, "the headset");
            var liveControllers = controllers.FindAll(d => usable[d]);
            if (liveControllers.Count < 2) return Fail(CalibrationError.DeviceNotTracked, "a controller");
            var liveTrackers = trackers.FindAll(d => usable[d]);
            if (liveTrackers.Count < 3) return Fail(CalibrationError.DeviceNotTracked, $"{3 - liveTrackers.Count} tracker(s)");
            if (liveControllers.Count > 2) Explanation += $"Using the first two of {liveControllers.Count} controllers. ";

            float floor = _settings.FloorHeight;
            RigidPose head = mean[hmd];
            if (float.IsNaN(floor))
            {
                float lowest = float.MaxValue;
                foreach (int t in liveTrackers) lowest = Math.Min(lowest, mean[t].Position.Y);
                floor = lowest - _settings.FootTrackerHeight;
            }
            float eyeHeight = head.Position.Y - floor;

            // Trackers: runtime roles first; otherwise the pelvis is the one nearest hip height, the feet the two lowest.
            int pelvis = -1, footA = -1, footB = -1;
            int runtimeFeet = 0;
            foreach (int t in liveTrackers)
            {
                DeviceRole r = _devices[t].RuntimeRole;
                if (r == DeviceRole.Pelvis) { if (pelvis >= 0) return Fail(CalibrationError.RoleConflict, "two trackers are assigned the waist role"); pelvis = t; }
                if (r == DeviceRole.LeftFoot || r == DeviceRole.RightFoot) runtimeFeet++;
            }
            if (runtimeFeet > 2) return Fail(CalibrationError.RoleConflict, "more than two trackers are assigned a foot role");
            // Without runtime roles, each tracker is scored by how well it fits the body: height off the expected
            // one plus horizontal distance from the HMD (a spare tracker on a table or the floor nearby scores badly).
            float Away(int t) => Horizontal(mean[t].Position - head.Position).Length();
            if (pelvis < 0)
            {
                float best = float.MaxValue;
                foreach (int t in liveTrackers)
                {
                    float score = Math.Abs(mean[t].Position.Y - floor - 0.57f * eyeHeight) + Away(t);
                    if (mean[t].Position.Y - floor > 0.25f * eyeHeight && score < best) { best = score; pelvis = t; }
                }
                if (pelvis < 0) return Fail(CalibrationError.PelvisNotBetweenHeadAndFeet, "no tracker is at waist height");
            }
            // Trackers the runtime calls feet come first; then the lowest near the body.
            float FootScore(int t) => mean[t].Position.Y - floor + Away(t)
                - (_devices[t].RuntimeRole == DeviceRole.LeftFoot || _devices[t].RuntimeRole == DeviceRole.RightFoot ? 100f : 0f);
            foreach (int t in liveTrackers)
            {
                if (t == pelvis) continue;
                if (footA < 0 || FootScore(t) < FootScore(footA)) { footB = footA; footA = t; }
                else if (footB < 0 || FootScore(t) < FootScore(footB)) footB = t;
            }
            if (liveTrackers.Count > 3)
                Explanation += $"{liveTrackers.Count} trackers are tracked: the one nearest waist height under the head is the pelvis, the two lowest near the body are the feet; the others are ignored. ";
            int left = liveControllers[0], right = liveControllers[1];

            int[] used = { hmd, left, right, pelvis, footA, footB };
            foreach (int d in used)
                if (!still[d]) return Fail(CalibrationError.DevicesMoving, _devices[d].ToString());

            Vector3 up = Vector3.UnitY;
            Vector3 hmdUp = Vector3.Transform(up, head.Rotation);
            if (Vectors.AngleDegrees(hmdUp, up) > 25f) return Fail(CalibrationError.HeadNotUpright);
            Vector3 look = Vectors.ProjectOnPlane(Vector3.Transform(Vector3.UnitZ, head.Rotation), up);

            float spread = Horizontal(mean[left].Position - mean[right].Position).Length();
            if (spread < 0.7f * eyeHeight) return Fail(CalibrationError.ArmsNotSpread, $"hands {spread:0.00} m apart");

            Span<Vector3> points = stackalloc Vector3[6];
            for (int i = 0; i < used.Length; i++) points[i] = mean[used[i]].Position;
            BodyPlane plane = BodyPlane.Fit(points, look);
            Vector3 facing = Horizontal(plane.Normal);
            if (Math.Abs(plane.Normal.Y) > 0.35f || facing.LengthSquared() < 1e-6f || Vectors.AngleDegrees(facing, look) > 45f || plane.RmsDistance > 0.15f)
                return Fail(CalibrationError.NotFacingPlane);
            Vector3 forward = Vector3.Normalize(facing);
            Vector3 rightAxis = Vector3.Cross(up, forward);

            float X(int d) => Vector3.Dot(mean[d].Position - head.Position, rightAxis);
            if (X(left) > X(right)) (left, right) = (right, left);
            if (X(left) > 0f || X(right) < 0f) return Fail(CalibrationError.RoleConflict, "both controllers are on the same side");
            float pelvisX = X(pelvis);
            if (X(footA) - pelvisX > X(footB) - pelvisX) (footA, footB) = (footB, footA);
            if (X(footA) > X(footB) - 0.05f) return Fail(CalibrationError.RoleConflict, "both foot trackers are on the same side");

            _deviceByRole[(int)DeviceRole.Head] = hmd;
            _deviceByRole[(int)DeviceRole.LeftHand] = left;
            _deviceByRole[(int)DeviceRole.RightHand] = right;
            _deviceByRole[(int)DeviceRole.Pelvis] = pelvis;
            _deviceByRole[(int)DeviceRole.LeftFoot] = footA;
            _deviceByRole[(int)DeviceRole.RightFoot] = footB;
            foreach (DeviceRole role in BodyRoles.All)
            {
                DeviceRole runtime = _devices[_deviceByRole[(int)role]].RuntimeRole;
                if (runtime != DeviceRole.None && runtime != role)
                {
                    string detail = $"{_devices[_deviceByRole[(int)role]]} is worn as {role}";
                    ResetRoles();
                    return Fail(CalibrationError.RuntimeRoleMismatch, detail);
                }
            }

            float lh = mean[left].Position.Y - floor, rh = mean[right].Position.Y - floor;
            if (Math.Abs(lh - rh) > 0.15f || Math.Min(lh, rh) < 0.75f * eyeHeight || Math.Max(lh, rh) > 1.02f * eyeHeight)
            {
                ResetRoles();
                return Fail(CalibrationError.ArmsNotLevel, $"hands at {lh:0.00} m and {rh:0.00} m, eyes at {eyeHeight:0.00} m");
            }
            float feetTop = Math.Max(mean[footA].Position.Y, mean[footB].Position.Y);
            if (feetTop - floor > 0.3f) { ResetRoles(); return Fail(CalibrationError.FeetNotOnFloor, $"{feetTop - floor:0.00} m above the floor"); }
            float pelvisY = mean[pelvis].Position.Y;
            if (pelvisY < feetTop + 0.25f || pelvisY > head.Position.Y - 0.25f) { ResetRoles(); return Fail(CalibrationError.PelvisNotBetweenHeadAndFeet); }

            // Scale: the wearer's eye height over the avatar's.
            var unscaled = new SkeletonPose(_avatar.Skeleton);
            TPoser.Apply(_avatar, unscaled, RigidPose.Identity);
            float avatarEye = TPoser.EyePosition(_avatar, unscaled, Quaternion.Identity).Y;
            float scale = eyeHeight / avatarEye;

            // Placement: between the ankles (the foot trackers sit on the insteps), on the floor, facing the wearer's way.
            Vector3 feet = (mean[footA].Position + mean[footB].Position) * 0.5f - forward * _settings.FootTrackerForward;
            var placement = new RigidPose(new Vector3(feet.X, floor, feet.Z), Rotations.LookRotation(forward, up));

            Skeleton scaled = _avatar.Skeleton.Scaled(scale);
            ScaledAvatar = new HumanoidMap(scaled, _avatar.Pairs());
            AvatarPose = new SkeletonPose(scaled);
            TPoser.Apply(ScaledAvatar, AvatarPose, placement);

            Profile = new CalibrationProfile { AvatarScale = scale, WearerEyeHeight = eyeHeight, AvatarEyeHeight = avatarEye, FloorHeight = floor, Placement = placement };
            foreach (DeviceRole role in BodyRoles.All) Profile.SetDevice(role, _devices[_deviceByRole[(int)role]]);
            State = CalibrationState.WalkIn;
            LastError = CalibrationError.None;
            LastMessage = "Walk into the avatar, match its pose, and press a trigger again.";
            return true;
        }

        // ---- Step 2: exact offsets -----------------------------------------------------------------------

        private bool ComputeOffsets(double now)
        {
            var device = new RigidPose[7];
            foreach (DeviceRole role in BodyRoles.All)
            {
                int d = _deviceByRole[(int)role];
                if (!TryAverage(d, now, out device[(int)role], out bool still, out int fraction) || fraction < 80)
                    return Fail(CalibrationError.DeviceNotTracked, _devices[d].ToString());
                if (!still) return Fail(CalibrationError.DevicesMoving, _devices[d].ToString());
            }
            foreach (DeviceRole role in BodyRoles.All)
            {
                RigidPose joint = AvatarPose.World[ScaledAvatar[BodyRoles.JointOf(role)]];
                Profile.SetOffsets(role, device[(int)role], joint);
            }
            Profile.RootToHead = device[(int)DeviceRole.Head].Position - device[(int)DeviceRole.Pelvis].Position;
            State = CalibrationState.Calibrated;
            LastError = CalibrationError.None;
            LastMessage = CalibrationMessages.For(CalibrationError.None);
            return true;
        }

        private static Vector3 Horizontal(Vector3 v) => new Vector3(v.X, 0f, v.Z);
    }
}
