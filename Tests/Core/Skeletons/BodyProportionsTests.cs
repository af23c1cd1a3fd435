using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The per-bone local position factors a Unity shell applies to an avatar's bone transforms: applied to any pose's
    /// local positions (rotations untouched) they give the fitted avatar's pose, in every rest convention.
    /// </summary>
    public class BodyProportionsTests
    {
        private static HumanoidMap Map(string clip) =>
            HumanoidNaming.Detect(BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true }).Skeleton);

        [Test]
        public void FactorsOnAPosedHierarchyGiveTheFittedAvatar([Values("mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh")] string clip)
        {
            BvhClip bvh = BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true });
            HumanoidMap map = HumanoidNaming.Detect(bvh.Skeleton);
            var p = new BodyProportions(0.91f, 0.93f, 1.12f, 1.1f);
            const float scale = 0.97f;
            float[] factors = p.LocalPositionFactors(map, scale);
            HumanoidMap fitted = p.Apply(map, scale);
            // A frame of motion: its local rotations on the original bones with scaled local positions, against the fitted
            // skeleton's rest positions with the same rotations.
            var local = new RigidPose[map.Skeleton.JointCount];
            bvh.GetLocalPoses(bvh.FrameCount / 2, local);
            var scaledLocal = new RigidPose[local.Length];
            var fittedLocal = new RigidPose[local.Length];
            for (int j = 0; j < local.Length; j++)
            {
                scaledLocal[j] = new RigidPose(map.Skeleton.GetParent(j) < 0 ? local[j].Position : map.Skeleton.GetRestLocal(j).Position * factors[j], local[j].Rotation);
                fittedLocal[j] = new RigidPose(map.Skeleton.GetParent(j) < 0 ? local[j].Position : fitted.Skeleton.GetRestLocal(j).Position, local[j].Rotation);
            }
            var a = new RigidPose[local.Length];
            var b = new RigidPose[local.Length];
            map.Skeleton.ComputeWorld(scaledLocal, a);
            fitted.Skeleton.ComputeWorld(fittedLocal, b);
            for (int j = 0; j < a.Length; j++) Assert.That(Vector3.Distance(a[j].Position, b[j].Position), Is.LessThan(1e-5f), map.Skeleton.GetName(j));

            // The segments are what the ratios say: a shin 0.91 x 0.97 as long, a forearm 1.12 x 0.97, a spine bone 0.97.
            int shin = map[HumanoidBone.LeftFoot], forearm = map[HumanoidBone.LeftHand], chest = map[HumanoidBone.Chest];
            Assert.That(fitted.Skeleton.GetRestLocal(shin).Position.Length(), Is.EqualTo(map.Skeleton.GetRestLocal(shin).Position.Length() * 0.91f * scale).Within(1e-5f));
            Assert.That(fitted.Skeleton.GetRestLocal(forearm).Position.Length(), Is.EqualTo(map.Skeleton.GetRestLocal(forearm).Position.Length() * 1.12f * scale).Within(1e-5f));
            Assert.That(fitted.Skeleton.GetRestLocal(chest).Position.Length(), Is.EqualTo(map.Skeleton.GetRestLocal(chest).Position.Length() * scale).Within(1e-5f));
            int finger = map[HumanoidBone.LeftIndexIntermediate];
            if (finger >= 0) Assert.That(factors[finger], Is.EqualTo(scale), "fingers take the overall scale");
        }

        [Test]
        public void UniformIsTheOverallScaleEverywhere()
        {
            HumanoidMap map = Map("mocapbank_30fps.bvh");
            float[] factors = BodyProportions.Uniform.LocalPositionFactors(map, 1.3f);
            foreach (float f in factors) Assert.That(f, Is.EqualTo(1.3f));
            Assert.That(BodyProportions.Uniform.IsUniform, Is.True);
            Assert.That(new BodyProportions(1f, 1f, 1.01f, 1f).IsUniform, Is.False);
        }

        [Test]
        public void InvalidProportionsAreRefused()
        {
            HumanoidMap map = Map("mocapbank_30fps.bvh");
            Assert.Throws<ArgumentException>(() => new BodyProportions(float.NaN, 1f, 1f, 1f).LocalPositionFactors(map));
            Assert.Throws<ArgumentException>(() => new BodyProportions(1f, 0f, 1f, 1f).Apply(map, 1f));
            Assert.Throws<ArgumentOutOfRangeException>(() => BodyProportions.Uniform.LocalPositionFactors(map, -1f));
        }
    }
}
