using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The outcome of calibration: which device plays each role, the avatar scale, and the paper's exact
    /// offsets. For the root, both feet, the head and both hands it stores the device pose
    /// <c>p0(T), R0(T)</c> and the avatar joint pose <c>p0(J), R0(J)</c> at the walk-in, and from them the
    /// joint's pose in the device frame, so that every frame
    /// <c>p_t(J) = p_t(T) + R_t(T) R0(T)^-1 v0(TJ)</c> and <c>R_t(J) = R_t(T) R0(T)^-1 R0(J)</c>
    /// (<see cref="JointInDevice"/>). Also the root-to-head vector <c>w0</c>.
    /// </summary>
    public sealed class CalibrationProfile
    {
        private readonly PerRole<int> _deviceIds = new PerRole<int>(-1);
        private readonly PerRole<string> _serials = new PerRole<string>(string.Empty);
        private readonly PerRole<RigidPose> _deviceAtCalibration = new PerRole<RigidPose>(RigidPose.Identity);
        private readonly PerRole<RigidPose> _jointAtCalibration = new PerRole<RigidPose>(RigidPose.Identity);
        private readonly PerRole<RigidPose> _jointInDevice = new PerRole<RigidPose>(RigidPose.Identity);

        /// <summary>
        /// The current format version of persisted profiles: 2 adds the scale mode, the proportions and the measurements
        /// (issue 15); version 1 files still load, as uniformly scaled profiles without measurements.
        /// </summary>
        public const int Version = 2;

        /// <summary>Creates an empty profile; <see cref="Calibrator"/> fills it.</summary>
        public CalibrationProfile() { }

        /// <summary>How the offsets were obtained.</summary>
        public OffsetMode Mode { get; private set; }

        /// <summary>
        /// The overall scale applied to the avatar: wearer eye height / avatar eye height when uniform; with fitted
        /// <see cref="Proportions"/>, the scale of the torso, head, hands and feet (the eye heights still match).
        /// </summary>
        public float AvatarScale { get; internal set; } = 1f;

        /// <summary>How the avatar was scaled: uniformly (the paper's) or with fitted proportions.</summary>
        public ScaleMode ScaleMode { get; internal set; }

        /// <summary>
        /// The avatar's legs and arms relative to <see cref="AvatarScale"/> (<see cref="BodyProportions.Uniform"/> for uniform
        /// scaling): the avatar the offsets were computed on is <c>Proportions.Apply(avatar, AvatarScale)</c>.
        /// </summary>
        public BodyProportions Proportions { get; internal set; } = BodyProportions.Uniform;

        /// <summary>The wearer's body measured at calibration, or null (a profile saved before measurements existed).</summary>
        public BodyMeasurements Measurements { get; internal set; }

        /// <summary>The wearer's eye height above the floor, in metres (from the HMD in T-pose).</summary>
        public float WearerEyeHeight { get; internal set; }

        /// <summary>The unscaled avatar's eye height, in metres.</summary>
        public float AvatarEyeHeight { get; internal set; }

        /// <summary>The floor height in tracking space.</summary>
        public float FloorHeight { get; internal set; }

        /// <summary>Where the avatar was shown: a floor point and a yaw (the wearer's facing at the T-pose).</summary>
        public RigidPose Placement { get; internal set; } = RigidPose.Identity;

        /// <summary><c>w0</c>: the vector from the pelvis tracker to the HMD at the walk-in (paper, eq. 1).</summary>
        public Vector3 RootToHead { get; internal set; }

        /// <summary>The id of the device playing <paramref name="role"/>, or -1.</summary>
        public int DeviceId(DeviceRole role) => _deviceIds[role];

        /// <summary>The serial of the device playing <paramref name="role"/> (to recognise it next time).</summary>
        public string Serial(DeviceRole role) => _serials[role];

        /// <summary><c>p0(T), R0(T)</c>: the device's pose at the walk-in.</summary>
        public RigidPose DeviceAtCalibration(DeviceRole role) => _deviceAtCalibration[role];

        /// <summary><c>p0(J), R0(J)</c>: the avatar joint's world pose at the walk-in.</summary>
        public RigidPose JointAtCalibration(DeviceRole role) => _jointAtCalibration[role];

        /// <summary>
        /// The joint's pose in the device frame: (<c>R0(T)^-1 v0(TJ)</c>, <c>R0(T)^-1 R0(J)</c>). The joint's world pose
        /// each frame is <c>devicePose * JointInDevice(role)</c>.
        /// </summary>
        public RigidPose JointInDevice(DeviceRole role) => _jointInDevice[role];

        internal void SetDevice(DeviceRole role, DeviceInfo device)
        {
            _deviceIds[role] = device.Id;
            _serials[role] = device.Serial;
        }

        internal void SetOffsets(DeviceRole role, RigidPose device, RigidPose joint)
        {
            _deviceAtCalibration[role] = device;
            _jointAtCalibration[role] = joint;
            _jointInDevice[role] = joint.RelativeTo(device);
        }

        /// <summary>
        /// The same calibration for the avatar uniformly rescaled to <paramref name="scale"/> (for example after the
        /// wearer chose another eye height): the avatar joints at the walk-in are scaled about the placement's floor
        /// point, and the offsets recomputed from them, so the avatar still stands on the floor where it stood and
        /// every device keeps its own measured pose. Rotation offsets do not change.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The scale is outside
        /// <see cref="CalibrationProfileStore.MinAvatarScale"/>…<see cref="CalibrationProfileStore.MaxAvatarScale"/>.</exception>
        public CalibrationProfile WithAvatarScale(float scale)
        {
            if (!(scale >= CalibrationProfileStore.MinAvatarScale && scale <= CalibrationProfileStore.MaxAvatarScale))
                throw new ArgumentOutOfRangeException(nameof(scale), scale, $"The scale must be from {CalibrationProfileStore.MinAvatarScale} to {CalibrationProfileStore.MaxAvatarScale}.");
            var p = new CalibrationProfile(this) { AvatarScale = scale };
            float ratio = scale / AvatarScale;
            Vector3 origin = Placement.Position;
            foreach (DeviceRole role in BodyRoles.All)
            {
                RigidPose joint = _jointAtCalibration[role];
                var moved = new RigidPose(origin + (joint.Position - origin) * ratio, joint.Rotation);
                p.SetOffsets(role, _deviceAtCalibration[role], moved);
            }
            if (Mode == OffsetMode.Fixed) return p.WithFixedOffsets();
            return p;
        }

        /// <summary>
        /// True when <paramref name="devices"/> contains a device with each role's serial (the same devices are worn),
        /// so this profile can be reused without calibrating again.
        /// </summary>
        public bool MatchesDevices(System.Collections.Generic.IReadOnlyList<DeviceInfo> devices) => MatchesDevices(devices, out _);

        /// <summary>
        /// As <see cref="MatchesDevices(System.Collections.Generic.IReadOnlyList{DeviceInfo})"/>, with why not: a role with no
        /// serial (the runtime gave none, as OpenXR often does: such a calibration cannot be matched to devices), two roles
        /// with one serial (they would land on one device), or a serial no connected device has.
        /// </summary>
        public bool MatchesDevices(System.Collections.Generic.IReadOnlyList<DeviceInfo> devices, out string reason)
        {
            reason = null;
            if (devices == null) { reason = "no devices"; return false; }
            foreach (DeviceRole role in BodyRoles.All)
            {
                string serial = _serials[role];
                if (string.IsNullOrEmpty(serial))
                {
                    reason = $"it holds no serial for the {role} device (the runtime gave none), so its devices cannot be recognised";
                    return false;
                }
                foreach (DeviceRole other in BodyRoles.All)
                    if (other != role && _serials[other] == serial)
                    {
                        reason = $"the {role} and {other} devices have the same serial '{serial}'";
                        return false;
                    }
                bool found = false;
                for (int i = 0; i < devices.Count && !found; i++) found = devices[i].Serial == serial;
                if (!found)
                {
                    reason = $"no connected device has the {role} device's serial '{serial}' (yet)";
                    return false;
                }
            }
            return true;
        }

        /// <summary>A copy whose device ids are those of this session's devices (matched when restoring by serial).</summary>
        internal CalibrationProfile WithDeviceIds(System.Collections.Generic.IReadOnlyList<DeviceInfo> devices, PerRole<int> deviceIndexByRole)
        {
            var p = new CalibrationProfile(this);
            foreach (DeviceRole role in BodyRoles.All) p.SetDevice(role, devices[deviceIndexByRole[role]]);
            return p;
        }

        /// <summary>
        /// A copy in which <paramref name="role"/>'s joint sits at <paramref name="jointInDevice"/> in its device's frame
        /// instead of the measured offset (the pipeline's palm-on-controller hands). Its walk-in poses are kept.
        /// </summary>
        internal CalibrationProfile WithJointInDevice(DeviceRole role, RigidPose jointInDevice)
        {
            var p = new CalibrationProfile(this);
            p._jointInDevice[role] = jointInDevice;
            return p;
        }

        /// <summary>
        /// A copy in which the devices of <paramref name="a"/> and <paramref name="b"/> trade roles (controllers found in
        /// the other hands, trackers on the other feet): each role keeps its offsets and walk-in poses, the devices' ids and
        /// serials swap.
        /// </summary>
        public CalibrationProfile WithSwappedDevices(DeviceRole a, DeviceRole b)
        {
            var p = new CalibrationProfile(this);
            p._deviceIds[a] = _deviceIds[b];
            p._deviceIds[b] = _deviceIds[a];
            p._serials[a] = _serials[b];
            p._serials[b] = _serials[a];
            return p;
        }

        /// <summary>
        /// A copy in which <paramref name="role"/>'s device was measured again: at <paramref name="device"/> while its joint
        /// was at <paramref name="joint"/> (a re-strapped tracker, <see cref="SelfAvatarPipeline.RecalibrateDevice"/>).
        /// </summary>
        public CalibrationProfile WithRemeasuredDevice(DeviceRole role, RigidPose device, RigidPose joint)
        {
            if (!device.IsValid || !joint.IsValid) throw new ArgumentException("The poses must be valid.");
            var p = new CalibrationProfile(this);
            p.SetOffsets(role, device, joint);
            return p.Mode == OffsetMode.Fixed ? p.WithFixedOffsets() : p;
        }

        /// <summary>Fixed-offset HMD → head joint translation in the HMD frame: 7 cm down and 9 cm back from the eyes (the inverse of <see cref="TPoser.HeadToEyes"/>).</summary>
        public static readonly Vector3 FixedHeadOffset = new Vector3(0f, -0.07f, -0.09f);

        /// <summary>Fixed-offset controller → wrist translation in the controller frame: the wrist 7 cm behind the grip.</summary>
        public static readonly Vector3 FixedWristOffset = new Vector3(0f, 0f, -0.07f);

        /// <summary>
        /// The paper's baseline on the same calibration: each tracker's position is taken as its joint's
        /// (pelvis tracker = hips, foot tracker = ankle), the head joint a constant <see cref="FixedHeadOffset"/>
        /// from the HMD and the wrist a constant <see cref="FixedWristOffset"/> behind the controller. Rotation
        /// offsets stay the measured ones: the paper's conditions differ in positions, and a baseline with
        /// wrong rotations would be a straw man.
        /// </summary>
        public CalibrationProfile WithFixedOffsets()
        {
            var p = new CalibrationProfile(this) { Mode = OffsetMode.Fixed };
            foreach (DeviceRole role in BodyRoles.All)
            {
                Vector3 position = role == DeviceRole.Head ? FixedHeadOffset
                    : role == DeviceRole.LeftHand || role == DeviceRole.RightHand ? FixedWristOffset
                    : Vector3.Zero;
                p._jointInDevice[role] = new RigidPose(position, _jointInDevice[role].Rotation);
            }
            return p;
        }

        private CalibrationProfile(CalibrationProfile other)
        {
            _deviceIds.CopyFrom(other._deviceIds);
            _serials.CopyFrom(other._serials);
            _deviceAtCalibration.CopyFrom(other._deviceAtCalibration);
            _jointAtCalibration.CopyFrom(other._jointAtCalibration);
            _jointInDevice.CopyFrom(other._jointInDevice);
            Mode = other.Mode;
            AvatarScale = other.AvatarScale;
            WearerEyeHeight = other.WearerEyeHeight;
            AvatarEyeHeight = other.AvatarEyeHeight;
            FloorHeight = other.FloorHeight;
            Placement = other.Placement;
            RootToHead = other.RootToHead;
            ScaleMode = other.ScaleMode;
            Proportions = other.Proportions;
            Measurements = other.Measurements;
        }
    }
}
