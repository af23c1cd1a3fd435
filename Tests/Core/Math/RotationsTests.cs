using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class RotationsTests
    {
        [Test]
        public void ProductAppliesRightOperandFirst_AsUnity()
        {
            Quaternion yaw = Rotations.AngleAxis(90f, Vector3.UnitY);
            Quaternion pitch = Rotations.AngleAxis(90f, Vector3.UnitX);
            // pitch first sends +Z to -Y (Unity: rotating +Z by +90° about +X gives -Y); yaw leaves -Y alone.
            Approx.Near(new Vector3(0, -1, 0), Vector3.Transform(Vector3.UnitZ, yaw * pitch), 1e-6f);
            // yaw first sends +Z to +X (Unity: +90° about +Y turns forward to the right); pitch leaves +X alone.
            Approx.Near(new Vector3(1, 0, 0), Vector3.Transform(Vector3.UnitZ, pitch * yaw), 1e-6f);
        }

        [Test]
        public void LookRotation_MapsForwardAndUp()
        {
            var rng = new Random(7);
            for (int i = 0; i < 200; i++)
            {
                Vector3 f = Vector3.Normalize(new Vector3((float)rng.NextDouble() - .5f, (float)rng.NextDouble() - .5f, (float)rng.NextDouble() - .5f));
                Quaternion q = Rotations.LookRotation(f, Vector3.UnitY);
                Approx.Near(f, Vector3.Transform(Vector3.UnitZ, q), 1e-5f, "forward");
                Vector3 up = Vector3.Transform(Vector3.UnitY, q);
                Assert.That(Vector3.Dot(up, f), Is.EqualTo(0f).Within(1e-5f));
                Assert.That(up.Y, Is.GreaterThanOrEqualTo(-1e-6f), "up stays on the +Y side");
                Approx.Near(Vector3.Cross(Vector3.UnitY, f) / Vector3.Cross(Vector3.UnitY, f).Length(), Vector3.Transform(Vector3.UnitX, q), 1e-5f, "right");
            }
        }

        [Test]
        public void LookRotation_DegenerateInputStillGivesUnitRotation()
        {
            Assert.That(Rotations.IsUnit(Rotations.LookRotation(Vector3.UnitY, Vector3.UnitY)), Is.True);
            Assert.That(Rotations.IsUnit(Rotations.LookRotation(Vector3.Zero, Vector3.UnitY)), Is.True);
            Assert.That(Rotations.IsUnit(Rotations.LookRotation(new Vector3(float.NaN, 0, 0), Vector3.UnitY)), Is.True);
        }

        [Test]
        public void FromTo_IncludingOppositeDirections()
        {
            Vector3[] dirs = { Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY, Vector3.UnitZ, Vector3.Normalize(new Vector3(1, 2, 3)) };
            foreach (Vector3 a in dirs)
            foreach (Vector3 b in dirs)
                Approx.Near(b, Vector3.Transform(a, Rotations.FromTo(a, b)), 1e-5f, $"{a}->{b}");
        }

        [Test]
        public void Average_OfSymmetricSpreadIsCentre_AndSignInvariant()
        {
            Quaternion centre = Rotations.AngleAxis(40f, new Vector3(1, 1, 0));
            var samples = new Quaternion[4];
            samples[0] = centre * Rotations.AngleAxis(3f, Vector3.UnitX);
            samples[1] = centre * Rotations.AngleAxis(-3f, Vector3.UnitX);
            Quaternion c = centre * Rotations.AngleAxis(3f, Vector3.UnitZ);
            samples[2] = new Quaternion(-c.X, -c.Y, -c.Z, -c.W); // same rotation, other hemisphere
            samples[3] = centre * Rotations.AngleAxis(-3f, Vector3.UnitZ);
            Approx.Near(centre, Rotations.Average(samples), 0.01f);
        }

        [Test]
        public void NormalizeOr_RejectsZeroAndNaN()
        {
            Assert.That(Rotations.NormalizeOr(new Quaternion(0, 0, 0, 0), Quaternion.Identity), Is.EqualTo(Quaternion.Identity));
            Assert.That(Rotations.NormalizeOr(new Quaternion(float.NaN, 0, 0, 1), Quaternion.Identity), Is.EqualTo(Quaternion.Identity));
            Assert.That(Rotations.NormalizeOr(new Quaternion(0, 0, 0, 2), Quaternion.Identity).W, Is.EqualTo(1f).Within(1e-7f));
        }

        [Test]
        public void SwingTwist_RecomposesAndTwistIsAboutAxis()
        {
            Quaternion q = Rotations.AngleAxis(30f, Vector3.UnitY) * Rotations.AngleAxis(50f, Vector3.UnitX);
            Rotations.SwingTwist(q, Vector3.UnitX, out Quaternion swing, out Quaternion twist);
            Approx.Near(q, swing * twist, 1e-3f);
            Approx.Near(Vector3.UnitX, Vector3.Transform(Vector3.UnitX, twist), 1e-5f, "twist keeps its axis");
        }
    }
}
