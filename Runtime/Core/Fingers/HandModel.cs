using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// One hand of an avatar for finger IK: per finger (thumb, index, middle, ring, little) its three joints, their
    /// open rotations (the rig's rest pose, or an open pose given, such as the calibration T-pose) and closed rotations,
    /// and a fingertip point. Each joint closes about an axis found from the hand's geometry, so any rig works whatever
    /// local axis its bones bend about: a finger bends about the finger's direction crossed with the palm normal; the
    /// thumb's two outer joints bend toward the little finger's base (the thumb's own flexion, which curls it across the
    /// palm); and the thumb's first joint has two parameters, like Unity's humanoid muscles (Thumb 1 Stretched and Thumb
    /// Spread): it turns toward the palm normal and, separately, lifts the thumb radially (toward the thumb side, over the top of a controller).
    /// Every joint has a parameter <c>t</c> in [0, 1] blending its open rotation to its closed one (the paper's
    /// <c>t_f^j</c>), and the thumb has its spread too: <see cref="FingerParameters"/>.
    /// </summary>
    public sealed class HandModel
    {
        /// <summary>How far the thumb's first joint spreads (lifts radially) at a spread parameter of 1, in degrees.</summary>
        public const float ThumbSpreadDegrees = 60f;

        // How far each joint closes at t = 1, in degrees: proximal, intermediate, distal.
        private static readonly float[] FingerClosing = { 80f, 100f, 70f };
        private static readonly float[] ThumbClosing = { 40f, 50f, 70f };

        /// <summary>How far a finger joint closes at t = 1, in degrees: fingers 80, 100, 70; thumb 40, 50, 70 (proximal to distal).</summary>
        public static float ClosingDegrees(Finger finger, Phalanx joint) => (finger == Finger.Thumb ? ThumbClosing : FingerClosing)[(int)joint];

        /// <summary>
        /// Where the handle crosses the palm, as a fraction of the way from the wrist to the middle knuckle (0.8: at the
        /// distal palm crease, where a power grip holds a handle).
        /// </summary>
        public const float GripAlongPalm = 0.8f;

        internal readonly int[,] Joints = new int[5, 3];
        internal readonly RigidPose[,] RestRelative = new RigidPose[5, 3];   // open pose: joint 0 relative to the hand, others to their parent joint
        internal readonly RigidPose[,] OpenLocal = new RigidPose[5, 3];      // open pose: each joint's local pose
        internal readonly Vector3[,] AxisLocal = new Vector3[5, 3];
        internal readonly float[,] MaxRadians = new float[5, 3];
        internal readonly Vector3[] TipLocal = new Vector3[5];
        internal readonly bool[] HasFinger = new bool[5];
        internal Vector3 ThumbSpreadAxisLocal;   // in the thumb's first joint's rest frame
        internal float ThumbSpreadRadians;

        /// <summary>Builds the model of one hand of <paramref name="map"/>'s rig with its rest pose as the open hand.</summary>
        /// <exception cref="ArgumentException">The hand cannot be modelled (<see cref="CanModel(HumanoidMap, BodySide, SkeletonPose, out string)"/> says why).</exception>
        public HandModel(HumanoidMap map, BodySide side) : this(map, side, null)
        {
        }

        /// <summary>
        /// Builds the model of one hand of <paramref name="map"/>'s rig with the fingers of <paramref name="openPose"/> (a pose
        /// of the rig's skeleton, its world poses up to date) as the open hand: the pipeline passes the calibration T-pose
        /// (<see cref="TPoser"/>: fingers side by side, relaxed), so that the grip does not depend on how the rig's rest pose holds its
        /// fingers (a rest with every bone along one axis has them in a line). Null uses the rest pose.
        /// </summary>
        /// <exception cref="ArgumentException">The hand cannot be modelled (<see cref="CanModel(HumanoidMap, BodySide, SkeletonPose, out string)"/> says why), or the pose is of another skeleton.</exception>
        public HandModel(HumanoidMap map, BodySide side, SkeletonPose openPose)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (!CanModel(map, side, out string reason)) throw new ArgumentException(reason, nameof(map));
            Map = map;
            Side = side;
            bool left = side == BodySide.Left;
            Skeleton s = map.Skeleton;
            if (openPose != null && openPose.Skeleton.JointCount != s.JointCount) throw new ArgumentException("The open pose belongs to another skeleton.", nameof(openPose));
            HandJoint = map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)];
            var rest = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            if (openPose != null)
            {
                Array.Copy(openPose.Local, rest, rest.Length);
                Array.Copy(openPose.World, world, world.Length);
            }
            else
            {
                s.GetRestLocal(rest);
                s.ComputeWorld(rest, world);
            }
            RigidPose hand = world[HandJoint];
            string degenerate = PalmProblem(map, side, world);
            if (degenerate != null) throw new ArgumentException(degenerate, nameof(openPose));

            int index = map[HumanoidBones.Finger(side, Finger.Index, Phalanx.Proximal)];
            int middle = map[HumanoidBones.Finger(side, Finger.Middle, Phalanx.Proximal)];
            int little = map[HumanoidBones.Finger(side, Finger.Little, Phalanx.Proximal)];
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
                int j0 = map[HumanoidBones.Finger(side, (Finger)f, Phalanx.Proximal)];
                int j1 = map[HumanoidBones.Finger(side, (Finger)f, Phalanx.Intermediate)];
                int j2 = map[HumanoidBones.Finger(side, (Finger)f, Phalanx.Distal)];
                if (j0 < 0 || j1 < 0 || j2 < 0) continue;
                HasFinger[f] = true;
                Joints[f, 0] = j0; Joints[f, 1] = j1; Joints[f, 2] = j2;
                OpenLocal[f, 0] = rest[j0]; OpenLocal[f, 1] = rest[j1]; OpenLocal[f, 2] = rest[j2];
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
                    MaxRadians[f, k] = ClosingDegrees((Finger)f, (Phalanx)k) * Rotations.Deg2Rad;
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
        }

        /// <summary>
        /// True when the rig's hand on <paramref name="side"/> can be modelled: it has the hand bone, the bases of the index,
        /// middle and little fingers (they give the palm's plane) and all three joints of the index and middle fingers.
        /// Otherwise <paramref name="reason"/> says what is missing (the avatar then holds the controller without finger IK).
        /// </summary>
        public static bool CanModel(HumanoidMap map, BodySide side, out string reason)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            return CanModelFromBones(map.Has, side, out reason);
        }

        /// <summary>
        /// As <see cref="CanModel(HumanoidMap, BodySide, out string)"/>, and the palm's geometry in <paramref name="openPose"/>
        /// (null: the rest pose) gives a plane: the middle finger's base away from the wrist, the index's and the little
        /// finger's bases apart, and the line between them not along the hand. Where it does not, the hand would get NaN
        /// rotations; it is then held without finger IK, and <paramref name="reason"/> says why.
        /// </summary>
        public static bool CanModel(HumanoidMap map, BodySide side, SkeletonPose openPose, out string reason)
        {
            if (!CanModel(map, side, out reason)) return false;
            RigidPose[] world;
            if (openPose != null && openPose.Skeleton.JointCount == map.Skeleton.JointCount) world = openPose.World;
            else
            {
                var rest = new RigidPose[map.Skeleton.JointCount];
                world = new RigidPose[rest.Length];
                map.Skeleton.GetRestLocal(rest);
                map.Skeleton.ComputeWorld(rest, world);
            }
            reason = PalmProblem(map, side, world);
            return reason == null;
        }

        // Why the knuckles give no palm plane (null when they do): the geometry the palm's axes are normalised from.
        private static string PalmProblem(HumanoidMap map, BodySide side, RigidPose[] world)
        {
            Vector3 wrist = world[map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]].Position;
            Vector3 index = world[map[HumanoidBones.Finger(side, Finger.Index, Phalanx.Proximal)]].Position;
            Vector3 middle = world[map[HumanoidBones.Finger(side, Finger.Middle, Phalanx.Proximal)]].Position;
            Vector3 little = world[map[HumanoidBones.Finger(side, Finger.Little, Phalanx.Proximal)]].Position;
            Vector3 along = middle - wrist, across = index - little;
            if (!(along.Length() > MinPalmLength)) return $"the {side} hand's middle finger base is at its wrist (no palm to model)";
            if (!(across.Length() > MinPalmLength)) return $"the {side} hand's index and little finger bases are at one point (no palm to model)";
            if (!(Vector3.Cross(Vector3.Normalize(along), Vector3.Normalize(across)).Length() > MinPalmSine))
                return $"the {side} hand's knuckles lie on a line with its wrist (no palm plane to model)";
            return null;
        }

        // The palm's plane needs the knuckles 1 mm apart and the little-to-index line at least 11.5° (sin 0.2) off the hand.
        private const float MinPalmLength = 0.001f, MinPalmSine = 0.2f;

        /// <summary>
        /// As <see cref="CanModel(HumanoidMap, BodySide, out string)"/>, for a rig known only by which humanoid bones it has
        /// (<paramref name="has"/>): an inspector asks this of a Unity Animator.
        /// </summary>
        public static bool CanModelFromBones(Predicate<HumanoidBone> has, BodySide side, out string reason)
        {
            if (has == null) throw new ArgumentNullException(nameof(has));
            reason = null;
            if (!has(HumanoidBones.OnSide(HumanoidBone.LeftHand, side))) reason = $"the rig has no {side} hand bone";
            else if (!has(HumanoidBones.Finger(side, Finger.Little, Phalanx.Proximal)))
                reason = $"the {side} hand has no little finger (the index, middle and little fingers' bases give the palm)";
            else
                foreach (Finger f in new[] { Finger.Index, Finger.Middle })
                    for (Phalanx k = Phalanx.Proximal; k <= Phalanx.Distal && reason == null; k++)
                        if (!has(HumanoidBones.Finger(side, f, k))) reason = $"the {side} hand lacks {HumanoidBones.Finger(side, f, k)}";
            return reason == null;
        }

        /// <summary>
        /// The palm of a hand without finger bones, in the T-pose <paramref name="tpose"/> (world): the hand points along the
        /// wrist's child (an End Site), or along the forearm when it has none; the palm faces down and the thumb forward,
        /// as the T-pose holds them; the hand is 0.36 of the forearm long (wrist to middle knuckle, typical proportions), and
        /// the palm centre is <see cref="GripAlongPalm"/> of the way along it, one finger radius out of the palm. Where such
        /// a hand holds a controller: <see cref="GripPose"/> of these.
        /// </summary>
        public static void PalmWithoutFingers(HumanoidMap wearer, SkeletonPose tpose, BodySide side, out Vector3 palmCentre, out Vector3 normal, out Vector3 across)
        {
            if (wearer == null) throw new ArgumentNullException(nameof(wearer));
            if (tpose == null) throw new ArgumentNullException(nameof(tpose));
            RigidPose[] w = tpose.World;
            Vector3 wrist = w[wearer[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]].Position;
            Vector3 elbow = w[wearer[HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side)]].Position;
            int landmark = TPoser.HandLandmark(wearer, side);
            Vector3 outward = side == BodySide.Left ? -Vector3.UnitX : Vector3.UnitX;
            Vector3 along = Vectors.NormalizeOr(landmark >= 0 ? w[landmark].Position - wrist : wrist - elbow, outward);
            normal = Vectors.NormalizeOr(Vectors.ProjectOnPlane(-Vector3.UnitY, along), -Vector3.UnitY);
            across = side == BodySide.Left ? Vector3.Cross(along, normal) : Vector3.Cross(normal, along);
            float handLength = 0.36f * Vector3.Distance(wrist, elbow);
            float fingerRadius = 0.0085f * handLength / 0.095f;
            palmCentre = wrist + along * (GripAlongPalm * handLength) + normal * fingerRadius;
        }

        /// <summary>The rig.</summary>
        public HumanoidMap Map { get; }

        /// <summary>Which hand.</summary>
        public BodySide Side { get; }

        /// <summary>The hand (wrist) joint.</summary>
        public int HandJoint { get; }

        /// <summary>Whether <paramref name="finger"/> has all three joints in the rig.</summary>
        public bool Has(Finger finger) => (uint)finger <= 4 ? HasFinger[(int)finger] : throw new ArgumentOutOfRangeException(nameof(finger), finger, "Not a finger.");

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
        /// the index, its trigger side (+Z) away from the palm, its origin one handle radius plus 2 mm off the palm centre
        /// (the palm centre is on the skin already) — the palm centre on the grip (<see cref="GripPose"/>).
        /// </summary>
        public RigidPose ControllerInHand(ControllerProfile profile)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            return GripPose(PalmCentreInHand, PalmNormalInHand, AcrossInHand, -profile.Shape.Distance(Vector3.Zero));
        }

        /// <summary>
        /// The pose of a controller held in a palm, in the frame the palm is given in: the handle's axis (the controller's
        /// +Y) along <paramref name="across"/> (little finger to index), its trigger side (+Z) out of the palm, its origin
        /// (on the handle's axis) <paramref name="handleRadius"/> and 2 mm of skin off <paramref name="palmCentre"/> along
        /// <paramref name="palmNormal"/>. The one definition of a held controller, for hands with and without finger bones.
        /// </summary>
        public static RigidPose GripPose(Vector3 palmCentre, Vector3 palmNormal, Vector3 across, float handleRadius)
        {
            Vector3 forward = Vectors.NormalizeOr(Vectors.ProjectOnPlane(palmNormal, across), palmNormal);
            return new RigidPose(palmCentre + palmNormal * (handleRadius + 0.002f), Rotations.LookRotation(forward, across));
        }

        /// <summary>
        /// The inverse of <see cref="ControllerInHand"/>: where the hand (wrist) joint sits in the controller's frame when
        /// it holds <paramref name="profile"/>. A tracked controller pose <c>c</c> puts the avatar's wrist at
        /// <c>c * WristInController(profile)</c>: the palm on the grip, the paper's placement of the hands
        /// (<see cref="HandPlacement.PalmOnController"/>).
        /// </summary>
        public RigidPose WristInController(ControllerProfile profile) => ControllerInHand(profile).Inverse();

        /// <summary>
        /// Sets the finger joints' local rotations in <paramref name="pose"/> from <paramref name="t"/>, each parameter
        /// clamped to [0, 1]; the world poses are not updated (call <see cref="SkeletonPose.UpdateWorld()"/>). Allocation-free.
        /// </summary>
        public void Apply(FingerParameters t, SkeletonPose pose)
        {
            if (t == null) throw new ArgumentNullException(nameof(t));
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            float[] v = t.Values;
            for (int f = 0; f < 5; f++)
            {
                if (!HasFinger[f]) continue;
                for (int k = 0; k < 3; k++)
                {
                    int j = Joints[f, k];
                    RigidPose rest = OpenLocal[f, k];
                    float spread = f == 0 && k == 0 ? v[FingerParameters.ThumbSpreadIndex] : 0f;
                    pose.Local[j] = new RigidPose(rest.Position, Quaternion.Normalize(rest.Rotation * Bend(f, k, v[f * 3 + k], spread)));
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
            Vector3 d = world[j2].Position - world[j1].Position;
            // The farthest child of the last phalanx marks its tip, unless it is a stub (a zero-length End Site, a nail or
            // helper bone): shorter than 0.3 of the phalanx before, it would put the tip at the joint and the last phalanx
            // into the controller.
            Vector3 tip = Vector3.Zero;
            for (int c = j2 + 1; c < s.JointCount; c++)
                if (s.GetParent(c) == j2)
                {
                    Vector3 child = world[c].RelativeTo(world[j2]).Position;
                    if (child.LengthSquared() > tip.LengthSquared()) tip = child;
                }
            if (tip.Length() >= 0.3f * d.Length()) return tip;
            // No end point: extrapolate the last phalanx with the length of the previous one, times 0.8.
            return Vector3.Transform(d * 0.8f, Quaternion.Conjugate(world[j2].Rotation));
        }
    }
}
