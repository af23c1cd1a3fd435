using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>Each SDF against brute force: the distance to a dense sampling of its surface, signed by an inside test.</summary>
    public class SdfShapeTests
    {
        private static readonly Random Rng = new Random(12);

        private static Vector3 RandomPoint(float extent) =>
            new Vector3((float)(Rng.NextDouble() * 2 - 1), (float)(Rng.NextDouble() * 2 - 1), (float)(Rng.NextDouble() * 2 - 1)) * extent;

        // Brute force for a capsule: the closest point of the segment by dense sampling.
        private static float BruteCapsule(Vector3 p, Vector3 a, Vector3 b, float r)
        {
            float best = float.MaxValue;
            for (int i = 0; i <= 20000; i++) best = Math.Min(best, Vector3.Distance(p, Vector3.Lerp(a, b, i / 20000f)));
            return best - r;
        }

        // Brute force for a rotated box: distance to a dense grid on its six faces, negative when inside.
        private static float BruteBox(Vector3 p, Vector3 centre, Vector3 half, Quaternion rotation, float rounding)
        {
            Vector3 q = Vector3.Transform(p - centre, Quaternion.Conjugate(rotation));
            Vector3 inner = half - new Vector3(rounding);
            bool inside = Math.Abs(q.X) <= inner.X && Math.Abs(q.Y) <= inner.Y && Math.Abs(q.Z) <= inner.Z;
            float best = float.MaxValue;
            const int n = 120;
            for (int axis = 0; axis < 3; axis++)
                for (int sign = -1; sign <= 1; sign += 2)
                    for (int i = 0; i <= n; i++)
                        for (int j = 0; j <= n; j++)
                        {
                            float u = -1 + 2f * i / n, v = -1 + 2f * j / n;
                            Vector3 s = axis == 0 ? new Vector3(sign * inner.X, u * inner.Y, v * inner.Z)
                                : axis == 1 ? new Vector3(u * inner.X, sign * inner.Y, v * inner.Z)
                                : new Vector3(u * inner.X, v * inner.Y, sign * inner.Z);
                            best = Math.Min(best, Vector3.Distance(q, s));
                        }
            return (inside ? -best : best) - rounding;
        }

        [Test]
        public void CapsuleMatchesTheClosestPointOfItsSegment()
        {
            var a = new Vector3(0.01f, -0.06f, 0.005f);
            var b = new Vector3(-0.005f, 0.04f, 0.01f);
            SdfShape capsule = SdfShape.Capsule(a, b, 0.019f);
            for (int i = 0; i < 200; i++)
            {
                Vector3 p = RandomPoint(0.1f);
                // Sampling the segment every 5 µm bounds the brute-force error to well under 0.01 mm.
                Assert.That(capsule.Distance(p), Is.EqualTo(BruteCapsule(p, a, b, 0.019f)).Within(1e-5f));
            }
        }

        [Test]
        public void SphereIsDistanceToCentreMinusRadius()
        {
            SdfShape sphere = SdfShape.Sphere(new Vector3(0.01f, 0.02f, 0.03f), 0.02f);
            for (int i = 0; i < 200; i++)
            {
                Vector3 p = RandomPoint(0.1f);
                Assert.That(sphere.Distance(p), Is.EqualTo(Vector3.Distance(p, new Vector3(0.01f, 0.02f, 0.03f)) - 0.02f).Within(1e-6f));
            }
        }

        [TestCase(0f)]
        [TestCase(0.008f)]
        public void BoxAndRoundedBoxMatchTheirSampledSurface(float rounding)
        {
            var centre = new Vector3(0.01f, 0.05f, 0f);
            var half = new Vector3(0.024f, 0.02f, 0.03f);
            Quaternion rotation = Rotations.AngleAxis(25f, new Vector3(1, 2, 0.5f));
            SdfShape box = rounding > 0 ? SdfShape.RoundedBox(centre, half, rounding, rotation) : SdfShape.Box(centre, half, rotation);
            for (int i = 0; i < 60; i++)
            {
                Vector3 p = centre + RandomPoint(0.06f);
                // The grid spacing (≤ 0.5 mm) bounds the brute-force error to about 0.35 mm.
                Assert.That(box.Distance(p), Is.EqualTo(BruteBox(p, centre, half, rotation, rounding)).Within(4e-4f), $"point {p}");
            }
        }

        [Test]
        public void AnalyticGradientsMatchFiniteDifferences()
        {
            SdfShape[] shapes =
            {
                SdfShape.Capsule(new Vector3(0, -0.05f, 0), new Vector3(0, 0.04f, 0.01f), 0.018f),
                SdfShape.Sphere(new Vector3(0.01f, 0, 0), 0.03f),
                SdfShape.Box(Vector3.Zero, new Vector3(0.02f, 0.03f, 0.04f), Rotations.AngleAxis(30, Vector3.UnitY)),
                SdfShape.RoundedBox(Vector3.Zero, new Vector3(0.02f, 0.03f, 0.04f), 0.01f, Rotations.AngleAxis(-20, Vector3.UnitX)),
            };
            const float h = 1e-4f;
            foreach (SdfShape s in shapes)
                for (int i = 0; i < 100; i++)
                {
                    Vector3 p = RandomPoint(0.08f);
                    s.Evaluate(p, out Vector3 g);
                    var fd = new Vector3(
                        s.Distance(p + new Vector3(h, 0, 0)) - s.Distance(p - new Vector3(h, 0, 0)),
                        s.Distance(p + new Vector3(0, h, 0)) - s.Distance(p - new Vector3(0, h, 0)),
                        s.Distance(p + new Vector3(0, 0, h)) - s.Distance(p - new Vector3(0, 0, h))) / (2 * h);
                    // Away from the medial axis and edges the SDF is smooth: skip points where the finite difference
                    // straddles a kink (its length is then below 1).
                    if (Math.Abs(fd.Length() - 1f) > 0.01f) continue;
                    Assert.That(Vector3.Distance(g, fd), Is.LessThan(0.02f), $"{s.Kind} at {p}");
                }
        }

        [Test]
        public void CompositeIsTheUnion()
        {
            var c = new SdfComposite(new[] { SdfShape.Sphere(Vector3.Zero, 0.01f), SdfShape.Sphere(new Vector3(0.1f, 0, 0), 0.02f) });
            Assert.That(c.Distance(new Vector3(0.05f, 0, 0)), Is.EqualTo(0.03f).Within(1e-6f));
            Assert.That(c.Distance(new Vector3(0.1f, 0, 0)), Is.EqualTo(-0.02f).Within(1e-6f));
            Assert.Throws<ArgumentOutOfRangeException>(() => SdfShape.Sphere(Vector3.Zero, float.NaN));
        }
    }
}
