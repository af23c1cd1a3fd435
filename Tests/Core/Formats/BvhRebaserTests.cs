using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// <see cref="BvhRebaser"/>: the same motion in another rest convention. Every joint's world position in every frame
    /// is compared with the original clip's (issue 10: within 0.01 mm), after the rebased clip went through BVH text.
    /// </summary>
    public class BvhRebaserTests
    {
        private static readonly string[] Clips = { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps_first240.bvh" };

        private static IEnumerable<TestCaseData> Conventions()
        {
            foreach (string clip in Clips)
            {
                yield return new TestCaseData(clip, "x-along", 0f, 0).SetName($"AlongX {clip}");
                yield return new TestCaseData(clip, "x-along", 37f, 0).SetName($"AlongX twist 37 {clip}");
                for (int seed = 1; seed <= 3; seed++) yield return new TestCaseData(clip, "random", 0f, seed).SetName($"Random seed {seed} {clip}");
            }
        }

        internal static BvhClip Rebase(BvhClip clip, string rest, float twist, int seed) =>
            rest == "x-along" ? BvhRebaser.AlongX(clip, twist) : BvhRebaser.RandomAxes(clip, seed);

        [TestCaseSource(nameof(Conventions))]
        public void EveryJointStaysWhereItWasInEveryFrame(string file, string rest, float twist, int seed)
        {
            BvhClip original = BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true });
            var text = new StringWriter();
            BvhWriter.Write(text, Rebase(BvhReader.ReadFile(TestData.Mocap(file)), rest, twist, seed));
            BvhClip rebased = BvhReader.Read(new StringReader(text.ToString()), "rebased", new BvhReadOptions { ToMetres = true });

            Assert.That(rebased.FrameCount, Is.EqualTo(original.FrameCount));
            Assert.That(rebased.Skeleton.Names, Is.EqualTo(original.Skeleton.Names));
            Assert.That(rebased.GuessMetresPerUnit(), Is.EqualTo(original.GuessMetresPerUnit()), "the unit is guessed from bone lengths, not the rest's shape");
            int n = original.Skeleton.JointCount;
            RigidPose[] l1 = new RigidPose[n], w1 = new RigidPose[n], l2 = new RigidPose[n], w2 = new RigidPose[n];
            double worst = 0;
            for (int f = 0; f < original.FrameCount; f++)
            {
                original.GetWorldPoses(f, l1, w1);
                rebased.GetWorldPoses(f, l2, w2);
                for (int j = 0; j < n; j++) worst = System.Math.Max(worst, Vector3.Distance(w1[j].Position, w2[j].Position));
            }
            Assert.That(worst * 1000, Is.LessThanOrEqualTo(0.01), "largest joint displacement (mm) over every frame");
        }

        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("rigify_6channel_24fps_first240.bvh")]
        public void AlongXPutsEveryBoneOnItsJointsXAxisAndTheRestIsNotATPose(string file)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap(file));
            BvhClip rebased = BvhRebaser.AlongX(clip);
            Skeleton s = rebased.Skeleton;
            // Every joint with a child away from it has a child along +X (the one leading the largest part of the
            // skeleton; children at the same place as that one are along +X too).
            for (int j = 0; j < s.JointCount; j++)
            {
                bool hasBone = false, alongX = false;
                for (int c = j + 1; c < s.JointCount; c++)
                {
                    if (s.GetParent(c) != j) continue;
                    Vector3 o = rebased.GetFileOffset(c);
                    if (o.Length() > 1e-6f) hasBone = true;
                    if (o.X > 0f && o.Y == 0f && o.Z == 0f) alongX = true;
                }
                if (hasBone) Assert.That(alongX, Is.True, $"{file}: a child of {s.GetName(j)} along +X");
            }
            // The rest is a line, not a T-pose: the spine no longer stands up.
            HumanoidMap map = HumanoidNaming.Detect(s);
            var rest = new SkeletonPose(s);
            Vector3 hips = rest.World[map[HumanoidBone.Hips]].Position, head = rest.World[map[HumanoidBone.Head]].Position;
            Assert.That(Vectors.AngleDegrees(head - hips, Vector3.UnitY), Is.GreaterThan(45f), "the rest's spine is not upright");
        }

        [Test]
        public void TheRandomAxesAreRepeatableAndDifferBySeed()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip a = BvhRebaser.RandomAxes(clip, 5), b = BvhRebaser.RandomAxes(clip, 5), c = BvhRebaser.RandomAxes(clip, 6);
            Assert.That(a.GetValue(10, 7), Is.EqualTo(b.GetValue(10, 7)));
            Assert.That(a.GetFileOffset(3), Is.EqualTo(b.GetFileOffset(3)));
            Assert.That(a.GetFileOffset(3), Is.Not.EqualTo(c.GetFileOffset(3)));
        }
    }
}
