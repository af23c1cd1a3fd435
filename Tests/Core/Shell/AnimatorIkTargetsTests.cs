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
    /// Mirrors the play-mode test AnimatorIKDriverFollowsARecordedSession. Unity is modelled as leaving the joints that are
    /// no humanoid bone as they are bound (the skeleton's rest).
    /// </summary>
    public class AnimatorIkTargetsTests
    {
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        public void TheTargetsReproduceThePipelinesSolve(string clip)
        {
            var (frames, worstEnd, worstMiddle, worstSpine) = Reproduce(BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true }), new PipelineSettings());
            Assert.That(frames, Is.GreaterThan(250));
            // A goal at the arm's full stretch, where the law of cosines turns micrometres of rounding at the shoulder into
            // millimetres at the elbow (since the back flexes about the hip line, one Mixamo frame: hand 1.04 mm, elbow
            // 5.5 mm; within 1 mm before): an elbow bent the other way would be centimetres off.
            Assert.That(worstEnd, Is.LessThanOrEqualTo(0.0015f), "wrists and ankles where the core's solve puts them (m)");
            Assert.That(worstMiddle, Is.LessThanOrEqualTo(0.01f), "knees and elbows bent the same way (m)");
            Assert.That(worstSpine, Is.LessThanOrEqualTo(1e-5f), "the spine, head and clavicles by forward kinematics (m)");
        }

        /// <summary>
        /// On a rig with joints between the spine bones that are no humanoid bone (UE5's <c>spine_02</c> and <c>neck_02</c>:
        /// here MocapBank with one inserted halfway between Chest2 and Neck and one between Chest and Chest2, turning in the
        /// motion, the bind curved there), which Unity's Animator leaves as bound, the calibrator's <see cref="CalibrationSettings.SpineJointsAsBound"/>
        /// keeps them so in the core's pose too, and the spine's local rotations copied into Unity give back the core's neck
        /// and head (found in review: with them stood up in the core's T-pose and left as bound in Unity, the head sat
        /// centimetres off the headset).
        /// </summary>
        [Test]
        public void JointsBetweenTheSpineBonesStayAsBoundUnderTheAnimator()
        {
            BvhClip vertebrae = WithCurvedSpineJoints();
            var asBound = new PipelineSettings();
            asBound.Calibration.SpineJointsAsBound = true;
            var (frames, worstEnd, worstMiddle, worstSpine) = Reproduce(vertebrae, asBound);
            var (_, _, _, stoodUp) = Reproduce(vertebrae, new PipelineSettings());
            TestContext.WriteLine($"spine, head and clavicles off the core's solve: {worstSpine * 1000:F3} mm kept as bound, {stoodUp * 1000:F1} mm stood up");
            Assert.That(frames, Is.GreaterThan(250));
            Assert.That(worstEnd, Is.LessThanOrEqualTo(0.001f), "wrists and ankles (m)");
            Assert.That(worstMiddle, Is.LessThanOrEqualTo(0.001f), "knees and elbows (m)");
            Assert.That(worstSpine, Is.LessThanOrEqualTo(1e-5f), "the spine, head and clavicles (m)");
            Assert.That(stoodUp, Is.GreaterThan(0.005f), "stood up in the core's pose only, they move the head off (m): what the setting is for");
        }

        /// <summary>
        /// MocapBank with a joint that is no humanoid bone halfway between Chest2 and Neck and one between Chest and Chest2,
        /// turning in the motion, bound with the spine curved at them (as UE5's is), the motion unchanged: their local frames
        /// turned 15° and -12° about the hip line, so the rest bends there.
        /// </summary>
        internal static BvhClip WithCurvedSpineJoints()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            BvhClip inserted = Topology.WithJointsAbove(clip, true, ("Chest2", "ChestMid", 0.5f), ("Neck", "ChestTop", 0.5f));
            var axes = new Quaternion[inserted.Skeleton.JointCount];
            for (int j = 0; j < axes.Length; j++) axes[j] = Quaternion.Identity;
            axes[inserted.Skeleton.IndexOf("ChestMid")] = Rotations.AngleAxis(15f, Vector3.UnitX);
            axes[inserted.Skeleton.IndexOf("ChestTop")] = Rotations.AngleAxis(-12f, Vector3.UnitX);
            return BvhRebaser.Rebase(inserted, axes);
        }

        // Replays the clip's session through the pipeline and, every calibrated frame, applies the targets as the driver's
        // OnAnimatorIK and Unity's IK pass do to a pose like Unity's: the joints that are no humanoid bone as bound (the
        // skeleton's rest), the hips placed, the turned bones' local rotations set, each limb solved to its goal toward its
        // hint. Returns the frames compared and the worst distances from the core's solve (m).
        private static (int frames, float end, float middle, float spine) Reproduce(BvhClip clip, PipelineSettings settings)
        {
            string session = Sessions.Simulate(clip, new SimulationOptions { Seed = 7 });
            AnimatorIkTargets targets = null;
            SkeletonPose animator = null;
            LimbChain[] limbs = null;
            float worstEnd = 0f, worstMiddle = 0f, worstSpine = 0f;
            int frames = 0;
            Sessions.Replay(session, settings, (i, p, f) =>
            {
                if (p.State != CalibrationState.Calibrated) return;
                HumanoidMap avatar = p.ScaledAvatar;
                if (targets == null)
                {
                    targets = new AnimatorIkTargets(avatar);
                    animator = new SkeletonPose(avatar.Skeleton);
                    animator.CopyFrom(p.Pose);
                    for (int j = 0; j < avatar.Skeleton.JointCount; j++)
                        if (avatar.BoneOf(j) == HumanoidBone.LastBone) animator.Local[j] = avatar.Skeleton.GetRestLocal(j);
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
                foreach (HumanoidBone b in new[] { HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.Neck, HumanoidBone.Head, HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder })
                    if (avatar.Has(b)) worstSpine = Math.Max(worstSpine, Vector3.Distance(animator.World[avatar[b]].Position, p.Pose.World[avatar[b]].Position));
            });
            return (frames, worstEnd, worstMiddle, worstSpine);
        }
    }
}
