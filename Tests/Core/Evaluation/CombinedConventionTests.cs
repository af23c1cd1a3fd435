using System.IO;
using System.Numerics;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Every way a clip may be expressed, at once: MocapBank renamed into Kinect v2's names, its bones given random local
    /// axes, written in a left-handed frame (mirrored) and with Z up. The simulator stands it up and mirrors it back, the
    /// names map the same joints, and the avatar follows it as it follows the original: each transformation alone is
    /// tested elsewhere; this shows they compose.
    /// </summary>
    public class CombinedConventionTests
    {
        [Test]
        public void AClipInEveryConventionAtOnceGivesTheSameAvatar()
        {
            string text = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip original = BvhReader.Read(new StringReader(text), "original", new BvhReadOptions { ToMetres = true });
            BvhClip renamed = NamingFamilyTests.Renamed(text, NamingFamilyTests.FamilyNames("kinect"));
            Quaternion zUp = Rotations.AngleAxis(-90f, Vector3.UnitX);
            BvhClip everything = Sessions.Rewrite(BvhRebaser.RandomAxes(renamed, 2).Mirrored(), (f, pose) =>
            {
                for (int j = 0; j < pose.Local.Length; j++)
                    if (pose.Skeleton.GetParent(j) < 0)
                        pose.Local[j] = new RigidPose(Vector3.Transform(pose.Local[j].Position, zUp), Quaternion.Normalize(zUp * pose.Local[j].Rotation));
            });

            var (own, _) = Evaluate(original);
            var (other, simulator) = Evaluate(everything);
            Assert.That(simulator.Mirrored, Is.True, "mirrored back");
            Assert.That(simulator.Upright, Is.Not.EqualTo(Quaternion.Identity), "stood up");
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.Frames, Is.EqualTo(own.Frames));
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.05), "MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), "end effectors median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.5), "elbows and knees median (mm)");
        }

        private static (EvaluationReport report, SessionSimulator simulator) Evaluate(BvhClip clip)
        {
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 3 });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            using var reader = new SessionReader(new StringReader(text.ToString()), "combined");
            return (SessionEvaluator.Evaluate(reader, new PipelineSettings()), simulator);
        }
    }
}
