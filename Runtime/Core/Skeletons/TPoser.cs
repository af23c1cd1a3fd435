using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Brings any humanoid skeleton, whatever its bind pose (T-pose, A-pose, a straight line) and its bones' local axes,
    /// to one canonical T-pose built from anatomy and landmarks: hip line level along +X, spine and neck straight up,
    /// clavicles, arms and hands straight out along ±X, palms down with the thumbs forward (from the finger bases),
    /// fingers side by side and relaxed (<see cref="RelaxedFingerDegrees"/>), legs straight down, feet flat toward the toes, facing +Z, the lowest point of the legs on the
    /// floor (y = 0), the hips above the origin; then placed at a floor position and facing given by a
    /// <see cref="RigidPose"/> (its rotation should be a yaw).
    /// </summary>
    /// <remarks>
    /// <para>Every joint is oriented from where its children are in its own frame (the skeleton's rest translations,
    /// which no bind pose changes), never from its rest rotation: a joint with two landmarks is fixed completely (the
    /// hips by the hip line and the spine; when the thighs hang from the first spine joint, as 3ds Max Biped's do, the
    /// hips only stand the spine up and that joint levels the thighs; the chest by the neck and the clavicles (the upper
    /// arms on a rig without clavicles), the hand by the middle finger's base
    /// and the little-to-index line, the head by its eyes and crown); a joint with one (an upper arm, a shin, a finger
    /// bone) gets its direction, each spine bone toward its own child on the way to the head, and the joints on that way
    /// that are no humanoid bone (UE5's spine_02) stand up with them. The twist about such a bone is not given by any landmark: it is the smallest turn from
    /// <c>twistReference</c> (the rest pose unless another pose is given), and nothing in the core depends on it (the
    /// solver bends limbs from positions; tested by rewriting clips in random local axes).</para>
    /// <para>Fallbacks where a landmark is missing: hips whose spine starts on the middle of the hip line stand up toward
    /// the first joint on the way to the head off it; a chest whose clavicles start at one point (Rigify) keeps the
    /// reference twist; a head without eyes stands its crown up (its one child besides the jaw, a leaf ending the head by
    /// being an End Site or by its name, at least half as far from it as it is from the neck) and keeps the
    /// reference twist about it, and without that crown keeps the reference rotation relative to the neck; a spine joint
    /// aims at the next joint toward the head that does not sit on it; a hand without
    /// finger bases points along its child (or keeps the reference rotation when it has none, as an end site); a foot
    /// without a child (no toes, no end site) keeps its reference rotation and stands <see cref="AnkleHeightOfLeg"/> of a
    /// leg above the floor.</para>
    /// </remarks>
    public static class TPoser
    {
        /// <summary>
        /// The height of the ankle joint above the floor, as a fraction of the leg's length (hip to knee plus knee to
        /// ankle): 0.08, from the body-segment proportions of Drillis and Contini (ankle 0.039 H, hip 0.53 H). In the T-pose
        /// the toes are put on the floor this far below the ankle (the foot pitched down toward them).
        /// </summary>
        public const float AnkleHeightOfLeg = 0.08f;

        /// <summary>
        /// How far each finger joint (not the thumb's) is flexed toward the palm in the T-pose, in degrees: 10°, a relaxed
        /// open hand rather than a stiff one. The T-pose is the finger IK's open hand (<see cref="HandModel"/>): from fully
        /// straight fingers the Mixamo hand's middle finger no longer reached the VIVE wand's surface (5 mm; 0 mm at 10°).
        /// </summary>
        public const float RelaxedFingerDegrees = 10f;

        /// <summary>The steepest the foot is pitched down toward its toes in the T-pose (60°), for a toe landmark close to the ankle.</summary>
        private const float MaxFootPitchDegrees = 60f;

        /// <summary>
        /// Poses <paramref name="pose"/> (a pose buffer of <paramref name="map"/>'s skeleton) in the canonical T-pose at
        /// <paramref name="placement"/>; bone twists no landmark fixes come from the rest pose.
        /// </summary>
        /// <exception cref="ArgumentException">The rig lacks a required humanoid bone.</exception>
        public static void Apply(HumanoidMap map, SkeletonPose pose, RigidPose placement) => Apply(map, pose, placement, null);

        /// <summary>
        /// As <see cref="Apply(HumanoidMap, SkeletonPose, RigidPose)"/>, taking the twists no landmark fixes (about single-child
        /// bones and the joints between the hips and the head that are no humanoid bones, and the whole rotation of the other
        /// joints that are not humanoid bones) from <paramref name="twistReference"/>: local
        /// poses of the skeleton (only their rotations are read), or null for the rest pose. A simulated wearer passes the
        /// first frame of its motion, so that its T-pose and its motion share those twists.
        /// </summary>
        /// <exception cref="ArgumentException">The rig lacks a required humanoid bone, or the reference has the wrong length.</exception>
        public static void Apply(HumanoidMap map, SkeletonPose pose, RigidPose placement, RigidPose[] twistReference) =>
            Apply(map, pose, placement, twistReference, false);

        /// <summary>
        /// As <see cref="Apply(HumanoidMap, SkeletonPose, RigidPose, RigidPose[])"/>; with <paramref name="spineJointsAsBound"/>
        /// the joints between the hips and the head that are no humanoid bone keep their reference rotation (the rest pose's:
        /// an avatar's bind pose) instead of standing up with the spine bones around them, as Unity's Animator leaves them
        /// (<see cref="CalibrationSettings.SpineJointsAsBound"/>).
        /// </summary>
        /// <exception cref="ArgumentException">The rig lacks a required humanoid bone, or the reference has the wrong length.</exception>
        public static void Apply(HumanoidMap map, SkeletonPose pose, RigidPose placement, RigidPose[] twistReference, bool spineJointsAsBound)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (pose == null || pose.Skeleton != map.Skeleton) throw new ArgumentException("The pose must belong to the map's skeleton.", nameof(pose));
            map.RequireComplete(nameof(map));
            Skeleton s = map.Skeleton;
            if (twistReference != null && twistReference.Length != s.JointCount)
                throw new ArgumentException($"The twist reference needs {s.JointCount} local poses, got {twistReference.Length}.", nameof(twistReference));
            pose.Origin = RigidPose.Identity;
            // Rest translations (the skeleton's proportions), reference rotations (the twists nothing else fixes).
            for (int j = 0; j < s.JointCount; j++)
            {
                RigidPose rest = s.GetRestLocal(j);
                Quaternion rotation = twistReference != null && !s.IsEndSite(j) ? Rotations.NormalizeOr(twistReference[j].Rotation, rest.Rotation) : rest.Rotation;
                pose.Local[j] = new RigidPose(rest.Position, rotation);
            }
            pose.UpdateWorld();
            var roles = new BoneRole[s.JointCount];
            for (int j = 0; j < roles.Length; j++) roles[j] = RoleOf(map, map.BoneOf(j));
            // Joints between the hips and the head that are no humanoid bone (UE5's spine_02 and neck_02, the CMU
            // conversion's Neck1) stand up too: kept in their reference rotation, they would place the neck and head
            // where the reference (the wearer's first frame, the avatar's rest) bends them, differently for each.
            int headJoint = map[HumanoidBone.Head], hipsJoint = map[HumanoidBone.Hips];
            // (Only on the way down from the head to the hips: with the hips mapped by hand beside the spine, the walk would
            // pass them and mark the joints above, a floor root among them.)
            if (!spineJointsAsBound && s.IsAncestorOrSelf(hipsJoint, headJoint))
                for (int j = s.GetParent(headJoint); j >= 0 && j != hipsJoint; j = s.GetParent(j))
                    if (roles[j] == BoneRole.Other) roles[j] = BoneRole.SpinePath;

            // Parents first: each joint turned so that its landmarks point where the T-pose has them.
            for (int j = 0; j < s.JointCount; j++)
            {
                if (s.IsEndSite(j)) continue;
                if (Orient(map, pose, j, roles[j])) UpdateSubtree(pose, j);
            }

            // Stand on the floor (the lowest point of the legs, or the ankle's anatomical height for feet without toes),
            // hips above the origin, then place.
            float floor = float.MaxValue;
            int leftLeg = map[HumanoidBone.LeftUpperLeg], rightLeg = map[HumanoidBone.RightUpperLeg];
            RigidPose[] w = pose.World;
            for (int j = 0; j < s.JointCount; j++)
                if (s.IsAncestorOrSelf(leftLeg, j) || s.IsAncestorOrSelf(rightLeg, j)) floor = Math.Min(floor, w[j].Position.Y);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int foot = map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)];
                if (ToeLandmark(map, side) < 0) floor = Math.Min(floor, w[foot].Position.Y - AnkleHeightOfLeg * LegLength(map, pose, side));
            }
            Vector3 hips = w[map[HumanoidBone.Hips]].Position;
            Vector3 shift = new Vector3(-hips.X, -floor, -hips.Z);
            for (int j = 0; j < s.JointCount; j++)
                if (s.GetParent(j) < 0) pose.Local[j] = placement * new RigidPose(pose.Local[j].Position + shift, pose.Local[j].Rotation);
            pose.UpdateWorld();
        }

        // Forward kinematics of joint j and its descendants only (every other joint's world pose is unchanged by j's local
        // one): the same products as a full update, so the same numbers, at a fraction of the cost on rigs with fingers.
        private static void UpdateSubtree(SkeletonPose pose, int j)
        {
            Skeleton s = pose.Skeleton;
            RigidPose[] world = pose.World, local = pose.Local;
            int parent = s.GetParent(j);
            world[j] = (parent < 0 ? pose.Origin : world[parent]) * local[j];
            for (int k = j + 1; k < world.Length; k++)
                if (s.IsAncestorOrSelf(j, k)) world[k] = world[s.GetParent(k)] * local[k];
        }

        /// <summary>
        /// The height of the eyes above the floor for a skeleton posed by <see cref="Apply(HumanoidMap, SkeletonPose, RigidPose)"/>:
        /// the midpoint of the eye bones when the rig has them, otherwise the head joint plus <see cref="HeadToEyes"/> in the body frame.
        /// </summary>
        public static Vector3 EyePosition(HumanoidMap map, SkeletonPose pose, Quaternion bodyRotation)
        {
            if (map.Has(HumanoidBone.LeftEye) && map.Has(HumanoidBone.RightEye))
                return (pose.World[map[HumanoidBone.LeftEye]].Position + pose.World[map[HumanoidBone.RightEye]].Position) * 0.5f;
            return pose.World[map[HumanoidBone.Head]].Position + Vector3.Transform(HeadToEyes, bodyRotation);
        }

        /// <summary>
        /// The uniform scale that puts the eyes of <paramref name="map"/>'s T-pose <paramref name="pose"/> (unscaled, standing
        /// on the floor at y = 0) at <paramref name="eyeHeight"/> metres. Eye bones scale with the avatar; a rig without them
        /// has its eyes <see cref="HeadToEyes"/> from the head joint, a human head's offset in metres, after scaling (as
        /// <see cref="EyePosition"/> places them on the scaled avatar): divided by the head joint's height, not added to it,
        /// so that an avatar in centimetres or millimetres gets its eyes at the wearer's (the offset in its units made it
        /// 4.6 % too tall).
        /// </summary>
        public static float ScaleForEyeHeight(HumanoidMap map, SkeletonPose pose, float eyeHeight)
        {
            if (map.Has(HumanoidBone.LeftEye) && map.Has(HumanoidBone.RightEye)) return eyeHeight / EyePosition(map, pose, Quaternion.Identity).Y;
            return (eyeHeight - HeadToEyes.Y) / pose.World[map[HumanoidBone.Head]].Position.Y;
        }

        /// <summary>
        /// Where the eyes are relative to the head joint, in the body frame (x right, y up, z forward), for rigs
        /// without eye bones: 7 cm up and 9 cm forward, the eye position relative to the top of the neck of an
        /// adult head (head joints of common rigs sit at the skull base).
        /// </summary>
        public static readonly Vector3 HeadToEyes = new Vector3(0f, 0.07f, 0.09f);

        /// <summary>
        /// The joint that marks where a foot's toes are: the toes bone, else the foot's child farthest from it (an End Site
        /// at the toes, as in most BVH rigs), else -1 (no landmark: the foot keeps its reference rotation).
        /// </summary>
        public static int ToeLandmark(HumanoidMap map, BodySide side)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            HumanoidBone toes = HumanoidBones.OnSide(HumanoidBone.LeftToes, side);
            if (map.Has(toes)) return map[toes];
            return FarthestChild(map.Skeleton, map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)]);
        }

        /// <summary>
        /// The joint that marks where a hand points: the middle finger's base, else (no middle finger, with or without other
        /// finger bones) the hand's child whose chain reaches farthest (an End Site at the knuckles or fingertips; the Kinects' hand centre, followed
        /// by the hand tip, rather than the thumb beside it), else -1 (the forearm's direction is used).
        /// </summary>
        public static int HandLandmark(HumanoidMap map, BodySide side)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            HumanoidBone middle = HumanoidBones.Finger(side, Finger.Middle, Phalanx.Proximal);
            if (map.Has(middle)) return map[middle];
            return ChildReachingFarthest(map.Skeleton, map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]);
        }

        // ---- What each joint is turned to ------------------------------------------------------------------------------

        private enum BoneRole { Other, SpinePath, Hips, Spine, Head, Clavicle, UpperArm, LowerArm, Hand, Finger, UpperLeg, LowerLeg, Foot, Toes }

        private static BoneRole RoleOf(HumanoidMap map, HumanoidBone bone)
        {
            switch (bone)
            {
                case HumanoidBone.Hips: return BoneRole.Hips;
                case HumanoidBone.Spine: case HumanoidBone.Chest: case HumanoidBone.UpperChest: case HumanoidBone.Neck: return BoneRole.Spine;
                case HumanoidBone.Head: return BoneRole.Head;
                case HumanoidBone.LeftShoulder: case HumanoidBone.RightShoulder: return BoneRole.Clavicle;
                case HumanoidBone.LeftUpperArm: case HumanoidBone.RightUpperArm: return BoneRole.UpperArm;
                case HumanoidBone.LeftLowerArm: case HumanoidBone.RightLowerArm: return BoneRole.LowerArm;
                case HumanoidBone.LeftHand: case HumanoidBone.RightHand: return BoneRole.Hand;
                case HumanoidBone.LeftUpperLeg: case HumanoidBone.RightUpperLeg: return BoneRole.UpperLeg;
                case HumanoidBone.LeftLowerLeg: case HumanoidBone.RightLowerLeg: return BoneRole.LowerLeg;
                case HumanoidBone.LeftFoot: case HumanoidBone.RightFoot: return BoneRole.Foot;
                case HumanoidBone.LeftToes: case HumanoidBone.RightToes: return BoneRole.Toes;
                default: return HumanoidBones.IsFinger(bone) ? BoneRole.Finger : BoneRole.Other;
            }
        }

        // Turns joint j (its parent already posed) so that its landmarks point where the T-pose has them. Returns false when
        // it keeps its reference rotation.
        private static bool Orient(HumanoidMap map, SkeletonPose pose, int j, BoneRole role)
        {
            HumanoidBone bone = map.BoneOf(j);
            bool left = HumanoidBones.IsLeft(bone);
            BodySide side = left ? BodySide.Left : BodySide.Right;
            Vector3 outward = left ? -Vector3.UnitX : Vector3.UnitX;
            switch (role)
            {
                case BoneRole.Hips:
                {
                    int l = map[HumanoidBone.LeftUpperLeg], r = map[HumanoidBone.RightUpperLeg];
                    // 3ds Max Biped hangs the thighs from its first spine bone, which levels them (Spine, below): the hips
                    // only stand the spine up (the thighs' line here would move with that bone's turn still to come).
                    // (Up toward the spine joint itself: past it, toward the next, a Rigify so rewritten lost its feet, end
                    // effectors p95 4 -> 18 mm, the spine joint's turn still to come.)
                    if (HumanoidParent(map, l) != j || HumanoidParent(map, r) != j) return Turn(pose, j, At(pose, map[HumanoidBone.Spine]) - At(pose, j), Vector3.UnitY);
                    Vector3 mid = (At(pose, l) + At(pose, r)) * 0.5f;
                    return Turn(pose, j, At(pose, r) - At(pose, l), Vector3.UnitX, At(pose, UpFrom(map, pose, mid)) - mid, Vector3.UnitY);
                }
                case BoneRole.Spine:
                {
                    // Up toward its child on the way to the head (the next spine bone, or a joint between that stands up too).
                    int next = NextTowardHead(map, pose, j);
                    if (next < 0) next = map[HumanoidBone.Head]; // a spine bone mapped off the way to the head (by hand)
                    // Level across the arms' roots when this joint carries them: the clavicles, or the upper arms of a rig
                    // without clavicles (whose shoulders this joint's turn alone places). Only the joint's own children:
                    // their offsets are the skeleton's, whatever the rest convention.
                    Vector3 across = ChildrenAcross(map, pose, j, HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder);
                    if (across == Vector3.Zero) across = ChildrenAcross(map, pose, j, HumanoidBone.LeftUpperArm, HumanoidBone.RightUpperArm);
                    if (across == Vector3.Zero) across = ChildrenAcross(map, pose, j, HumanoidBone.LeftUpperLeg, HumanoidBone.RightUpperLeg); // Biped's thighs
                    return Turn(pose, j, At(pose, next) - At(pose, j), Vector3.UnitY, across, Vector3.UnitX);
                }
                case BoneRole.Head:
                {
                    // The eye line level along +X and the crown up; without a crown, the eyes where HeadToEyes puts them;
                    // without eyes, the crown up and the facing (the twist about it) from the reference; with neither, the
                    // reference rotation.
                    int le = map[HumanoidBone.LeftEye], re = map[HumanoidBone.RightEye];
                    if (le < 0 || re < 0)
                    {
                        int top = CrownWithoutEyes(map, pose, j);
                        return top >= 0 && Turn(pose, j, At(pose, top) - At(pose, j), Vector3.UnitY);
                    }
                    // The eyes first (where HeadToEyes puts them), so that what lies above them is judged in a head that
                    // faces the T-pose's way whatever the reference turned it to; then the crown, if one lies above them.
                    Vector3 eyes = (At(pose, le) + At(pose, re)) * 0.5f - At(pose, j);
                    bool turned = Turn(pose, j, At(pose, re) - At(pose, le), Vector3.UnitX, eyes, Vector3.Normalize(HeadToEyes));
                    if (turned) UpdateSubtree(pose, j);
                    int crown = CrownAboveEyes(map, pose, j, (At(pose, le) + At(pose, re)) * 0.5f - At(pose, j));
                    return crown >= 0
                        ? Turn(pose, j, At(pose, re) - At(pose, le), Vector3.UnitX, At(pose, crown) - At(pose, j), Vector3.UnitY)
                        : turned;
                }
                case BoneRole.Clavicle:
                    return Turn(pose, j, At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side)]) - At(pose, j), outward);
                case BoneRole.UpperArm:
                    return Turn(pose, j, At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side)]) - At(pose, j), outward);
                case BoneRole.LowerArm:
                    return Turn(pose, j, At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]) - At(pose, j), outward);
                case BoneRole.Hand:
                {
                    // Palm down, thumb forward: the middle finger's base out along the arm, little-to-index forward.
                    int index = map[HumanoidBones.Finger(side, Finger.Index, Phalanx.Proximal)], little = map[HumanoidBones.Finger(side, Finger.Little, Phalanx.Proximal)];
                    int landmark = HandLandmark(map, side);
                    if (landmark < 0) return false;
                    Vector3 across = index >= 0 && little >= 0 ? At(pose, index) - At(pose, little) : Vector3.Zero;
                    return Turn(pose, j, At(pose, landmark) - At(pose, j), outward, across, Vector3.UnitZ);
                }
                case BoneRole.Finger:
                {
                    // The four fingers side by side along the hand (wrist to the middle finger's base), the thumb
                    // along the line from the wrist through its first joint.
                    int child = FarthestChild(pose.Skeleton, j);
                    if (child < 0) return false;
                    int hand = map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)];
                    HumanoidBone firstBone = FirstJointOf(bone);
                    int first = firstBone == HumanoidBones.Finger(side, Finger.Thumb, Phalanx.Proximal) ? map[firstBone] : HandLandmark(map, side);
                    Vector3 direction = At(pose, first) - At(pose, hand);
                    if (!(direction.LengthSquared() > 1e-12f)) return false;
                    direction = Vector3.Normalize(direction);
                    if (first != map[HumanoidBones.Finger(side, Finger.Thumb, Phalanx.Proximal)])
                    {
                        // Relaxed, not stiff: each joint flexed RelaxedFingerDegrees toward the palm (down).
                        int k = (int)bone - (int)firstBone;
                        float curl = RelaxedFingerDegrees * (k + 1) * Rotations.Deg2Rad;
                        Vector3 palm = -Vector3.UnitY;
                        direction = Vector3.Normalize(direction * MathF.Cos(curl) + Vectors.NormalizeOr(Vectors.ProjectOnPlane(palm, direction), palm) * MathF.Sin(curl));
                    }
                    return Turn(pose, j, At(pose, child) - At(pose, j), direction);
                }
                case BoneRole.UpperLeg:
                    return Turn(pose, j, At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side)]) - At(pose, j), -Vector3.UnitY);
                case BoneRole.LowerLeg:
                    return Turn(pose, j, At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)]) - At(pose, j), -Vector3.UnitY);
                case BoneRole.Foot:
                {
                    // Toward the toes, straight ahead, pitched down so that the toes touch the floor with the ankle at its
                    // anatomical height.
                    int toe = ToeLandmark(map, side);
                    if (toe < 0) return false;
                    Vector3 toToe = At(pose, toe) - At(pose, j);
                    float reach = toToe.Length();
                    if (!(reach > 1e-6f)) return false;
                    float drop = Math.Min(AnkleHeightOfLeg * LegLength(map, pose, side) / reach, MathF.Sin(MaxFootPitchDegrees * Rotations.Deg2Rad));
                    return Turn(pose, j, toToe, new Vector3(0f, -drop, MathF.Sqrt(1f - drop * drop)));
                }
                case BoneRole.SpinePath:
                {
                    int next = NextTowardHead(map, pose, j);
                    return next >= 0 && Turn(pose, j, At(pose, next) - At(pose, j), Vector3.UnitY);
                }
                case BoneRole.Toes:
                {
                    int tip = FarthestChild(pose.Skeleton, j);
                    return tip >= 0 && Turn(pose, j, At(pose, tip) - At(pose, j), Vector3.UnitZ);
                }
                default:
                    return false;
            }
        }

        // From the left to the right bone's joint when both are children of j, else zero.
        private static Vector3 ChildrenAcross(HumanoidMap map, SkeletonPose pose, int j, HumanoidBone left, HumanoidBone right)
        {
            int l = map[left], r = map[right];
            return l >= 0 && r >= 0 && pose.Skeleton.GetParent(l) == j && pose.Skeleton.GetParent(r) == j ? At(pose, r) - At(pose, l) : Vector3.Zero;
        }

        // The first joint after j on the way to the head that does not sit on j (a joint at j's place, two joints at one
        // place, gives no direction: taken as the next one, it left the chest in its reference rotation, the shoulders
        // 54 mm apart between two references), or -1 off that way.
        private static int NextTowardHead(HumanoidMap map, SkeletonPose pose, int j) =>
            FirstOffTowardHead(map, pose, ChildToward(pose.Skeleton, j, map[HumanoidBone.Head]), At(pose, j));

        // The hips' way up from `from` (the hip line's middle, or the hips joint): the spine joint, or, when it sits there
        // (Rigify's starts on the middle of the hip line), the first joint on the way to the head off it. Up toward a joint
        // at `from` gave no direction, and the hips kept the reference's pitch (a simulated wearer's first frame: a clip
        // that starts lying down calibrated its pelvis tracker turned 90 degrees).
        private static int UpFrom(HumanoidMap map, SkeletonPose pose, Vector3 from)
        {
            int up = FirstOffTowardHead(map, pose, map[HumanoidBone.Spine], from);
            return up < 0 ? map[HumanoidBone.Spine] : up;
        }

        // From `start` on the way to the head, the first joint that does not sit on `from` (within a thousandth of the
        // distance from there to the head), the head at the latest, or -1 off that way.
        private static int FirstOffTowardHead(HumanoidMap map, SkeletonPose pose, int start, Vector3 from)
        {
            int head = map[HumanoidBone.Head], joint = start;
            float reach = Vector3.Distance(from, At(pose, head));
            while (joint >= 0 && joint != head && Vector3.Distance(At(pose, joint), from) <= 1e-3f * reach)
                joint = ChildToward(pose.Skeleton, joint, head);
            return joint;
        }

        // The child of `joint` that `descendant` hangs from (or is), or -1.
        private static int ChildToward(Skeleton s, int joint, int descendant)
        {
            for (int c = descendant; c >= 0; c = s.GetParent(c))
                if (s.GetParent(c) == joint) return c;
            return -1;
        }

        // The nearest ancestor of `joint` that is a humanoid bone, or -1.
        private static int HumanoidParent(HumanoidMap map, int joint)
        {
            for (int p = map.Skeleton.GetParent(joint); p >= 0; p = map.Skeleton.GetParent(p))
                if (map.BoneOf(p) != HumanoidBone.LastBone) return p;
            return -1;
        }

        // Turns joint j by the smallest world rotation taking its current `from` direction onto `to`.
        private static bool Turn(SkeletonPose pose, int j, Vector3 from, Vector3 to)
        {
            if (from.LengthSquared() < 1e-12f) return false;
            pose.RotateWorld(j, Rotations.FromTo(from, to));
            return true;
        }

        // Turns joint j so that `from` points along `to` and `fromSecond` (made perpendicular) along `toSecond`; with no usable
        // second direction (too short, or along the first), by the smallest rotation for the first alone.
        private static bool Turn(SkeletonPose pose, int j, Vector3 from, Vector3 to, Vector3 fromSecond, Vector3 toSecond)
        {
            if (from.LengthSquared() < 1e-12f) return Turn(pose, j, fromSecond, toSecond);
            Vector3 f = Vector3.Normalize(from);
            Vector3 second = fromSecond - Vector3.Dot(fromSecond, f) * f;
            if (second.LengthSquared() < 1e-4f * Math.Max(from.LengthSquared(), fromSecond.LengthSquared()) || second.LengthSquared() < 1e-12f)
                return Turn(pose, j, from, to);
            Vector3 t = Vector3.Normalize(to);
            Vector3 targetSecond = Vectors.NormalizeOr(toSecond - Vector3.Dot(toSecond, t) * t, Vector3.UnitY);
            Quaternion current = Frame(f, Vector3.Normalize(second));
            Quaternion target = Frame(t, targetSecond);
            pose.RotateWorld(j, Quaternion.Normalize(target * Quaternion.Conjugate(current)));
            return true;
        }

        // The rotation taking +X to a and +Y to b (a, b unit and perpendicular).
        private static Quaternion Frame(Vector3 a, Vector3 b) => Rotations.FromBasis(a, b, Vector3.Cross(a, b));

        private static Vector3 At(SkeletonPose pose, int joint) => pose.World[joint].Position;

        // The crown of a head already faced by its eyes: of its children that are neither an eye nor the jaw, the one that
        // lies highest, within CrownConeDegrees of straight up and above the eyes (eyes: their midpoint from the head).
        // Ears beside the head and hair behind it are not the crown: taken for it (the longest child), they turned the
        // head by 9 and 68 degrees and lowered the eyes by up to 13 cm, the avatar's scale with them.
        private static int CrownAboveEyes(HumanoidMap map, SkeletonPose pose, int head, Vector3 eyes)
        {
            Skeleton s = map.Skeleton;
            float cone = MathF.Cos(CrownConeDegrees * Rotations.Deg2Rad);
            int best = -1;
            float bestHeight = Math.Max(eyes.Y, 0f);
            for (int c = head + 1; c < s.JointCount; c++)
            {
                if (s.GetParent(c) != head || IsEyeOrJaw(map, c)) continue;
                Vector3 offset = At(pose, c) - At(pose, head);
                float length = offset.Length();
                if (!(length > 1e-6f) || offset.Y < cone * length) continue;
                if (offset.Y > bestHeight) { best = c; bestHeight = offset.Y; }
            }
            return best;
        }

        // How far from straight up a crown may lie in a head faced by its eyes (degrees): the top of the skull lies within
        // about 20 degrees of it; ears and the back of the skull lie beyond 50.
        private const float CrownConeDegrees = 40f;

        // The crown of a head without eyes, where nothing in the skeleton's geometry says which way the head faces (a lone
        // child's direction is the rest convention's): its one child besides the jaw, when that is a leaf (hair and other
        // chains are not) that ends the head (a BVH End Site, or a joint named as a head top: top, end, nub, tip, crown,
        // and like nothing on the face), at least half as far from the head as the head is from its humanoid parent (a
        // skull's height against its neck's: Rigify's 3 cm face End Site is not a crown), else -1 (the head keeps its
        // reference rotation). A nose taken for the crown tipped the face 73 degrees up.
        private static int CrownWithoutEyes(HumanoidMap map, SkeletonPose pose, int head)
        {
            Skeleton s = map.Skeleton;
            int below = HumanoidParent(map, head), crown = -1;
            if (below < 0) return -1;
            for (int c = head + 1; c < s.JointCount; c++)
            {
                if (s.GetParent(c) != head || IsEyeOrJaw(map, c)) continue;
                if (crown >= 0) return -1; // two candidates: which is the crown is not known
                crown = c;
            }
            if (crown < 0) return -1;
            for (int c = crown + 1; c < s.JointCount; c++)
                if (s.GetParent(c) == crown) return -1;
            // The name without its namespace ("Clip:", "Bear:" and "Machine:" hold face words). An End Site's name is only its
            // parent's (the head's) with "_End": nothing to read in it, its length decides.
            // A BVH End Site's name is made from its parent's (the head's, "_End" after it): nothing to read in it, its length
            // decides. Any other name is read, an engine's end point's too (a hat socket or a ponytail's root kept as the end
            // of a bound hierarchy turned an eyeless head 67°: a second review).
            if (!IsMadeEndSiteName(s, crown) && !NamedAsHeadTop(s.GetName(crown))) return -1;
            float neck = Vector3.Distance(At(pose, head), At(pose, below));
            return s.GetRestLocal(crown).Position.Length() >= 0.5f * neck ? crown : -1;
        }

        // An End Site named as the BVH reader names them: its parent's name and "_End" (with a number when there are several).
        private static bool IsMadeEndSiteName(Skeleton s, int joint) =>
            s.IsEndSite(joint) && s.GetName(joint).StartsWith(s.GetName(s.GetParent(joint)) + "_End", StringComparison.Ordinal);

        /// <summary>
        /// True for a joint named as the top of a head (top, end, nub, tip, crown) and like nothing on the face or hair, its
        /// namespace aside ("Clip:", "Bear:" and "Machine:" hold face words): Mixamo's HeadTop_End, a "Head_Nub".
        /// </summary>
        internal static bool NamedAsHeadTop(string name)
        {
            if (string.IsNullOrEmpty(name)) return false;
            name = name.Substring(name.LastIndexOf(':') + 1).ToLowerInvariant();
            return ContainsAny(name, HeadTopWords) && !ContainsAny(name, FaceWords);
        }

        private static readonly string[] HeadTopWords = { "top", "end", "nub", "tip", "crown" };
        private static readonly string[] FaceWords = { "face", "nose", "jaw", "chin", "mouth", "eye", "ear", "hair", "tongue", "teeth", "brow", "lip", "cheek" };

        private static bool ContainsAny(string name, string[] words)
        {
            foreach (string word in words)
                if (name.Contains(word)) return true;
            return false;
        }

        private static bool IsEyeOrJaw(HumanoidMap map, int joint)
        {
            HumanoidBone bone = map.BoneOf(joint);
            return bone == HumanoidBone.LeftEye || bone == HumanoidBone.RightEye || bone == HumanoidBone.Jaw;
        }

        private static int FarthestChild(Skeleton s, int joint)
        {
            int best = -1;
            float bestLength = 1e-6f;
            for (int c = joint + 1; c < s.JointCount; c++)
            {
                if (s.GetParent(c) != joint) continue;
                float length = s.GetRestLocal(c).Position.Length();
                if (length > bestLength) { best = c; bestLength = length; }
            }
            return best;
        }

        // The child of `joint` with the longest chain of rest offsets below it (its own offset included), or -1. Joints come
        // after their parents, so one pass sums each chain.
        private static int ChildReachingFarthest(Skeleton s, int joint)
        {
            int best = -1;
            float bestReach = 1e-6f;
            var reach = new float[s.JointCount];
            var childOf = new int[s.JointCount];
            for (int j = joint + 1; j < s.JointCount; j++)
            {
                int parent = s.GetParent(j);
                if (parent == joint) childOf[j] = j;
                else if (parent > joint && childOf[parent] > 0) childOf[j] = childOf[parent];
                else continue;
                reach[j] = (parent == joint ? 0f : reach[parent]) + s.GetRestLocal(j).Position.Length();
                if (reach[j] > bestReach) { best = childOf[j]; bestReach = reach[j]; }
            }
            return best;
        }

        private static HumanoidBone FirstJointOf(HumanoidBone fingerBone)
        {
            int first = (int)HumanoidBone.LeftThumbProximal;
            int offset = (int)fingerBone - first;
            if (offset >= 15) offset -= 15;   // right hand
            int start = (int)fingerBone - offset % 3;
            return (HumanoidBone)start;
        }

        private static float LegLength(HumanoidMap map, SkeletonPose pose, BodySide side)
        {
            Vector3 hip = At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side)]);
            Vector3 knee = At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side)]);
            Vector3 ankle = At(pose, map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)]);
            return Vector3.Distance(hip, knee) + Vector3.Distance(knee, ankle);
        }
    }
}
