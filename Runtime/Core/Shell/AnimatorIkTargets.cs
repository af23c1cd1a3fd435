using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// What an Animator IK driver sets in one IK pass so that Unity's humanoid IK reproduces the pipeline's solve: the four
    /// limb goals (the solved wrists' and ankles' world poses), a hint per knee and elbow (in front of the solved middle
    /// joint, along its bend), the hips' world pose, and the local rotations of the bones the body IK turns itself (spine,
    /// chest, upper chest, neck, head, clavicles: the paper's spine forward kinematics). Engine-free: the Unity driver only
    /// copies these, after mapping them from tracking space to world space and converting the goals to Unity's effector
    /// frames. Allocation-free per frame.
    /// </summary>
    /// <remarks>
    /// The local rotations equal the Unity bones' local rotations only when the core skeleton was bound from the Unity
    /// transform hierarchy itself, every transform between the humanoid bones included (as the Unity binding does).
    /// </remarks>
    public sealed class AnimatorIkTargets
    {
        private static readonly HumanoidBone[] TurnedBones =
        {
            HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.UpperChest, HumanoidBone.Neck, HumanoidBone.Head,
            HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder,
        };

        private readonly HumanoidMap _avatar;
        private readonly int[] _goalJoint = new int[4], _rootJoint = new int[4], _middleJoint = new int[4];
        private readonly float[] _limbLength = new float[4];
        private readonly RigidPose[] _goals = new RigidPose[4];
        private readonly Vector3[] _hints = new Vector3[4];
        private readonly HumanoidBone[] _turned;
        private readonly int[] _turnedJoint;
        private readonly Quaternion[] _turnedLocal;

        /// <summary>Prepares the targets of <paramref name="avatar"/> (the scaled avatar the pipeline solves).</summary>
        public AnimatorIkTargets(HumanoidMap avatar)
        {
            _avatar = avatar ?? throw new ArgumentNullException(nameof(avatar));
            avatar.RequireComplete(nameof(avatar));
            Limb(IkGoal.LeftFoot, HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot);
            Limb(IkGoal.RightFoot, HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot);
            Limb(IkGoal.LeftHand, HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand);
            Limb(IkGoal.RightHand, HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, HumanoidBone.RightHand);
            var turned = new List<HumanoidBone>();
            foreach (HumanoidBone b in TurnedBones) if (avatar.Has(b)) turned.Add(b);
            _turned = turned.ToArray();
            _turnedJoint = new int[_turned.Length];
            _turnedLocal = new Quaternion[_turned.Length];
            for (int i = 0; i < _turned.Length; i++) _turnedJoint[i] = avatar[_turned[i]];
        }

        private void Limb(IkGoal goal, HumanoidBone root, HumanoidBone middle, HumanoidBone end)
        {
            int g = (int)goal;
            _rootJoint[g] = _avatar[root];
            _middleJoint[g] = _avatar[middle];
            _goalJoint[g] = _avatar[end];
        }

        /// <summary>The world pose the limb's end (ankle or wrist) should take.</summary>
        public RigidPose Goal(IkGoal goal) => _goals[(int)goal];

        /// <summary>Where the knee or elbow should bend toward.</summary>
        public Vector3 Hint(IkHint hint) => _hints[(int)hint];

        /// <summary>The hips' world pose (the avatar's root).</summary>
        public RigidPose Hips { get; private set; }

        /// <summary>How many bones have a local rotation to set (<see cref="TurnedBone"/>).</summary>
        public int TurnedBoneCount => _turned.Length;

        /// <summary>The <paramref name="index"/>th bone the body IK turns itself (spine, chest, upper chest, neck, head, clavicles, as the rig has them).</summary>
        public HumanoidBone TurnedBone(int index) => _turned[index];

        /// <summary>That bone's solved local rotation (relative to its parent transform).</summary>
        public Quaternion TurnedLocalRotation(int index) => _turnedLocal[index];

        /// <summary>Fills every target from the pipeline's solved pose (world poses up to date). Allocation-free.</summary>
        public void Update(SkeletonPose solved)
        {
            if (solved == null) throw new ArgumentNullException(nameof(solved));
            RigidPose[] w = solved.World;
            Hips = w[_avatar[HumanoidBone.Hips]];
            for (int g = 0; g < 4; g++)
            {
                _goals[g] = w[_goalJoint[g]];
                // The hint: in front of the middle joint along its bend (away from the root-end line), half a limb away,
                // so the IK bends the same way; a straight limb keeps its last hint.
                Vector3 root = w[_rootJoint[g]].Position, middle = w[_middleJoint[g]].Position, end = w[_goalJoint[g]].Position;
                Vector3 line = end - root;
                Vector3 bend = Vectors.ProjectOnPlane(middle - root, Vectors.NormalizeOr(line, Vector3.UnitY));
                float limb = Vector3.Distance(root, middle) + Vector3.Distance(middle, end);
                if (bend.LengthSquared() > 1e-6f * limb * limb) _hints[g] = middle + Vector3.Normalize(bend) * (0.5f * limb);
                else if (_hints[g] == Vector3.Zero) _hints[g] = middle;
            }
            for (int i = 0; i < _turned.Length; i++) _turnedLocal[i] = solved.Local[_turnedJoint[i]].Rotation;
        }
    }
}
