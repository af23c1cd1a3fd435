using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class SkeletonTests
    {
        private static Skeleton Chain()
        {
            return new Skeleton(
                new[] { "root", "a", "b", "tip" },
                new[] { -1, 0, 1, 2 },
                new[]
                {
                    new RigidPose(new Vector3(0, 1, 0), Quaternion.Identity),
                    new RigidPose(new Vector3(0, 0.5f, 0), Rotations.AngleAxis(90f, Vector3.UnitZ)),
                    new RigidPose(new Vector3(0, 0.25f, 0), Quaternion.Identity),
                    new RigidPose(new Vector3(0, 0.1f, 0), Quaternion.Identity),
                },
                new[] { false, false, false, true });
        }

        [Test]
        public void ForwardKinematicsOfAChain()
        {
            Skeleton s = Chain();
            var pose = new SkeletonPose(s);
            // a is rotated 90° about +Z, so its +Y points to -X: b sits 0.25 along -X from a.
            Approx.Near(new Vector3(0, 1.5f, 0), pose.World[1].Position, 1e-6f, "a");
            Approx.Near(new Vector3(-0.25f, 1.5f, 0), pose.World[2].Position, 1e-6f, "b");
            Approx.Near(new Vector3(-0.35f, 1.5f, 0), pose.World[3].Position, 1e-6f, "tip");
            Assert.That(s.IsEndSite(3), Is.True);
            Assert.That(s.IndexOf("b"), Is.EqualTo(2));
            Assert.That(s.IndexOf("missing"), Is.EqualTo(-1));
        }

        [Test]
        public void LocalFromWorldInvertsForwardKinematics()
        {
            Skeleton s = Chain();
            var pose = new SkeletonPose(s) { Origin = new RigidPose(new Vector3(3, 0, -2), Rotations.AngleAxis(33f, Vector3.UnitY)) };
            pose.Local[1] = pose.Local[1].WithRotation(Rotations.AngleAxis(-20f, Vector3.UnitX));
            pose.UpdateWorld();
            var copy = new SkeletonPose(s) { Origin = pose.Origin };
            Array.Copy(pose.World, copy.World, s.JointCount);
            copy.UpdateLocal();
            for (int i = 0; i < s.JointCount; i++) Approx.Near(pose.Local[i], copy.Local[i], 1e-5f, 1e-2f, s.GetName(i));
        }

        [Test]
        public void RejectsParentsAfterChildrenAndDuplicateNames()
        {
            var rest = new[] { RigidPose.Identity, RigidPose.Identity };
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "b" }, new[] { 1, -1 }, rest));
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "a" }, new[] { -1, 0 }, rest));
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "b" }, new[] { -1, 0 },
                new[] { RigidPose.Identity, new RigidPose(new Vector3(float.NaN, 0, 0), Quaternion.Identity) }));
        }

        [Test]
        public void HumanoidMapReportsMissingRequiredBones()
        {
            Skeleton s = Chain();
            var map = new HumanoidMap(s, new[]
            {
                new System.Collections.Generic.KeyValuePair<HumanoidBone, string>(HumanoidBone.Hips, "root"),
                new System.Collections.Generic.KeyValuePair<HumanoidBone, string>(HumanoidBone.Spine, "a"),
            });
            Assert.That(map[HumanoidBone.Spine], Is.EqualTo(1));
            Assert.That(map[HumanoidBone.Head], Is.EqualTo(-1));
            Assert.That(map.MissingRequired().Count, Is.EqualTo(HumanoidBones.Required.Length - 2));
            Assert.That(map.BoneOf(0), Is.EqualTo(HumanoidBone.Hips));
            Assert.That(HumanoidBones.Mirror(HumanoidBone.LeftIndexDistal), Is.EqualTo(HumanoidBone.RightIndexDistal));
            Assert.That(HumanoidBones.Parent(HumanoidBone.RightThumbProximal), Is.EqualTo(HumanoidBone.RightHand));
        }
    }
}
