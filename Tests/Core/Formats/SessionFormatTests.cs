using System;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class SessionFormatTests
    {
        private static SessionHeader Header(HumanoidMap truth = null, bool roles = false)
        {
            var devices = new[]
            {
                new DeviceInfo(0, DeviceClass.Hmd, "HMD-1", DeviceRole.Head),
                new DeviceInfo(3, DeviceClass.Controller, "LHR-A"),
                new DeviceInfo(4, DeviceClass.Controller, "LHR-B"),
                new DeviceInfo(7, DeviceClass.Tracker, "TRK-1", DeviceRole.Pelvis),
                new DeviceInfo(8, DeviceClass.Tracker, "TRK-2"),
                new DeviceInfo(9, DeviceClass.Tracker, ""),
            };
            var trueRoles = roles ? new[] { DeviceRole.Head, DeviceRole.LeftHand, DeviceRole.RightHand, DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot } : null;
            return new SessionHeader(90f, devices, trueRoles, truth);
        }

        private static void Fill(SessionFrame f, int i, Random rng)
        {
            f.Clear();
            f.Time = i / 90.0;
            for (int d = 0; d < f.Samples.Length; d++)
            {
                var q = Rotations.AngleAxis((float)rng.NextDouble() * 360f, new Vector3((float)rng.NextDouble(), 1, (float)rng.NextDouble() - .5f));
                var p = new Vector3((float)rng.NextDouble() * 4 - 2, (float)rng.NextDouble() * 2, (float)rng.NextDouble() * 4 - 2);
                f.Samples[d] = new DeviceSample(new RigidPose(p, q), (i + d) % 17 != 0);
            }
            if (i % 50 == 10) f.Events.Add(new DeviceEvent(3, DeviceEventKind.TriggerPressed));
            if (i % 50 == 20) f.Events.Add(new DeviceEvent(3, DeviceEventKind.TriggerReleased));
            f.Trigger[1] = (float)rng.NextDouble();
            f.Grip[2] = (float)rng.NextDouble();
        }

        [Test]
        public void RoundTripKeepsEveryValue()
        {
            SessionHeader h = Header(roles: true);
            var text = new StringWriter();
            var rng = new Random(5);
            var written = new SessionFrame[120];
            using (var w = new SessionWriter(text, h))
            {
                for (int i = 0; i < written.Length; i++)
                {
                    written[i] = new SessionFrame(h);
                    Fill(written[i], i, rng);
                    w.WriteFrame(written[i]);
                }
            }
            using var r = new SessionReader(new StringReader(text.ToString()), "rt");
            Assert.That(r.Header.Rate, Is.EqualTo(90f));
            Assert.That(r.Header.Devices.Count, Is.EqualTo(6));
            Assert.That(r.Header.Devices[1].Id, Is.EqualTo(3));
            Assert.That(r.Header.Devices[0].RuntimeRole, Is.EqualTo(DeviceRole.Head));
            Assert.That(r.Header.Devices[5].Serial, Is.EqualTo(""));
            Assert.That(r.Header.TrueRole(4), Is.EqualTo(DeviceRole.LeftFoot));
            SessionFrame f = r.CreateFrame();
            int n = 0;
            while (r.ReadFrame(f))
            {
                SessionFrame e = written[n++];
                Assert.That(f.Time, Is.EqualTo(e.Time));
                for (int d = 0; d < 6; d++)
                {
                    Assert.That(f.Samples[d].IsTracked, Is.EqualTo(e.Samples[d].IsTracked));
                    // Exact: numbers are written with round-trip precision and a unit quaternion is not renormalised on reading.
                    Assert.That(f.Samples[d].Pose.Position, Is.EqualTo(e.Samples[d].Pose.Position));
                    Assert.That(f.Samples[d].Pose.Rotation, Is.EqualTo(e.Samples[d].Pose.Rotation));
                }
                Assert.That(f.Events.Count, Is.EqualTo(e.Events.Count));
                for (int k = 0; k < f.Events.Count; k++) Assert.That(f.Events[k].Kind, Is.EqualTo(e.Events[k].Kind));
                Assert.That(f.Trigger[1], Is.EqualTo(e.Trigger[1]));
                Assert.That(f.Grip[2], Is.EqualTo(e.Grip[2]));
                Assert.That(f.Trigger[0], Is.NaN);
            }
            Assert.That(n, Is.EqualTo(written.Length));
            Assert.That(r.ReadFrame(f), Is.False, "stays at the end");
        }

        [Test]
        public void GroundTruthSkeletonAndJointsRoundTrip()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            SessionHeader h = Header(map, roles: true);
            var text = new StringWriter();
            var local = new RigidPose[clip.Skeleton.JointCount];
            var world = new RigidPose[local.Length];
            using (var w = new SessionWriter(text, h))
            {
                var f = new SessionFrame(h);
                for (int i = 0; i < 30; i++)
                {
                    Fill(f, i, new Random(i));
                    clip.GetWorldPoses(i, local, world);
                    for (int b = 0; b < HumanoidBones.Count; b++)
                        if (map.Has((HumanoidBone)b)) { f.Truth[b] = world[map[(HumanoidBone)b]]; f.HasTruth[b] = true; }
                    w.WriteFrame(f);
                }
            }
            using var r = new SessionReader(new StringReader(text.ToString()), "truth");
            HumanoidMap back = r.Header.TruthHumanoid;
            Assert.That(back, Is.Not.Null);
            Assert.That(back.Skeleton.Names, Is.EqualTo(clip.Skeleton.Names));
            Assert.That(back.Count, Is.EqualTo(map.Count));
            for (int j = 0; j < local.Length; j++)
            {
                Assert.That(back.Skeleton.GetParent(j), Is.EqualTo(clip.Skeleton.GetParent(j)));
                Assert.That(back.Skeleton.IsEndSite(j), Is.EqualTo(clip.Skeleton.IsEndSite(j)));
                Assert.That(back.BoneOf(j), Is.EqualTo(map.BoneOf(j)));
                Assert.That(back.Skeleton.GetRestLocal(j).Position, Is.EqualTo(clip.Skeleton.GetRestLocal(j).Position), clip.Skeleton.GetName(j));
                Assert.That(back.Skeleton.GetRestLocal(j).Rotation, Is.EqualTo(clip.Skeleton.GetRestLocal(j).Rotation), clip.Skeleton.GetName(j));
            }
            SessionFrame g = r.CreateFrame();
            for (int i = 0; r.ReadFrame(g); i++)
            {
                clip.GetWorldPoses(i, local, world);
                Assert.That(g.HasTruth[(int)HumanoidBone.LeftHand], Is.True);
                Assert.That(g.HasTruth[(int)HumanoidBone.LeftThumbProximal], Is.False);
                for (int b = 0; b < HumanoidBones.Count; b++)
                    if (map.Has((HumanoidBone)b))
                    {
                        Assert.That(g.Truth[b].Position, Is.EqualTo(world[map[(HumanoidBone)b]].Position), ((HumanoidBone)b).ToString());
                        Assert.That(g.Truth[b].Rotation, Is.EqualTo(world[map[(HumanoidBone)b]].Rotation), ((HumanoidBone)b).ToString());
                    }
            }
        }

        [Test]
        public void StreamsALongSessionThroughAFile()
        {
            string path = Path.Combine(Path.GetTempPath(), "avatargo-stream-" + Guid.NewGuid().ToString("N") + ".agsession");
            const int frames = 20000;
            try
            {
                SessionHeader h = Header();
                double sumWritten = 0, sumRead = 0;
                using (var w = SessionWriter.Create(path, h))
                {
                    var f = new SessionFrame(h);
                    var rng = new Random(11);
                    for (int i = 0; i < frames; i++)
                    {
                        Fill(f, i, rng);
                        sumWritten += f.Samples[i % 6].Pose.Position.X;
                        w.WriteFrame(f);
                    }
                }
                TestContext.WriteLine($"{new FileInfo(path).Length / (double)frames:0} bytes per six-device frame");
                using (var r = SessionReader.Open(path))
                {
                    var f = r.CreateFrame();
                    int i = 0;
                    while (r.ReadFrame(f)) { sumRead += f.Samples[i % 6].Pose.Position.X; i++; }
                    Assert.That(i, Is.EqualTo(frames));
                }
                Assert.That(sumRead, Is.EqualTo(sumWritten));
            }
            finally { File.Delete(path); }
        }

        /// <summary>
        /// <see cref="SessionWriter.WriteFile"/> writes a session whole or not at all: when the code writing the frames throws
        /// mid-way, a session already at the path is left as it was, and the exception goes on (found in review: the
        /// headset-free session was written in a bare using, which completed the frames written so far over the old file).
        /// </summary>
        [Test]
        public void WriteFileKeepsTheOldSessionWhenWritingThrows()
        {
            string path = Path.Combine(Path.GetTempPath(), "avatargo-whole-" + Guid.NewGuid().ToString("N") + ".agsession");
            try
            {
                SessionHeader h = Header();
                void Frames(SessionWriter w, int count, bool fail)
                {
                    var f = new SessionFrame(h);
                    var rng = new Random(3);
                    for (int i = 0; i < count; i++)
                    {
                        Fill(f, i, rng);
                        w.WriteFrame(f);
                    }
                    if (fail) throw new InvalidOperationException("the simulation failed");
                }
                SessionWriter.WriteFile(path, h, w => Frames(w, 50, false));
                string before = File.ReadAllText(path);
                var e = Assert.Throws<InvalidOperationException>(() => SessionWriter.WriteFile(path, h, w => Frames(w, 20, true)));
                Assert.That(e.Message, Is.EqualTo("the simulation failed"));
                Assert.That(File.ReadAllText(path), Is.EqualTo(before), "the 50-frame session is untouched");
                Assert.That(Directory.GetFiles(Path.GetDirectoryName(path), "." + Path.GetFileName(path) + ".*"), Is.Empty, "no temporary file is left (.NAME.PID-RANDOM.tmp)");
                using (var r = SessionReader.Open(path))
                {
                    var f = r.CreateFrame();
                    int n = 0;
                    while (r.ReadFrame(f)) n++;
                    Assert.That(n, Is.EqualTo(50));
                }
            }
            finally { File.Delete(path); }
        }

        [Test]
        public void ASerialThatIsTheNoSerialMarkIsRefused()
        {
            // "-" is how the format writes no serial; written as it is, a serial "-" read back as none (found in review).
            var header = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "-") });
            var e = Assert.Throws<ArgumentException>(() => new SessionWriter(new System.IO.StringWriter(), header).Dispose());
            StringAssert.Contains("Serial '-'", e.Message);
            // A device without a serial is written as "-" and reads back without one.
            var text = new System.IO.StringWriter();
            using (var writer = new SessionWriter(text, new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "") }))) { }
            using var reader = new SessionReader(new System.IO.StringReader(text.ToString()), "s");
            Assert.That(reader.Header.Devices[0].Serial, Is.EqualTo(""));
        }

        [Test]
        public void WriterRejectsInvalidTrackedPosesAndTimeGoingBack()
        {
            SessionHeader h = Header();
            using var w = new SessionWriter(new StringWriter(), h);
            var f = new SessionFrame(h);
            Fill(f, 1, new Random(1));
            f.Samples[0] = new DeviceSample(new RigidPose(Vector3.Zero, new Quaternion(0, 0, 0, 0)), true);
            Assert.Throws<ArgumentException>(() => w.WriteFrame(f));
            Fill(f, 5, new Random(1));
            w.WriteFrame(f);
            Fill(f, 4, new Random(1));
            Assert.Throws<ArgumentException>(() => w.WriteFrame(f));
        }
    }
}
