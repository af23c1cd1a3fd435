using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Poses a whole humanoid skeleton from <see cref="BodyTargets"/>: the hips at their target, the spine bent
    /// toward the head target, the head turned like the HMD, then both legs and both arms by <see cref="TwoBoneIk"/>.
    /// Built once per avatar; <see cref="Solve"/> allocates nothing.
    /// </summary>
    /// <remarks>
    /// Spine: the bend <see cref="BodyTargets.SpineBend"/> (the paper's angle α between w0 and wt, with its axis) is
    /// first shared equally by the spine joints (Spine, Chest, UpperChest, Neck as present), which curves the back
    /// instead of folding it at one joint; then a few cyclic-coordinate-descent passes, each joint taking half of
    /// its correction, bring the head joint onto its target where the spine's length allows.
    /// </remarks>
    public sealed class FullBodyIk
    {
        private const int SpinePasses = 3;
        private readonly int _hips;
        private readonly int _head;
        private readonly int[] _spine;
        private readonly LimbChain _leftLeg, _rightLeg, _leftArm, _rightArm;
        private readonly Quaternion[] _spineReference;

        /// <summary>
        /// Precomputes the chains of <paramref name="map"/>'s skeleton. <paramref name="reference"/> is the pose the
        /// spine is bent from every frame (the avatar's calibration T-pose); null uses the skeleton's rest pose.
        /// </summary>
        public FullBodyIk(HumanoidMap map, SkeletonPose reference = null)
        {
            Map = map ?? throw new ArgumentNullException(nameof(map));
            var missing = map.MissingRequired();
            if (missing.Count > 0) throw new ArgumentException($"The rig lacks required bones: {string.Join(", ", missing)}.", nameof(map));
            Skeleton s = map.Skeleton;
            _hips = map[HumanBone.Hips];
            _head = map[HumanBone.Head];
            var spine = new List<int>();
            foreach (HumanBone b in new[] { HumanBone.Spine, HumanBone.Chest, HumanBone.UpperChest, HumanBone.Neck })
                if (map.Has(b) && s.IsAncestorOrSelf(map[b], _head)) spine.Add(map[b]);
            _spine = spine.ToArray();
            _spineReference = new Quaternion[_spine.Length];
            for (int i = 0; i < _spine.Length; i++)
                _spineReference[i] = reference != null ? reference.Local[_spine[i]].Rotation : s.GetRestLocal(_spine[i]).Rotation;
            _leftLeg = new LimbChain(s, map[HumanBone.LeftUpperLeg], map[HumanBone.LeftLowerLeg], map[HumanBone.LeftFoot]);
            _rightLeg = new LimbChain(s, map[HumanBone.RightUpperLeg], map[HumanBone.RightLowerLeg], map[HumanBone.RightFoot]);
            _leftArm = new LimbChain(s, map[HumanBone.LeftUpperArm], map[HumanBone.LeftLowerArm], map[HumanBone.LeftHand]);
            _rightArm = new LimbChain(s, map[HumanBone.RightUpperArm], map[HumanBone.RightLowerArm], map[HumanBone.RightHand]);
        }

        /// <summary>The avatar's humanoid map.</summary>
        public HumanoidMap Map { get; }

        /// <summary>
        /// Poses <paramref name="pose"/> (its previous content is the starting point and what inactive parts keep).
        /// On return <see cref="SkeletonPose.World"/> is up to date.
        /// </summary>
        public IkReport Solve(in BodyTargets targets, SkeletonPose pose)
        {
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            var report = new IkReport();
            Pose[] w = pose.World;
            if (targets.HipsActive && targets.Hips.IsValid) SetWorld(pose, _hips, targets.Hips);
            pose.UpdateWorld();

            if (targets.HeadActive && targets.Head.IsValid)
            {
                if (_spine.Length > 0)
                {
                    // The bend is relative to the reference spine: start from it, not from last frame's result.
                    for (int i = 0; i < _spine.Length; i++) pose.Local[_spine[i]] = pose.Local[_spine[i]].WithRotation(_spineReference[i]);
                    pose.UpdateWorld();
                    Quaternion bend = Rotations.IsUnit(targets.SpineBend) ? targets.SpineBend : Quaternion.Identity;
                    Quaternion share = Quaternion.Slerp(Quaternion.Identity, bend, 1f / _spine.Length);
                    for (int i = 0; i < _spine.Length; i++)
                    {
                        RotateWorld(pose, _spine[i], share);
                        pose.UpdateWorld();
                    }
                    for (int pass = 0; pass < SpinePasses; pass++)
                        for (int i = _spine.Length - 1; i >= 0; i--)
                        {
                            Vector3 pivot = w[_spine[i]].Position;
                            Quaternion toTarget = Rotations.FromTo(w[_head].Position - pivot, targets.Head.Position - pivot);
                            RotateWorld(pose, _spine[i], Quaternion.Slerp(Quaternion.Identity, toTarget, 0.5f));
                            pose.UpdateWorld();
                        }
                }
                report.HeadDistanceLeft = Vector3.Distance(w[_head].Position, targets.Head.Position);
                SetWorldRotation(pose, _head, targets.Head.Rotation);
                pose.UpdateWorld();
            }

            if (targets.LeftFoot.IsActive) report.LeftFoot = TwoBoneIk.Solve(pose, _leftLeg, targets.LeftFoot.Goal, targets.LeftFoot.Hint);
            if (targets.RightFoot.IsActive) report.RightFoot = TwoBoneIk.Solve(pose, _rightLeg, targets.RightFoot.Goal, targets.RightFoot.Hint);
            if (targets.LeftHand.IsActive) report.LeftHand = TwoBoneIk.Solve(pose, _leftArm, targets.LeftHand.Goal, targets.LeftHand.Hint);
            if (targets.RightHand.IsActive) report.RightHand = TwoBoneIk.Solve(pose, _rightArm, targets.RightHand.Goal, targets.RightHand.Hint);
            pose.UpdateWorld();
            return report;
        }

        private static Quaternion ParentRotation(SkeletonPose pose, int joint)
        {
            int parent = pose.Skeleton.GetParent(joint);
            return parent < 0 ? pose.Origin.Rotation : pose.World[parent].Rotation;
        }

        private static void SetWorld(SkeletonPose pose, int joint, Pose world)
        {
            int parent = pose.Skeleton.GetParent(joint);
            pose.Local[joint] = world.RelativeTo(parent < 0 ? pose.Origin : pose.World[parent]);
        }

        private static void SetWorldRotation(SkeletonPose pose, int joint, Quaternion world) =>
            pose.Local[joint] = pose.Local[joint].WithRotation(Quaternion.Normalize(Quaternion.Conjugate(ParentRotation(pose, joint)) * world));

        private static void RotateWorld(SkeletonPose pose, int joint, Quaternion delta) =>
            SetWorldRotation(pose, joint, delta * pose.World[joint].Rotation);
    }
}
