using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Puts the hips where the pipeline solved them through an Animator that is told where the body is, not the hips:
    /// Unity's <c>Animator.bodyPosition</c>/<c>bodyRotation</c> are the humanoid's centre of mass and body orientation, whose
    /// relation to the hips depends on the avatar's proportions and, a little, on the pose (the limbs move the centre of
    /// mass). The relation is measured from what happened: the body pose set in one IK pass and the hips pose the Animator
    /// produced from it (read in the next pass, before anything else moves the bones) give the body in the hips' frame,
    /// and the next body pose set is the target hips times that relation. A relation that holds still is exact after one
    /// frame; one that changes as the limbs and the spine move is one frame behind them. Nothing about how Unity defines its
    /// body is assumed. Everything is in one space (tracking space). Engine-free and allocation-free.
    /// </summary>
    public sealed class BodyPoseCompensation
    {
        private readonly float _maxOffset;

        /// <summary>Prepares the compensation for <paramref name="avatar"/> (the scaled avatar the pipeline solves).</summary>
        public BodyPoseCompensation(HumanoidMap avatar)
        {
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            avatar.RequireComplete(nameof(avatar));
            // A body further from the hips than half the avatar's height is no measurement (something else moved the bones):
            // the limit is half the rest distance from the head to a foot.
            var local = new RigidPose[avatar.Skeleton.JointCount];
            var rest = new RigidPose[local.Length];
            avatar.Skeleton.GetRestLocal(local);
            avatar.Skeleton.ComputeWorld(local, rest);
            _maxOffset = 0.5f * Vector3.Distance(rest[avatar[HumanoidBone.Head]].Position, rest[avatar[HumanoidBone.LeftFoot]].Position);
        }

        /// <summary>True once a relation has been measured.</summary>
        public bool HasMeasurement { get; private set; }

        /// <summary>The body pose in the hips' frame (the last measurement), or the identity before any.</summary>
        public RigidPose BodyInHips { get; private set; } = RigidPose.Identity;

        /// <summary>The body pose to set so that the hips land on <paramref name="hipsTarget"/> (the target itself before any measurement).</summary>
        public RigidPose BodyFor(RigidPose hipsTarget) => HasMeasurement ? hipsTarget * BodyInHips : hipsTarget;

        /// <summary>
        /// Records one frame: <paramref name="bodySet"/> is the body pose that was set in an IK pass (or read there, before
        /// anything was set) and <paramref name="hipsResult"/> the hips' pose the Animator produced from it. A pose that is not
        /// finite, or a body further from the hips than half the avatar's height, is ignored. Returns true when taken.
        /// </summary>
        public bool Observe(RigidPose bodySet, RigidPose hipsResult)
        {
            if (!bodySet.IsValid || !hipsResult.IsValid) return false;
            RigidPose relation = bodySet.RelativeTo(hipsResult);
            if (!(relation.Position.Length() <= _maxOffset)) return false;
            BodyInHips = new RigidPose(relation.Position, Quaternion.Normalize(relation.Rotation));
            HasMeasurement = true;
            return true;
        }

        /// <summary>Forgets the relation (a new calibration, a new scale).</summary>
        public void Reset()
        {
            HasMeasurement = false;
            BodyInHips = RigidPose.Identity;
        }
    }
}
