using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Where each of the six devices sits on the body. For the HMD and the trackers: the device pose relative to its
    /// joint, expressed in the body frame of the canonical T-pose (x right, y up, z forward; see <see cref="TPoser"/>);
    /// the HMD's reference point is the eyes (the runtime reports the centre-eye pose), the pelvis tracker's the hips
    /// joint, the foot trackers' the ankles. For the controllers: the controller's pose relative to where a hand holds it
    /// (<see cref="HandModel.GripPose"/>: the handle across the palm, the palm centre on the grip), in that grip's frame.
    /// </summary>
    /// <remarks>
    /// Defaults (a 1.75 m adult): HMD at the centre eye; controllers held in the palm; pelvis tracker on the lower back,
    /// 12 cm behind and 3 cm above the hips joint (belt strap over the sacrum); foot trackers on the instep, 8 cm in
    /// front of and 2 cm above the ankle joint. <see cref="Sample"/> varies each tracker's position by up to ±2 cm
    /// (±3 mm for the HMD, whose optics fix it to the eyes) and draws its rotation uniformly (the HMD: within ±5° of
    /// pitch and, separately, of roll, so up to about 7° from level), because a strap never sits twice in the same place; a controller's grip varies by up to ±4 mm and ±4° about each axis: its
    /// shape decides how it is held (the handle in the palm's crease, the index on the trigger), so people and holds differ
    /// by millimetres and degrees, not centimetres (an assumption, not a measurement).
    /// </remarks>
    public sealed class DeviceMountings
    {
        private readonly RigidPose[] _byRole = new RigidPose[7];

        /// <summary>The mounting of a role's device, in the T-pose body frame relative to its joint.</summary>
        public RigidPose this[DeviceRole role]
        {
            get => _byRole[(int)role];
            set
            {
                if (!value.IsValid) throw new ArgumentException("A mounting must be a valid pose.", nameof(value));
                _byRole[(int)role] = value;
            }
        }

        /// <summary>The default mounting (no randomness): every device level and facing forward.</summary>
        public static DeviceMountings Default()
        {
            var m = new DeviceMountings();
            m[DeviceRole.Head] = RigidPose.Identity;
            m[DeviceRole.LeftHand] = RigidPose.Identity;
            m[DeviceRole.RightHand] = RigidPose.Identity;
            m[DeviceRole.Pelvis] = RigidPose.FromPosition(new Vector3(0f, 0.03f, -0.12f));
            m[DeviceRole.LeftFoot] = RigidPose.FromPosition(new Vector3(0f, 0.02f, 0.08f));
            m[DeviceRole.RightFoot] = RigidPose.FromPosition(new Vector3(0f, 0.02f, 0.08f));
            return m;
        }

        /// <summary>A mounting drawn at random around <see cref="Default"/> (ranges in the remarks).</summary>
        public static DeviceMountings Sample(Random rng)
        {
            if (rng == null) throw new ArgumentNullException(nameof(rng));
            DeviceMountings m = Default();
            foreach (DeviceRole role in BodyRoles.All)
            {
                bool hmd = role == DeviceRole.Head, hand = role == DeviceRole.LeftHand || role == DeviceRole.RightHand;
                float range = hmd ? 0.003f : hand ? 0.004f : 0.02f;
                Vector3 p = m[role].Position + new Vector3(Uniform(rng, range), Uniform(rng, range), Uniform(rng, range));
                Quaternion q = hmd
                    ? Rotations.AngleAxis(Uniform(rng, 5f), Vector3.UnitX) * Rotations.AngleAxis(Uniform(rng, 5f), Vector3.UnitZ)
                    : hand
                        ? Rotations.AngleAxis(Uniform(rng, 4f), Vector3.UnitX) * Rotations.AngleAxis(Uniform(rng, 4f), Vector3.UnitY) * Rotations.AngleAxis(Uniform(rng, 4f), Vector3.UnitZ)
                        : UniformRotation(rng);
                m[role] = new RigidPose(p, q);
            }
            return m;
        }

        private static float Uniform(Random rng, float halfRange) => (float)((rng.NextDouble() * 2 - 1) * halfRange);

        /// <summary>A rotation drawn uniformly over all orientations (Shoemake's method).</summary>
        public static Quaternion UniformRotation(Random rng)
        {
            double u1 = rng.NextDouble(), u2 = rng.NextDouble() * 2 * Math.PI, u3 = rng.NextDouble() * 2 * Math.PI;
            double a = Math.Sqrt(1 - u1), b = Math.Sqrt(u1);
            return Quaternion.Normalize(new Quaternion((float)(a * Math.Sin(u2)), (float)(a * Math.Cos(u2)), (float)(b * Math.Sin(u3)), (float)(b * Math.Cos(u3))));
        }
    }
}
