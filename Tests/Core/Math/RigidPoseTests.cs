using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class RigidPoseTests
    {
        private static RigidPose RandomPose(Random rng)
        {
            var axis = new Vector3((float)rng.NextDouble() - .5f, (float)rng.NextDouble() - .5f, (float)rng.NextDouble() - .5f);
            return new RigidPose(new Vector3((float)rng.NextDouble() * 4 - 2, (float)rng.NextDouble() * 2, (float)rng.NextDouble() * 4 - 2),
                Rotations.AngleAxis((float)rng.NextDouble() * 360f, axis));
        }

        [Test]
        public void InverseComposesToIdentity()
        {
            var rng = new Random(1);
            for (int i = 0; i < 100; i++)
            {
                RigidPose p = RandomPose(rng);
                Approx.Near(RigidPose.Identity, p.Inverse() * p, 1e-5f, 1e-2f);
                Approx.Near(RigidPose.Identity, p * p.Inverse(), 1e-5f, 1e-2f);
            }
        }

        [Test]
        public void CompositionMatchesPointTransforms()
        {
            var rng = new Random(2);
            for (int i = 0; i < 100; i++)
            {
                RigidPose a = RandomPose(rng), b = RandomPose(rng);
                var point = new Vector3(0.1f, -0.3f, 0.7f);
                Approx.Near(a.TransformPoint(b.TransformPoint(point)), (a * b).TransformPoint(point), 1e-5f);
                Approx.Near(point, a.InverseTransformPoint(a.TransformPoint(point)), 1e-5f);
                Approx.Near(b, (b.RelativeTo(a) is var rel ? a * rel : default), 1e-5f, 1e-2f);
            }
        }

        [Test]
        public void IsValidRejectsNaNAndNonUnitRotations()
        {
            Assert.That(RigidPose.Identity.IsValid, Is.True);
            Assert.That(new RigidPose(new Vector3(float.NaN, 0, 0), Quaternion.Identity).IsValid, Is.False);
            Assert.That(new RigidPose(new Vector3(float.PositiveInfinity, 0, 0), Quaternion.Identity).IsValid, Is.False);
            Assert.That(new RigidPose(Vector3.Zero, new Quaternion(0, 0, 0, 0)).IsValid, Is.False);
            Assert.That(new RigidPose(Vector3.Zero, new Quaternion(0, 0, 0, 1.5f)).IsValid, Is.False);
        }
    }
}
