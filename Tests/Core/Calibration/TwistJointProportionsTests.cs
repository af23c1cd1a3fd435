using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Fitted proportions on an avatar with twist joints inserted along its limbs (the knee hangs from a thigh twist joint,
    /// as Daz Genesis' lShin from lThighTwist): a limb's ratio scales the whole limb, not only the part below its last twist
    /// joint, so the twisted avatar fits and solves as the same body without them does.
    /// </summary>
    public class TwistJointProportionsTests
    {
        private static float Limb(HumanoidMap map, HumanoidBone upper, HumanoidBone lower, HumanoidBone end)
        {
            var pose = new SkeletonPose(map.Skeleton);
            Vector3 a = pose.World[map[upper]].Position, b = pose.World[map[lower]].Position, c = pose.World[map[end]].Position;
            return Vector3.Distance(a, b) + Vector3.Distance(b, c);
        }

        private static BvhClip Mixamo() => BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true });

        [Test]
        public void ALimbRatioScalesTheWholeLimbPastItsTwistJoints()
        {
            HumanoidMap twisted = HumanoidNaming.Detect(Topology.WithTwistJoints(Mixamo()).Skeleton);
            HumanoidMap fitted = new BodyProportions(1.2f, 1.2f, 0.9f, 0.9f).Apply(twisted, 1f);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HumanoidBone hip = HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side), knee = HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side), ankle = HumanoidBones.OnSide(HumanoidBone.LeftFoot, side);
                HumanoidBone shoulder = HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side), elbow = HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side), wrist = HumanoidBones.OnSide(HumanoidBone.LeftHand, side);
                Assert.That(Limb(fitted, hip, knee, ankle) / Limb(twisted, hip, knee, ankle), Is.EqualTo(1.2).Within(1e-4), $"{side} leg");
                Assert.That(Limb(fitted, shoulder, elbow, wrist) / Limb(twisted, shoulder, elbow, wrist), Is.EqualTo(0.9).Within(1e-4), $"{side} arm");
            }
            Assert.That(Limb(Proportions.ScaleLimbs(twisted, 1.2f, 0.9f), HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot)
                        / Limb(twisted, HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot), Is.EqualTo(1.2).Within(1e-4), "ScaleLimbs (evaluate --leg-scale)");
        }

        [Test]
        public void TheShellsMovedBonesGiveTheFittedSkeletonWithTwistJoints()
        {
            HumanoidMap twisted = HumanoidNaming.Detect(Topology.WithTwistJoints(Mixamo()).Skeleton);
            Skeleton s = twisted.Skeleton;
            var bind = new Vector3[s.JointCount];
            for (int j = 0; j < bind.Length; j++) bind[j] = s.GetRestLocal(j).Position;
            var bones = new ProportionedBones(twisted, bind);
            Assert.That(bones.Count, Is.EqualTo(16), "knees, ankles, elbows, wrists and the twist joint above each");
            var proportions = new BodyProportions(1.15f, 1.1f, 0.9f, 0.85f);
            var profile = new CalibrationProfile { ScaleMode = ScaleMode.Fitted, Proportions = proportions };
            Assert.That(bones.Update(profile, true), Is.True);
            for (int i = 0; i < bones.Count; i++) bind[bones.Joint(i)] = bones.LocalPosition(i);
            var rest = new RigidPose[s.JointCount];
            for (int j = 0; j < rest.Length; j++) rest[j] = new RigidPose(bind[j], s.GetRestLocal(j).Rotation);
            var moved = new SkeletonPose(s.WithRestLocal(rest));
            var expected = new SkeletonPose(proportions.Apply(twisted, 1f).Skeleton);
            for (int j = 0; j < s.JointCount; j++)
                Assert.That(Vector3.Distance(moved.World[j].Position, expected.World[j].Position), Is.LessThan(1e-5f), s.GetName(j));
        }

        // The same body with and without twist joints: the plain rig's limbs scaled by BodyProportions, the twisted rig's
        // by every joint along each limb (the twist joints halfway, as on the plain rig's bone).
        [TestCase(1f, 1f)]
        [TestCase(0.85f, 1.1f)]
        public void TwistJointsChangeNoFittedCalibration(float leg, float arm)
        {
            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            BvhClip clip = Mixamo();
            var settings = new PipelineSettings();
            settings.Calibration.Proportions.Mode = ScaleMode.Fitted;
            HumanoidMap plain = new BodyProportions(leg, leg, arm, arm).Apply(HumanoidNaming.Detect(clip.Skeleton), 1f);
            HumanoidMap twisted = ScaledAlongEveryJoint(HumanoidNaming.Detect(Topology.WithTwistJoints(clip).Skeleton), leg, arm);
            var a = SessionEvaluator.Evaluate(Sessions.Read(session), settings, plain);
            var b = SessionEvaluator.Evaluate(Sessions.Read(session), settings, twisted);
            Assert.That(a.Profile, Is.Not.Null, a.CalibrationMessage);
            Assert.That(b.Profile, Is.Not.Null, b.CalibrationMessage);
            TestContext.WriteLine($"plain {a.Profile.Proportions}, scale {a.Profile.AvatarScale:0.0000}, end effectors {a.EndEffectorMm.Median:0.00} mm; twisted {b.Profile.Proportions}, scale {b.Profile.AvatarScale:0.0000}, end effectors {b.EndEffectorMm.Median:0.00} mm");
            Assert.That(b.Profile.AvatarScale, Is.EqualTo(a.Profile.AvatarScale).Within(1e-4));
            Assert.That(b.Profile.Proportions.LeftLeg, Is.EqualTo(a.Profile.Proportions.LeftLeg).Within(1e-4));
            Assert.That(b.Profile.Proportions.LeftArm, Is.EqualTo(a.Profile.Proportions.LeftArm).Within(1e-4));
            Assert.That(b.EndEffectorMm.Median, Is.EqualTo(a.EndEffectorMm.Median).Within(0.1));
        }

        private static HumanoidMap ScaledAlongEveryJoint(HumanoidMap map, float leg, float arm)
        {
            Skeleton s = map.Skeleton;
            var rest = new RigidPose[s.JointCount];
            for (int j = 0; j < rest.Length; j++) rest[j] = s.GetRestLocal(j);
            foreach (var (upper, end, k) in new[] { (HumanoidBone.LeftUpperLeg, HumanoidBone.LeftFoot, leg), (HumanoidBone.RightUpperLeg, HumanoidBone.RightFoot, leg), (HumanoidBone.LeftUpperArm, HumanoidBone.LeftHand, arm), (HumanoidBone.RightUpperArm, HumanoidBone.RightHand, arm) })
                for (int j = map[end]; j != map[upper]; j = s.GetParent(j)) rest[j] = rest[j].WithPosition(rest[j].Position * k);
            return new HumanoidMap(s.WithRestLocal(rest), new List<KeyValuePair<HumanoidBone, string>>(map.Pairs()));
        }
    }
}
