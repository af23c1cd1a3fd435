using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// One hand of an avatar for finger IK: per finger (thumb, index, middle, ring, little) its three joints, their
    /// open rotations (the rig's rest pose) and closed rotations, and a fingertip point. Each joint closes about an
    /// axis found from the hand's geometry, so any rig works whatever local axis its bones bend about: a finger bends
    /// about the finger's direction crossed with the palm normal; the thumb's two outer joints bend toward the little
    /// finger's base (the thumb's own flexion, which curls it across the palm); and the thumb's first joint has two
    /// parameters, like Unity's humanoid muscles (Thumb 1 Stretched and Thumb Spread): it turns toward the palm normal
    /// and, separately, lifts the thumb radially (toward the thumb side, over the top of a controller).
    /// Joint <c>j</c> of finger <c>f</c> has a parameter <c>t</c> in [0, 1] blending its open rotation to its closed one
    /// (the paper's <c>t_f^j</c>), stored at <c>f * 3 + j</c>; the thumb's spread is parameter <see cref="ThumbSpreadIndex"/>.
    /// </summary>
    public sealed class HandModel
    {
        /// <summary>The number of joint parameters of a hand: five fingers of three joints, plus the thumb's spread.</summary>
        public const int ParameterCount = 16;

        /// <summary>The index of the thumb's second parameter at its first joint (radial spread), after the 15 joint parameters.</summary>
        public const int ThumbSpreadIndex = 15;

        /// <summary>How far the thumb's first joint spreads (lifts radially) at a spread parameter of 1, in degrees.</summary>
        public const float ThumbSpreadDegrees = 60f;

        // How far each joint closes at t = 1, in degrees: proximal, intermediate, distal.
        private static readonly float[] FingerClosing = { 80f, 100f, 70f };
        private static readonly float[] ThumbClosing = { 40f, 50f, 70f };

        /// <summary>
        /// How far joint <paramref name="joint"/> (0 proximal, 1 intermediate, 2 distal) of finger <paramref name="finger"/>
        /// (0 thumb … 4 little) closes at t = 1, in degrees: fingers 80, 100, 70; thumb 40, 50, 70.
        /// </summary>
        public static float ClosingDegrees(int finger, int joint) => (finger == 0 ? ThumbClosing : FingerClosing)[joint];

        /// <summary>
        /// Where the handle crosses the palm, as a fraction of the way from the wrist to the middle knuckle (0.8: at the
        /// distal palm crease, where a power grip holds a handle).
        /// </summary>
        public const float GripAlongPalm = 0.8f;

        internal readonly int[,] Joints = new int[5, 3];
        internal readonly RigidPose[,] RestRelative = new RigidPose[5, 3];   // joint 0 relative to the hand, others to their parent joint
        internal readonly Vector3[,] AxisLocal = new Vector3[5, 3];
        internal readonly float[,] MaxRadians = new float[5, 3];
        internal readonly Vector3[] TipLocal = new Vector3[5];
        internal readonly bool[] HasFinger = new bool[5];
        internal Vector3 ThumbSpreadAxisLocal;   // in the thumb's first joint's rest frame
        internal float ThumbSpreadRadians;

        /// <summary>Builds the model of the left or right hand of <paramref name="map"/>'s rig from its rest pose.</summary>
        /// <exception cref="ArgumentException">The rig has no hand bone on that side, no index, middle or little finger base, or
        /// no complete index or middle finger.</exception>
        public HandModel(HumanoidMap map, bool left)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            Map = map;
            IsLeft = left;
            Skeleton s = map.Skeleton;
            HandJoint = map[left ? HumanoidBone.LeftHand : HumanoidBone.RightHand];
            if (HandJoint < 0) throw new ArgumentException("The rig has no hand bone on that side.", nameof(map));
            var rest = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            s.GetRestLocal(rest);
            s.ComputeWorld(rest, world);
            RigidPose hand = world[HandJoint];

            int index = map[HumanoidBones.Finger(left, 1, 0)], little = map[HumanoidBones.Finger(left, 4, 0)], middle = map[HumanoidBones.Finger(left, 2, 0)];
            if (index < 0 || little < 0 || middle < 0) throw new ArgumentException("The hand needs index, middle and little fingers.", nameof(map));
            Vector3 along = Vector3.Normalize(world[middle].Position - hand.Position);
            Vector3 across = Vector3.Normalize(world[index].Position - world[little].Position);
            // Palm normal from geometry: for a right hand, (finger direction × little-to-index) points out of the palm;
            // a left hand is its mirror image.
            Vector3 palm = Vector3.Normalize(left ? Vector3.Cross(across, along) : Vector3.Cross(along, across));
            PalmNormalInHand = Vector3.Transform(palm, Quaternion.Conjugate(hand.Rotation));
            AcrossInHand = Vector3.Transform(across, Quaternion.Conjugate(hand.Rotation));
            AlongInHand = Vector3.Transform(along, Quaternion.Conjugate(hand.Rotation));
            float handLength = Vector3.Distance(hand.Position, world[middle].Position);
            FingerRadius = 0.0085f * handLength / 0.095f;
            PalmCentreInHand = hand.InverseTransformPoint(hand.Position + (world[middle].Position - hand.Position) * GripAlongPalm + palm * FingerRadius);

            for (int f = 0; f < 5; f++)
            {
                int j0 = map[HumanoidBones.Finger(left, f, 0)], j1 = map[HumanoidBones.Finger(left, f, 1)], j2 = map[HumanoidBones.Finger(left, f, 2)];
                if (j0 < 0 || j1 < 0 || j2 < 0) continue;
                HasFinger[f] = true;
                Joints[f, 0] = j0; Joints[f, 1] = j1; Joints[f, 2] = j2;
                RestRelative[f, 0] = world[j0].RelativeTo(hand);
                RestRelative[f, 1] = world[j1].RelativeTo(world[j0]);
                RestRelative[f, 2] = world[j2].RelativeTo(world[j1]);
                TipLocal[f] = TipOf(s, world, j1, j2);
                Vector3 direction = Vector3.Normalize(world[j2].Position - world[j0].Position);
                Vector3 axis = Vectors.NormalizeOr(Vector3.Cross(direction, palm), Vector3.Cross(along, palm));
                int[] joints = { j0, j1, j2 };
                for (int k = 0; k < 3; k++)
                {
                    Vector3 jointAxis = axis;
                    if (f == 0 && k > 0)
                    {
                        // The thumb's outer joints curl it toward the little finger's base (flexion of a thumb that
                        // faces the fingers), not straight into the palm.
                        Vector3 toLittle = world[little].Position - world[j0].Position;
                        jointAxis = Vectors.NormalizeOr(Vector3.Cross(direction, toLittle - direction * Vector3.Dot(toLittle, direction)), axis);
                    }
                    AxisLocal[f, k] = Vector3.Transform(jointAxis, Quaternion.Conjugate(world[joints[k]].Rotation));
                    MaxRadians[f, k] = ClosingDegrees(f, k) * Rotations.Deg2Rad;
                }
                if (f == 0)
                {
                    // Spread: turns the thumb toward the radial side (little-to-index, continued past the index).
                    // A thumb laid along little-to-index (no rig seen does this) has no radial direction to lift
                    // toward: it then spreads in the palm's plane, about the palm normal.
                    Vector3 radial = Vector3.Cross(direction, across);
                    Vector3 spread = radial.LengthSquared() > 0.01f ? Vector3.Normalize(radial) : palm;
                    ThumbSpreadAxisLocal = Vector3.Transform(spread, Quaternion.Conjugate(world[j0].Rotation));
                    ThumbSpreadRadians = ThumbSpreadDegrees * Rotations.Deg2Rad;
                }
            }
            if (!HasFinger[1] || !HasFinger[2]) throw new ArgumentException("The hand needs complete index and middle fingers.", nameof(map));
        }

        /// <summary>The rig.</summary>
        public HumanoidMap Map { get; }

        /// <summary>True for the left hand.</summary>
        public bool IsLeft { get; }

        /// <summary>The hand (wrist) joint.</summary>
        public int HandJoint { get; }

        /// <summary>Whether finger <paramref name="finger"/> (0 thumb … 4 little) has all three joints.</summary>
        public bool Has(int finger) => HasFinger[finger];

        /// <summary>The radius of a finger (for contact): 8.5 mm for a hand 9.5 cm from wrist to middle knuckle, scaled.</summary>
        public float FingerRadius { get; }

        /// <summary>The palm centre (on the skin of the palm) in the hand joint's frame.</summary>
        public Vector3 PalmCentreInHand { get; }

        /// <summary>The unit normal out of the palm, in the hand joint's frame.</summary>
        public Vector3 PalmNormalInHand { get; }

        /// <summary>The unit direction across the palm from the little finger to the index, in the hand joint's frame.</summary>
        public Vector3 AcrossInHand { get; }

        /// <summary>The unit direction from the wrist toward the middle finger, in the hand joint's frame.</summary>
        public Vector3 AlongInHand { get; }

        /// <summary>
        /// Where a controller sits in the hand joint's frame when held: its handle axis (+Y) across the palm toward
        /// the index, its trigger side (+Z) away from the palm, its origin one handle radius plus a finger radius
        /// off the palm centre — the palm centre on the grip.
        /// </summary>
        public RigidPose ControllerInHand(ControllerProfile profile)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            float radius = -profile.Shape.Distance(Vector3.Zero);
            Vector3 up = AcrossInHand;
            Vector3 forward = Vector3.Normalize(Vectors.ProjectOnPlane(PalmNormalInHand, up));
            Vector3 origin = PalmCentreInHand + PalmNormalInHand * (radius + 0.002f);
            return new RigidPose(origin, Rotations.LookRotation(forward, up));
        }

        /// <summary>
        /// The inverse of <see cref="ControllerInHand"/>: where the hand (wrist) joint sits in the controller's frame when
        /// it holds <paramref name="profile"/>. A tracked controller pose <c>c</c> puts the avatar's wrist at
        /// <c>c * WristInController(profile)</c> (what calibration needs to place the wrist on the controller).
        /// </summary>
        public RigidPose WristInController(ControllerProfile profile) => ControllerInHand(profile).Inverse();

        /// <summary>
        /// Sets the finger joints of <paramref name="pose"/> from the <see cref="ParameterCount"/> parameters
        /// <paramref name="t"/> (finger-major, then the thumb's spread), each clamped to [0, 1].
        /// </summary>
        /// <exception cref="ArgumentException">Fewer than <see cref="ParameterCount"/> parameters.</exception>
        public void Apply(ReadOnlySpan<float> t, SkeletonPose pose)
        {
            if (t.Length < ParameterCount) throw new ArgumentException($"{ParameterCount} parameters (5 fingers × 3 joints, and the thumb's spread) are needed.", nameof(t));
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            for (int f = 0; f < 5; f++)
            {
                if (!HasFinger[f]) continue;
                for (int k = 0; k < 3; k++)
                {
                    int j = Joints[f, k];
                    RigidPose rest = pose.Skeleton.GetRestLocal(j);
                    pose.Local[j] = new RigidPose(rest.Position, Quaternion.Normalize(rest.Rotation * Bend(f, k, t[f * 3 + k], f == 0 && k == 0 ? t[ThumbSpreadIndex] : 0f)));
                }
            }
        }

        // The rotation of joint k of finger f relative to its rest rotation. The thumb's first joint spreads first
        // (about an axis fixed in its rest frame), then flexes about its flexion axis carried by the spread.
        internal Quaternion Bend(int f, int k, float t, float spread)
        {
            Quaternion bend = Quaternion.CreateFromAxisAngle(AxisLocal[f, k], Clamp01(t) * MaxRadians[f, k]);
            if (f != 0 || k != 0) return bend;
            return Quaternion.CreateFromAxisAngle(ThumbSpreadAxisLocal, Clamp01(spread) * ThumbSpreadRadians) * bend;
        }

        private static float Clamp01(float v) => v > 0f ? (v < 1f ? v : 1f) : 0f;

        private static Vector3 TipOf(Skeleton s, RigidPose[] world, int j1, int j2)
        {
            for (int c = j2 + 1; c < s.JointCount; c++)
                if (s.GetParent(c) == j2) return world[c].RelativeTo(world[j2]).Position;
            // No end point: extrapolate the last phalanx with the length of the previous one, times 0.8.
            Vector3 d = world[j2].Position - world[j1].Position;
            return Vector3.Transform(d * 0.8f, Quaternion.Conjugate(world[j2].Rotation));
        }
    }
}
