using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>The bend-plane angle error that sees a knee or elbow bent the wrong way (issue 10).</summary>
    public class BendPlaneTests
    {
        // A leg from the hip at the origin down to the ankle, the knee 10 cm off the line in `bend`'s direction.
        private static readonly Vector3 Hip = Vector3.Zero, Ankle = new Vector3(0f, -0.8f, 0f);

        private static Vector3 Knee(Vector3 bend) => new Vector3(0f, -0.4f, 0f) + Vector3.Normalize(bend) * 0.1f;

        [Test]
        public void ABackwardKneeIsAHalfTurnOffAndASidewaysOneAQuarter()
        {
            Vector3 forward = Knee(Vector3.UnitZ);
            Assert.That(BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, Hip, forward, Ankle), Is.EqualTo(0.0).Within(1e-3));
            Assert.That(System.Math.Abs(BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, Hip, Knee(-Vector3.UnitZ), Ankle)), Is.EqualTo(180.0).Within(1e-3));
            double left = BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, Hip, Knee(-Vector3.UnitX), Ankle);
            double right = BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, Hip, Knee(Vector3.UnitX), Ankle);
            Assert.That(System.Math.Abs(left), Is.EqualTo(90.0).Within(1e-3));
            Assert.That(right, Is.EqualTo(-left).Within(1e-3), "signed: one side positive, the other negative");
            Assert.That(BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, Hip, Knee(new Vector3(1f, 0f, 1f)), Ankle), Is.EqualTo(-right / 2).Within(1e-3).Or.EqualTo(right / 2).Within(1e-3));
        }

        [Test]
        public void AShoulderOffTheWearersDoesNotReadAsSwivel()
        {
            // The avatar's whole arm moved 4 cm and tilted, bent the same way: no swivel error.
            Vector3 forward = Knee(Vector3.UnitZ);
            Quaternion tilt = Rotations.AngleAxis(8f, Vector3.UnitX);
            Vector3 shift = new Vector3(0.01f, 0.03f, -0.02f);
            Vector3 r = Vector3.Transform(Hip, tilt) + shift, m = Vector3.Transform(forward, tilt) + shift, e = Vector3.Transform(Ankle, tilt) + shift;
            Assert.That(BendPlaneReport.SignedAngleDegrees(Hip, forward, Ankle, r, m, e), Is.EqualTo(0.0).Within(1e-2));
        }

        [Test]
        public void AStraightLimbHasNoBendPlaneAndAStraightAvatarLimbIsWrong()
        {
            Vector3 straight = new Vector3(0f, -0.4f, 0.005f); // 1.4° off the line
            Assert.That(double.IsNaN(BendPlaneReport.SignedAngleDegrees(Hip, straight, Ankle, Hip, Knee(Vector3.UnitZ), Ankle)), Is.True);
            Assert.That(BendPlaneReport.SignedAngleDegrees(Hip, Knee(Vector3.UnitZ), Ankle, Hip, new Vector3(0f, -0.4f, 0f), Ankle), Is.EqualTo(180.0));
        }

        [Test]
        public void TheEvaluatorReportsNoFlippedKneeOrElbowOnMixamo()
        {
            EvaluationReport report = RestConventionTests.Evaluate(RestConventionTests.Read(TestData.Mocap("mixamo_fingers_30fps.bvh")), 2, false);
            foreach (BendPlaneReport b in report.BendPlanes)
            {
                Assert.That(b.AbsoluteDegrees.Count + b.StraightFrames, Is.EqualTo(report.Frames), $"{b.Joint}: every frame counted or left out as straight");
                Assert.That(b.AbsoluteDegrees.Count, Is.GreaterThan(100), $"{b.Joint}: frames bent enough to compare");
                Assert.That(b.FlippedShare, Is.LessThanOrEqualTo(0.01), $"{b.Joint}: flipped share");
                Assert.That(b.AbsoluteDegrees.Median, Is.LessThanOrEqualTo(45.0), $"{b.Joint}: median bend-plane error (deg)");
            }
        }
    }
}
