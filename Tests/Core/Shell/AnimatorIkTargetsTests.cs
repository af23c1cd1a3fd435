using System;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free twin of the Animator IK driver: the targets it would set (hips, the local rotations of the spine,
    /// head and clavicles, the four limb goals with their hints), applied the way Unity's humanoid IK uses them (the hips
    /// placed, the bones turned, each limb solved to its goal toward its hint), give back the pipeline's own solve.
    /// Mirrors the play-mode test AnimatorIKDriverFollowsARecordedSession.
    /// </summary>
    public class AnimatorIkTargetsTests
    {
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        public void TheTargetsReproduceThePipelinesSolve(string clip)
        {
            string session = Sessions.Simulate(clip, new SimulationOptions { Seed = 7 });
            AnimatorIkTargets targets = null;
            SkeletonPose animator = null;
            LimbChain[] limbs = null;
            float worstEnd = 0f, worstMiddle = 0f, worstSpine = 0f;
            int frames = 0;
            Sessions.Replay(session, null, (i, p, f) =>
            {
                if (p.State != CalibrationState.Calibrated) return;
                HumanoidMap avatar = p.ScaledAvatar;
                if (targets == null)
                {
                    targets = new AnimatorIkTargets(avatar);
                    animator = new SkeletonPose(avatar.Skeleton);
                    animator.CopyFrom(p.Pose);
                    limbs = new[]
                    {
                        new LimbChain(avatar.Skeleton, avatar[HumanoidBone.LeftUpperLeg], avatar[HumanoidBone.LeftLowerLeg], avatar[HumanoidBone.LeftFoot]),
                        new LimbChain(avatar.Skeleton, avatar[HumanoidBone.RightUpperLeg], avatar[HumanoidBone.RightLowerLeg], avatar[HumanoidBone.RightFoot]),
                        new LimbChain(avatar.Skeleton, avatar[HumanoidBone.LeftUpperArm], avatar[HumanoidBone.LeftLowerArm], avatar[HumanoidBone.LeftHand]),
                        new LimbChain(avatar.Skeleton, avatar[HumanoidBone.RightUpperArm], avatar[HumanoidBone.RightLowerArm], avatar[HumanoidBone.RightHand]),
                    };
                    return;
                }
                targets.Update(p.Pose);
                // What the driver's OnAnimatorIK and Unity's IK pass do with them.
                animator.SetWorldPose(avatar[HumanoidBone.Hips], targets.Hips);
                for (int b = 0; b < targets.TurnedBoneCount; b++)
                {
                    int j = avatar[targets.TurnedBone(b)];
                    animator.Local[j] = animator.Local[j].WithRotation(targets.TurnedLocalRotation(b));
                }
                animator.UpdateWorld();
                foreach (IkGoal g in new[] { IkGoal.LeftFoot, IkGoal.RightFoot, IkGoal.LeftHand, IkGoal.RightHand })
                    TwoBoneIk.Solve(animator, limbs[(int)g], targets.Goal(g), targets.Hint((IkHint)(int)g));
                animator.UpdateWorld();
                frames++;
                foreach (HumanoidBone b in new[] { HumanoidBone.LeftFoot, HumanoidBone.RightFoot, HumanoidBone.LeftHand, HumanoidBone.RightHand })
                    worstEnd = Math.Max(worstEnd, Vector3.Distance(animator.World[avatar[b]].Position, p.Pose.World[avatar[b]].Position));
                foreach (HumanoidBone b in new[] { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg, HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm })
                    worstMiddle = Math.Max(worstMiddle, Vector3.Distance(animator.World[avatar[b]].Position, p.Pose.World[avatar[b]].Position));
                foreach (HumanoidBone b in new[] { HumanoidBone.Spine, HumanoidBone.Head, HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder })
                    if (avatar.Has(b)) worstSpine = Math.Max(worstSpine, Vector3.Distance(animator.World[avatar[b]].Position, p.Pose.World[avatar[b]].Position));
            });
            Assert.That(frames, Is.GreaterThan(250));
            Assert.That(worstEnd, Is.LessThanOrEqualTo(0.001f), "wrists and ankles where the core's solve puts them (m)");
            Assert.That(worstMiddle, Is.LessThanOrEqualTo(0.001f), "knees and elbows bent the same way (m)");
            Assert.That(worstSpine, Is.LessThanOrEqualTo(1e-5f), "the spine, head and clavicles by forward kinematics (m)");
        }
    }
}
