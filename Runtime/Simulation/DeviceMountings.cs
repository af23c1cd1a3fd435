using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Where each of the six devices sits on the body: per role, the device pose relative to its joint,
    /// expressed in the body frame of the canonical T-pose (x right, y up, z forward; see <see cref="TPoser"/>).
    /// The HMD's reference point is the eyes (the runtime reports the centre-eye pose), the controllers' the
    /// wrist, the pelvis tracker's the hips joint, the foot trackers' the ankles.
    /// </summary>
    /// <remarks>
    /// Defaults (a 1.75 m adult): HMD at the centre eye; controller grip centre 7 cm along the hand from the
    /// wrist and 4 cm below the palm line (inside the closed fist); pelvis tracker on the lower back, 12 cm
    /// behind and 3 cm above the hips joint (belt strap over the sacrum); foot trackers on the instep, 8 cm in
    /// front of and 2 cm above the ankle joint. <see cref="Sample"/> varies each position by up to ±2 cm
    /// (±3 mm for the HMD, whose optics fix it to the eyes) and draws every device rotation uniformly
    /// (the HMD: within ±5° of level), because a strap never sits twice in the same place.
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
            m[DeviceRole.LeftHand] = RigidPose.FromPosition(new Vector3(-0.07f, -0.04f, 0f));
            m[DeviceRole.RightHand] = RigidPose.FromPosition(new Vector3(0.07f, -0.04f, 0f));
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
                bool hmd = role == DeviceRole.Head;
                float range = hmd ? 0.003f : 0.02f;
                Vector3 p = m[role].Position + new Vector3(Uniform(rng, range), Uniform(rng, range), Uniform(rng, range));
                Quaternion q = hmd
                    ? Rotations.AngleAxis(Uniform(rng, 5f), Vector3.UnitX) * Rotations.AngleAxis(Uniform(rng, 5f), Vector3.UnitZ)
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
