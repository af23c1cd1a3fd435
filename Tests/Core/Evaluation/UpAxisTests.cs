using System.IO;
using System.Numerics;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// A clip recorded with another axis up (Z-up exports, a clip upside down or on its side) is the same motion: the
    /// simulator stands it up (<see cref="SessionSimulator.Upright"/>) and the avatar follows it exactly as it follows the
    /// Y-up original. Before, such a clip simulated a wearer lying on the floor, and calibration failed.
    /// </summary>
    public class UpAxisTests
    {
        private static BvhClip Turned(BvhClip clip, Quaternion turn) => Sessions.Rewrite(clip, (f, pose) => TurnRoots(pose, turn));

        // Turns the whole body about the origin: each root's local pose.
        private static void TurnRoots(SkeletonPose pose, Quaternion turn)
        {
            for (int j = 0; j < pose.Local.Length; j++)
                if (pose.Skeleton.GetParent(j) < 0) pose.Local[j] = new RigidPose(Vector3.Transform(pose.Local[j].Position, turn), Quaternion.Normalize(turn * pose.Local[j].Rotation));
        }

        private static (EvaluationReport report, Quaternion upright) Evaluate(BvhClip clip)
        {
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 1 });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            using var reader = new SessionReader(new StringReader(text.ToString()), "up");
            return (SessionEvaluator.Evaluate(reader, new PipelineSettings()), simulator.Upright);
        }

        [TestCase(90f, 1f, 0f, 0f)]   // a quarter turn about X: Z-up
        [TestCase(-90f, 1f, 0f, 0f)]  // -Z up
        [TestCase(90f, 0f, 0f, 1f)]   // on its side: X-up
        [TestCase(180f, 1f, 0f, 0f)]  // upside down
        public void AClipWithAnotherAxisUpGivesTheSameAvatar(float degrees, float x, float y, float z)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            Quaternion turn = Rotations.AngleAxis(degrees, new Vector3(x, y, z));
            var (own, ownUpright) = Evaluate(clip);
            var (other, upright) = Evaluate(Turned(clip, turn));
            Assert.That(ownUpright, Is.EqualTo(Quaternion.Identity), "a Y-up clip is left as it is");
            Assert.That(Rotations.AngleDegrees(upright * turn, Quaternion.Identity) < 0.01f || Vector3.Distance(Vector3.Transform(Vector3.UnitY, upright * turn), Vector3.UnitY) < 1e-4f,
                Is.True, "the turn found stands the clip up");
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.Frames, Is.EqualTo(own.Frames));
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.05), "MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), "end effectors median (mm)");
        }

        /// <summary>
        /// Where the clip stands and which way it faces do not matter either: the same motion recorded with its floor below
        /// or above y = 0 (a root at the hips, a floor at the capture volume's centre), far from the origin, or facing
        /// another way gives the same avatar (measured: within 0.01 mm on MocapBank).
        /// </summary>
        [TestCase(0f, 5f, -0.9f, 3f)]
        [TestCase(0f, 0f, 1.5f, 0f)]
        [TestCase(135f, 0f, 0f, 0f)]
        [TestCase(-60f, 100f, 0f, -100f)]
        public void AClipAnywhereOnAnyFloorFacingAnyWayGivesTheSameAvatar(float headingDegrees, float x, float y, float z)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            Quaternion heading = Rotations.AngleAxis(headingDegrees, Vector3.UnitY);
            var shift = new Vector3(x, y, z);
            BvhClip moved = Sessions.Rewrite(clip, (f, pose) =>
            {
                TurnRoots(pose, heading);
                for (int j = 0; j < pose.Local.Length; j++)
                    if (pose.Skeleton.GetParent(j) < 0) pose.Local[j] = new RigidPose(pose.Local[j].Position + shift, pose.Local[j].Rotation);
            });
            var (own, _) = Evaluate(clip);
            var (other, upright) = Evaluate(moved);
            Assert.That(upright, Is.EqualTo(Quaternion.Identity), "a Y-up clip is left as it is");
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.Frames, Is.EqualTo(own.Frames));
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.05), "MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), "end effectors median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.05), "elbows and knees median (mm)");
        }

        /// <summary>
        /// A Y-up clip that lies down or stands on its hands for a good part of it stays as it is (found in review: with 40 %
        /// of its frames lying face down the whole clip was once turned 90°), and <see cref="SimulationOptions.StandClipUp"/>
        /// false keeps even a Z-up clip as it is.
        /// </summary>
        [TestCase(0.4f, 90f), TestCase(0.45f, 180f), TestCase(0.6f, 180f)]
        public void AClipThatOnlyPartlyLiesDownStaysUp(float share, float degrees)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            Quaternion turn = Rotations.AngleAxis(degrees, Vector3.UnitX);
            int turnedFrames = (int)(share * clip.FrameCount);
            BvhClip partly = Sessions.Rewrite(clip, (f, pose) =>
            {
                if (f < turnedFrames) TurnRoots(pose, turn);
            });
            Assert.That(new SessionSimulator(partly).Upright, Is.EqualTo(Quaternion.Identity));
            Assert.That(new SessionSimulator(Turned(clip, Rotations.AngleAxis(90f, Vector3.UnitX)), new SimulationOptions { StandClipUp = false }).Upright,
                Is.EqualTo(Quaternion.Identity), "StandClipUp false");
        }
    }
}
