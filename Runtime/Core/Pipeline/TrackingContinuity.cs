using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Keeps the avatar whole while devices come and go. For a device that is lost (or was rejected by
    /// <see cref="SampleSanitizer"/>), its joint first holds its last pose relative to the body
    /// (<see cref="TrackingSettings.HoldSeconds"/>), then eases (<see cref="TrackingSettings.EaseSeconds"/>) to a plausible
    /// pose derived from the others: a lost foot settles under the hips on the floor, a lost hand hangs from its shoulder,
    /// a lost pelvis follows the head and the feet. When the device comes back, the difference between where its joint was
    /// shown and where the device puts it decays (<see cref="TrackingSettings.RecoveryTimeConstant"/>, never faster than
    /// <see cref="TrackingSettings.RecoveryMaxSpeed"/>): nothing snaps. The result is a full set of samples the body's
    /// target mapping can use as they are. Without the HMD nothing is plausible: <see cref="Apply"/> then says to freeze.
    /// Time-based, so the same at any frame rate; allocation-free per frame.
    /// </summary>
    public sealed class TrackingContinuity
    {
        private readonly TrackingSettings _settings;
        private readonly PerRole<int> _device = new PerRole<int>(-1);
        private readonly PerRole<RigidPose> _jointInDevice = new PerRole<RigidPose>();
        private readonly PerRole<RigidPose> _deviceInJoint = new PerRole<RigidPose>();
        private readonly PerRole<RigidPose> _joint0 = new PerRole<RigidPose>();     // each role's joint at calibration
        private readonly PerRole<RoleState> _state = new PerRole<RoleState>();
        private readonly Quaternion _yaw0;
        private readonly Vector3 _hipsForwardLocal, _headForwardLocal;
        private readonly int _leftShoulder, _rightShoulder;
        private readonly float _leftArm, _rightArm;
        private readonly Quaternion _leftHang, _rightHang;
        private double _lastTime = double.NaN;
        private bool _frozen;   // the last frame had no HMD
        private static readonly DeviceRole[] Limbs = { DeviceRole.LeftFoot, DeviceRole.RightFoot, DeviceRole.LeftHand, DeviceRole.RightHand };

        private sealed class RoleState
        {
            public bool Lost, Recovering, BlendNext;
            public double LostSince;
            public RigidPose HeldLocal;      // the joint relative to its reference when it was lost
            public RigidPose Shown;          // the joint pose fed last frame
            public Vector3 OffsetPosition;   // recovery: shown minus tracked
            public Quaternion OffsetRotation = Quaternion.Identity;
            public Vector3 FromFeet, FromHead;  // the pelvis at its loss, from the feet and from the head, in the head's yaw frame
            public Quaternion InHeadYaw;        // and its rotation in that frame
        }

        /// <summary>
        /// Prepares for a calibration: <paramref name="profile"/>'s offsets, which device plays each role, and the avatar
        /// in its calibration pose (the references of the plausible poses).
        /// </summary>
        public TrackingContinuity(CalibrationProfile profile, PerRole<int> deviceOfRole, HumanoidMap avatar, SkeletonPose calibrationPose, TrackingSettings settings)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            if (deviceOfRole == null) throw new ArgumentNullException(nameof(deviceOfRole));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            if (calibrationPose == null) throw new ArgumentNullException(nameof(calibrationPose));
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            RigidPose[] w = calibrationPose.World;
            foreach (DeviceRole role in BodyRoles.All)
            {
                _device[role] = deviceOfRole[role];
                _jointInDevice[role] = profile.JointInDevice(role);
                _deviceInJoint[role] = _jointInDevice[role].Inverse();
                _joint0[role] = w[avatar[BodyRoles.JointOf(role)]];
                _state[role] = new RoleState { Shown = _joint0[role] };
            }
            Vector3 forward = Vector3.Transform(Vector3.UnitZ, profile.Placement.Rotation);
            _yaw0 = Yaw(forward);
            _hipsForwardLocal = Vector3.Transform(forward, Quaternion.Conjugate(_joint0[DeviceRole.Pelvis].Rotation));
            _headForwardLocal = Vector3.Transform(forward, Quaternion.Conjugate(_joint0[DeviceRole.Head].Rotation));
            _leftShoulder = avatar[HumanoidBone.LeftUpperArm];
            _rightShoulder = avatar[HumanoidBone.RightUpperArm];
            _leftArm = ArmLength(avatar, w, BodySide.Left);
            _rightArm = ArmLength(avatar, w, BodySide.Right);
            _leftHang = Rotations.FromTo(_joint0[DeviceRole.LeftHand].Position - w[_leftShoulder].Position, -Vector3.UnitY);
            _rightHang = Rotations.FromTo(_joint0[DeviceRole.RightHand].Position - w[_rightShoulder].Position, -Vector3.UnitY);
        }

        /// <summary>True when <paramref name="role"/>'s device was tracked (and accepted) in the last frame.</summary>
        public bool IsTracked(DeviceRole role) => !_state[role].Lost;

        /// <summary>True while <paramref name="role"/>'s joint is being blended back onto its device after a loss.</summary>
        public bool IsRecovering(DeviceRole role) => _state[role].Recovering;

        /// <summary>
        /// Continues from the avatar's current pose: every part is blended, as after a loss, from where
        /// <paramref name="pose"/> shows it to where its device puts it (after the devices' roles or offsets changed).
        /// </summary>
        public void StartFrom(SkeletonPose pose, HumanoidMap avatar)
        {
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            foreach (DeviceRole role in BodyRoles.All)
            {
                RoleState s = _state[role];
                s.Shown = pose.World[avatar[BodyRoles.JointOf(role)]];
                s.Lost = s.Recovering = false;
                s.BlendNext = true;
            }
        }

        /// <summary>Forgets every loss (after a calibration): every joint as at the calibration.</summary>
        public void Clear()
        {
            foreach (DeviceRole role in BodyRoles.All)
            {
                RoleState s = _state[role];
                s.Lost = s.Recovering = s.BlendNext = false;
                s.Shown = _joint0[role];
            }
            _lastTime = double.NaN;
            _frozen = false;
        }

        /// <summary>
        /// Fills <paramref name="effective"/> with a tracked sample for every role's device: the accepted one (blended back
        /// after a loss) or the eased plausible one. Other devices are copied. Returns false, leaving the output a copy of the
        /// input, when the HMD is lost: the avatar should keep its last pose. <paramref name="lastSolved"/> is the avatar's
        /// last solved pose (for the shoulders). Allocation-free.
        /// <paramref name="time"/> (seconds) must not go back and should advance by frame-sized steps: the speeds and
        /// durations are measured between calls. <see cref="SelfAvatarPipeline"/> passes its own clock, which does that
        /// whatever the frames' times do.
        /// </summary>
        public bool Apply(double time, ReadOnlySpan<DeviceSample> accepted, SkeletonPose lastSolved, Span<DeviceSample> effective)
        {
            if (lastSolved == null) throw new ArgumentNullException(nameof(lastSolved));
            accepted.CopyTo(effective);
            float dt = !double.IsNaN(_lastTime) && time > _lastTime ? (float)Math.Min(time - _lastTime, 0.25) : 0f;
            _lastTime = time;
            if (!accepted[_device[DeviceRole.Head]].IsTracked)
            {
                // Nothing to place the body by: freeze, and let every part come back blended once the HMD does.
                foreach (DeviceRole role in BodyRoles.All) MarkLost(role, time, ReferenceOf(role));
                _frozen = true;
                return false;
            }
            RigidPose head = Follow(DeviceRole.Head, time, dt, accepted, RigidPose.Identity, effective, lastSolved);
            RigidPose hips = Follow(DeviceRole.Pelvis, time, dt, accepted, head, effective, lastSolved);
            foreach (DeviceRole role in Limbs) Follow(role, time, dt, accepted, hips, effective, lastSolved);
            _frozen = false;
            return true;
        }

        // One role: its joint pose this frame (tracked, blended back, held or eased), written to effective as a device sample.
        // Its reference is the joint it is held relative to and placed from when lost: the head for the pelvis, the hips
        // for the feet and hands.
        private RigidPose Follow(DeviceRole role, double time, float dt, ReadOnlySpan<DeviceSample> accepted, RigidPose reference,
            Span<DeviceSample> effective, SkeletonPose lastSolved)
        {
            RoleState s = _state[role];
            int device = _device[role];
            RigidPose joint;
            if (accepted[device].IsTracked)
            {
                joint = accepted[device].Pose * _jointInDevice[role];
                if (s.Lost || s.BlendNext)
                {
                    s.Lost = s.BlendNext = false;
                    s.Recovering = true;
                    s.OffsetPosition = s.Shown.Position - joint.Position;
                    s.OffsetRotation = Quaternion.Normalize(s.Shown.Rotation * Quaternion.Conjugate(joint.Rotation));
                }
                if (s.Recovering)
                {
                    Decay(s, dt);
                    joint = new RigidPose(joint.Position + s.OffsetPosition, Quaternion.Normalize(s.OffsetRotation * joint.Rotation));
                }
            }
            else
            {
                // Back from a freeze still lost: hold and ease again from where it was shown, not from where the easing
                // would have reached meanwhile.
                if (_frozen) s.Lost = false;
                MarkLost(role, time, reference);
                RigidPose held = reference * s.HeldLocal;
                float u = Smooth((float)((time - s.LostSince - _settings.HoldSeconds) / Math.Max(_settings.EaseSeconds, 1e-3f)));
                joint = u > 0f ? RigidPose.Lerp(held, Plausible(role, reference, accepted, lastSolved), u) : held;
            }
            s.Shown = joint;
            effective[device] = new DeviceSample(joint * _deviceInJoint[role], true);
            return joint;
        }

        // The first frame of a loss: the joint is held, from now on, where it was last shown relative to its reference.
        private void MarkLost(DeviceRole role, double time, RigidPose reference)
        {
            RoleState s = _state[role];
            if (s.Lost) return;
            s.Lost = true;
            s.Recovering = s.BlendNext = false;
            s.LostSince = time;
            s.HeldLocal = s.Shown.RelativeTo(reference);
            if (role == DeviceRole.Pelvis)
            {
                Quaternion unyaw = Quaternion.Conjugate(Yaw(Vector3.Transform(_headForwardLocal, reference.Rotation)));
                Vector3 feet = (_state[DeviceRole.LeftFoot].Shown.Position + _state[DeviceRole.RightFoot].Shown.Position) * 0.5f;
                s.FromFeet = Vector3.Transform(s.Shown.Position - feet, unyaw);
                s.FromHead = Vector3.Transform(s.Shown.Position - reference.Position, unyaw);
                s.InHeadYaw = Quaternion.Normalize(unyaw * s.Shown.Rotation);
            }
        }

        private RigidPose ReferenceOf(DeviceRole role) =>
            role == DeviceRole.Head ? RigidPose.Identity : role == DeviceRole.Pelvis ? _state[DeviceRole.Head].Shown : _state[DeviceRole.Pelvis].Shown;

        // Where a lost part plausibly is, from the others (its reference: the head for the pelvis, the hips otherwise): in the
        // body's frame now, as it was in the calibration pose.
        private RigidPose Plausible(DeviceRole role, RigidPose reference, ReadOnlySpan<DeviceSample> accepted, SkeletonPose lastSolved)
        {
            if (role == DeviceRole.Pelvis)
            {
                // Where it was, at the loss, relative to the head and relative to the feet (as last shown: tracked, recovering
                // or eased, so this never switches), half each, turned with the head: a crouch after the loss brings the
                // hips halfway down with the head, a forward bend leaves them halfway over the feet. (Compared with a pose
                // from the calibration's T-pose and with holding relative to the head alone: Documentation~/solver.md.)
                RigidPose head = reference;
                RoleState pelvis = _state[DeviceRole.Pelvis];
                Quaternion yaw = Yaw(Vector3.Transform(_headForwardLocal, head.Rotation));
                Vector3 feet = (_state[DeviceRole.LeftFoot].Shown.Position + _state[DeviceRole.RightFoot].Shown.Position) * 0.5f;
                Vector3 p = 0.5f * (feet + Vector3.Transform(pelvis.FromFeet, yaw)) + 0.5f * (head.Position + Vector3.Transform(pelvis.FromHead, yaw));
                return new RigidPose(p, Quaternion.Normalize(yaw * pelvis.InHeadYaw));
            }
            RigidPose hips = reference;
            Quaternion bodyTurn = Yaw(Vector3.Transform(_hipsForwardLocal, hips.Rotation)) * Quaternion.Conjugate(_yaw0);
            if (role == DeviceRole.LeftFoot || role == DeviceRole.RightFoot)
            {
                // Under the hips, where it stood at the calibration, on the floor.
                Vector3 p = hips.Position + Vector3.Transform(_joint0[role].Position - _joint0[DeviceRole.Pelvis].Position, bodyTurn);
                p.Y = _joint0[role].Position.Y; // the ankle's height when standing
                return new RigidPose(p, Quaternion.Normalize(bodyTurn * _joint0[role].Rotation));
            }
            // A hand hangs from its shoulder (where the last frame put it), the arm straight down, turned with the body.
            bool leftHand = role == DeviceRole.LeftHand;
            Vector3 shoulder = lastSolved.World[leftHand ? _leftShoulder : _rightShoulder].Position;
            Vector3 wrist = shoulder - Vector3.UnitY * (0.97f * (leftHand ? _leftArm : _rightArm));
            return new RigidPose(wrist, Quaternion.Normalize(bodyTurn * (leftHand ? _leftHang : _rightHang) * _joint0[role].Rotation));
        }

        private void Decay(RoleState s, float dt)
        {
            // In no time nothing moves (and an infinite speed limit times 0 would be NaN).
            if (!(dt > 0f)) return;
            float keep = (float)Math.Exp(-dt / Math.Max(_settings.RecoveryTimeConstant, 1e-4f));
            float d = s.OffsetPosition.Length();
            float next = Math.Max(d * keep, d - _settings.RecoveryMaxSpeed * dt);
            s.OffsetPosition = d > 1e-9f ? s.OffsetPosition * (next / d) : Vector3.Zero;
            float angle = Rotations.AngleDegrees(Quaternion.Identity, s.OffsetRotation);
            float nextAngle = Math.Max(angle * keep, angle - _settings.RecoveryMaxAngularSpeedDegrees * dt);
            s.OffsetRotation = angle > 1e-6f ? Quaternion.Slerp(Quaternion.Identity, s.OffsetRotation, nextAngle / angle) : Quaternion.Identity;
            if (next < 1e-4f && nextAngle < 0.05f)
            {
                s.Recovering = false;
                s.OffsetPosition = Vector3.Zero;
                s.OffsetRotation = Quaternion.Identity;
            }
        }

        private static float ArmLength(HumanoidMap avatar, RigidPose[] w, BodySide side)
        {
            Vector3 shoulder = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side)]].Position;
            Vector3 elbow = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side)]].Position;
            Vector3 wrist = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]].Position;
            return Vector3.Distance(shoulder, elbow) + Vector3.Distance(elbow, wrist);
        }

        // The rotation about +Y that faces +Z along the horizontal part of forward.
        private static Quaternion Yaw(Vector3 forward) => Rotations.LookRotation(new Vector3(forward.X, 0f, forward.Z), Vector3.UnitY);

        private static float Smooth(float t)
        {
            t = t < 0f ? 0f : t > 1f ? 1f : t;
            return t * t * (3f - 2f * t);
        }
    }
}
