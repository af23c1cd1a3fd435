using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Brings any humanoid skeleton (T-pose, A-pose or any bind pose) to a canonical T-pose: spine and neck
    /// straight up, legs straight down, arms and hands horizontal along the body's left/right, facing +Z,
    /// the lowest point of the legs on the floor (y = 0), the hips above the origin — then placed at a floor
    /// position and facing given by a <see cref="RigidPose"/> (its rotation should be a yaw).
    /// </summary>
    /// <remarks>
    /// Each limb segment is turned by the smallest rotation that takes it onto its target direction, parents
    /// before children, so the twist of every bone is the bind pose's own. The body's facing is taken from
    /// the rig: right = left hip → right hip (or shoulders), up = hips → head, forward = right × up.
    /// </remarks>
    public static class TPoser
    {
        /// <summary>Poses <paramref name="pose"/> (a pose buffer of <paramref name="map"/>'s skeleton) in the canonical T-pose at <paramref name="placement"/>.</summary>
        /// <exception cref="ArgumentException">The rig lacks a required humanoid bone.</exception>
        public static void Apply(HumanoidMap map, SkeletonPose pose, RigidPose placement)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (pose == null || pose.Skeleton != map.Skeleton) throw new ArgumentException("The pose must belong to the map's skeleton.", nameof(pose));
            map.RequireComplete(nameof(map));
            Skeleton s = map.Skeleton;
            pose.Origin = RigidPose.Identity;
            pose.ResetToRest();
            RigidPose[] w = pose.World;

            // 1. Turn the whole body so that it faces +Z with its spine along +Y.
            Vector3 right = w[map[HumanoidBone.RightUpperLeg]].Position - w[map[HumanoidBone.LeftUpperLeg]].Position;
            if (right.LengthSquared() < 1e-8f) right = w[map[HumanoidBone.RightUpperArm]].Position - w[map[HumanoidBone.LeftUpperArm]].Position;
            Vector3 up = w[map[HumanoidBone.Head]].Position - w[map[HumanoidBone.Hips]].Position;
            Quaternion body = Rotations.LookRotation(Vector3.Cross(right, up), up);
            RotateRoots(pose, Quaternion.Conjugate(body));

            // 2. Straighten the chains.
            HumanoidBone[] spine = { HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.UpperChest, HumanoidBone.Neck, HumanoidBone.Head };
            for (int i = 0; i < spine.Length - 1; i++)
            {
                if (!map.Has(spine[i])) continue;
                for (int k = i + 1; k < spine.Length; k++)
                    if (map.Has(spine[k])) { Align(map, pose, spine[i], spine[k], Vector3.UnitY); break; }
            }
            foreach (bool left in new[] { true, false })
            {
                Vector3 outward = left ? -Vector3.UnitX : Vector3.UnitX;
                Align(map, pose, left ? HumanoidBone.LeftUpperLeg : HumanoidBone.RightUpperLeg, left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg, -Vector3.UnitY);
                Align(map, pose, left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg, left ? HumanoidBone.LeftFoot : HumanoidBone.RightFoot, -Vector3.UnitY);
                Align(map, pose, left ? HumanoidBone.LeftUpperArm : HumanoidBone.RightUpperArm, left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm, outward);
                Align(map, pose, left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm, left ? HumanoidBone.LeftHand : HumanoidBone.RightHand, outward);
                Align(map, pose, left ? HumanoidBone.LeftHand : HumanoidBone.RightHand, left ? HumanoidBone.LeftMiddleProximal : HumanoidBone.RightMiddleProximal, outward);
            }

            // 3. Stand on the floor, hips above the origin, then place.
            float floor = float.MaxValue;
            int leftLeg = map[HumanoidBone.LeftUpperLeg], rightLeg = map[HumanoidBone.RightUpperLeg];
            for (int j = 0; j < s.JointCount; j++)
                if (s.IsAncestorOrSelf(leftLeg, j) || s.IsAncestorOrSelf(rightLeg, j)) floor = Math.Min(floor, w[j].Position.Y);
            Vector3 hips = w[map[HumanoidBone.Hips]].Position;
            Vector3 shift = new Vector3(-hips.X, -floor, -hips.Z);
            for (int j = 0; j < s.JointCount; j++)
                if (s.GetParent(j) < 0) pose.Local[j] = placement * new RigidPose(pose.Local[j].Position + shift, pose.Local[j].Rotation);
            pose.UpdateWorld();
        }

        /// <summary>
        /// The height of the eyes above the floor for a skeleton posed by <see cref="Apply"/>: the midpoint of the
        /// eye bones when the rig has them, otherwise the head joint plus <see cref="HeadToEyes"/> in the body frame.
        /// </summary>
        public static Vector3 EyePosition(HumanoidMap map, SkeletonPose pose, Quaternion bodyRotation)
        {
            if (map.Has(HumanoidBone.LeftEye) && map.Has(HumanoidBone.RightEye))
                return (pose.World[map[HumanoidBone.LeftEye]].Position + pose.World[map[HumanoidBone.RightEye]].Position) * 0.5f;
            return pose.World[map[HumanoidBone.Head]].Position + Vector3.Transform(HeadToEyes, bodyRotation);
        }

        /// <summary>
        /// Where the eyes are relative to the head joint, in the body frame (x right, y up, z forward), for rigs
        /// without eye bones: 7 cm up and 9 cm forward, the eye position relative to the top of the neck of an
        /// adult head (head joints of common rigs sit at the skull base).
        /// </summary>
        public static readonly Vector3 HeadToEyes = new Vector3(0f, 0.07f, 0.09f);

        private static void RotateRoots(SkeletonPose pose, Quaternion rotation)
        {
            Skeleton s = pose.Skeleton;
            for (int j = 0; j < s.JointCount; j++)
                if (s.GetParent(j) < 0)
                    pose.Local[j] = new RigidPose(Vector3.Transform(pose.Local[j].Position, rotation), Quaternion.Normalize(rotation * pose.Local[j].Rotation));
            pose.UpdateWorld();
        }

        private static void Align(HumanoidMap map, SkeletonPose pose, HumanoidBone bone, HumanoidBone child, Vector3 direction)
        {
            int j = map[bone], c = map[child];
            if (j < 0 || c < 0) return;
            Vector3 d = pose.World[c].Position - pose.World[j].Position;
            if (d.LengthSquared() < 1e-10f) return;
            pose.RotateWorld(j, Rotations.FromTo(d, direction));
            pose.UpdateWorld();
        }
    }
}
