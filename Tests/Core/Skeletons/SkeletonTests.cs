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
                    new Pose(new Vector3(0, 1, 0), Quaternion.Identity),
                    new Pose(new Vector3(0, 0.5f, 0), Rotations.AngleAxis(90f, Vector3.UnitZ)),
                    new Pose(new Vector3(0, 0.25f, 0), Quaternion.Identity),
                    new Pose(new Vector3(0, 0.1f, 0), Quaternion.Identity),
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
            var pose = new SkeletonPose(s) { Origin = new Pose(new Vector3(3, 0, -2), Rotations.AngleAxis(33f, Vector3.UnitY)) };
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
            var rest = new[] { Pose.Identity, Pose.Identity };
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "b" }, new[] { 1, -1 }, rest));
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "a" }, new[] { -1, 0 }, rest));
            Assert.Throws<ArgumentException>(() => new Skeleton(new[] { "a", "b" }, new[] { -1, 0 },
                new[] { Pose.Identity, new Pose(new Vector3(float.NaN, 0, 0), Quaternion.Identity) }));
        }

        [Test]
        public void HumanoidMapReportsMissingRequiredBones()
        {
            Skeleton s = Chain();
            var map = new HumanoidMap(s, new[]
            {
                new System.Collections.Generic.KeyValuePair<HumanBone, string>(HumanBone.Hips, "root"),
                new System.Collections.Generic.KeyValuePair<HumanBone, string>(HumanBone.Spine, "a"),
            });
            Assert.That(map[HumanBone.Spine], Is.EqualTo(1));
            Assert.That(map[HumanBone.Head], Is.EqualTo(-1));
            Assert.That(map.MissingRequired().Count, Is.EqualTo(HumanBones.Required.Length - 2));
            Assert.That(map.BoneOf(0), Is.EqualTo(HumanBone.Hips));
            Assert.That(HumanBones.Mirror(HumanBone.LeftIndexDistal), Is.EqualTo(HumanBone.RightIndexDistal));
            Assert.That(HumanBones.Parent(HumanBone.RightThumbProximal), Is.EqualTo(HumanBone.RightHand));
        }
    }
}
