using System;
using System.IO;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free twin of the headset-free sample (Samples~/HeadsetFree): the session it writes from the bundled
    /// clip's text, played through the pipeline onto a mannequin of the same skeleton, calibrates from the session's own
    /// presses and follows the true joints as closely as `avatargo evaluate` says; a broken clip or an unwritable path
    /// fails with the usual typed errors and leaves an earlier session file as it was.
    /// </summary>
    public class HeadsetFreeSessionTests
    {
        private const string SampleMotion = "Samples~/HeadsetFree/Motion/mixamo_fingers_30fps.bvh.txt";

        private string _folder;

        [SetUp]
        public void MakeFolder() => Directory.CreateDirectory(_folder = Path.Combine(Path.GetTempPath(), "avatargo-sample-" + Guid.NewGuid().ToString("N")));

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_folder, true);

        [Test]
        public void TheSamplesSessionCalibratesAndFollowsTheWearer()
        {
            string clip = File.ReadAllText(TestData.InPackage(SampleMotion));
            string path = Path.Combine(_folder, "AvatarGo", "headset-free.agsession");
            HumanoidMap wearer = HeadsetFreeSession.Write(clip, "mixamo_fingers_30fps.bvh.txt", path, new SimulationOptions { Rate = 60 });

            // What the sample does with it: a mannequin of the wearer's skeleton is the avatar, the session plays through it.
            MannequinBlueprint mannequin = MannequinBlueprint.Create(wearer);
            Assert.That(mannequin.HumanBones.Count, Is.EqualTo(wearer.Count));
            var meter = new TruthErrorMeter();
            using (SessionReader reader = SessionReader.Open(path))
            {
                Assert.That(reader.Header.Rate, Is.EqualTo(60));
                Assert.That(reader.Header.TruthHumanoid.Skeleton.JointCount, Is.EqualTo(wearer.Skeleton.JointCount));
                var pipeline = new SelfAvatarPipeline(reader.Header.Devices, wearer);
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame))
                {
                    pipeline.Update(frame);
                    meter.Measure(pipeline.ScaledAvatar, pipeline.Pose, frame, pipeline.State);
                }
                Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), "the session's own trigger presses calibrate");
            }
            Assert.That(meter.Frames, Is.GreaterThan(150), "the motion after calibration (3.3 s at 60 Hz)");
            // The figures of pipeline.md for this clip with exact offsets (MPJPE about 11 mm, end effectors a few mm).
            Assert.That(meter.MeanMm, Is.LessThan(20), "MPJPE (mm)");
            Assert.That(meter.MeanEndEffectorMm, Is.LessThan(8), "end effectors (mm)");
        }

        [Test]
        public void TheSamplesMotionIsTheTestClipWithPlainWhitespace()
        {
            // The sample ships the Mixamo clip as a text asset with LF line ends and spaces (PVS checks .txt files).
            BvhClip shipped = BvhReader.ReadFile(TestData.InPackage(SampleMotion), new BvhReadOptions { ToMetres = true });
            BvhClip test = BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            Assert.That(shipped.Skeleton.Names, Is.EqualTo(test.Skeleton.Names));
            Assert.That(shipped.FrameCount, Is.EqualTo(test.FrameCount));
            var a = new RigidPose[shipped.Skeleton.JointCount];
            var b = new RigidPose[test.Skeleton.JointCount];
            for (int f = 0; f < shipped.FrameCount; f += 37)
            {
                shipped.GetLocalPoses(f, a);
                test.GetLocalPoses(f, b);
                for (int j = 0; j < a.Length; j++) Approx.Near(b[j], a[j], 1e-6f, 1e-3f, $"frame {f} {shipped.Skeleton.GetName(j)}");
            }
        }

        [Test]
        public void ABrokenClipFailsWithItsLineAndKeepsTheEarlierSession()
        {
            string path = Path.Combine(_folder, "s.agsession");
            File.WriteAllText(path, "earlier");
            string clip = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            var e = Assert.Throws<FormatException>(() => HeadsetFreeSession.Write(clip.Replace("CHANNELS 6", "CHANNELS 6x"), "clip.bvh.txt", path));
            Assert.That(e.Message, Does.StartWith("clip.bvh.txt:"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("earlier"));
            Assert.That(Directory.GetFiles(_folder), Has.Length.EqualTo(1), "no temporary file left");
        }
    }
}
