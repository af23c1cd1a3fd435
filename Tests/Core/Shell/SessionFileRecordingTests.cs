using System;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free half of AvatarGoRecorder: a recording streamed to a partial file and moved onto its name when
    /// completed reads back with the session reader as it was fed; until then the target is untouched, and an interrupted
    /// recording leaves its frames readable up to the point where it stopped.
    /// </summary>
    public class SessionFileRecordingTests
    {
        private string _dir;

        [SetUp]
        public void CreateFolder() => Directory.CreateDirectory(_dir = Path.Combine(Path.GetTempPath(), "avatargo-recording-" + Guid.NewGuid().ToString("N")));

        [TearDown]
        public void DeleteFolder() => Directory.Delete(_dir, true);

        /// <summary>
        /// A disk that fills up mid-recording (Linux's /dev/full behind the partial file: every write fails with "no space"):
        /// the frame whose write fails throws an <see cref="IOException"/>, and so does completing the recording afterwards,
        /// as its documentation says, not the writer's <see cref="InvalidOperationException"/> (found in review:
        /// AvatarGoRecorder catches IOException only, so that escaped its Update and the "frames are in" message was lost);
        /// nothing appears at the target.
        /// </summary>
        [Test]
        public void AFullDiskFailsTheRecordingWithAnIOExceptionUpToItsCompletion()
        {
            if (!File.Exists("/dev/full")) Assert.Ignore("needs /dev/full (Linux)");
            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            string path = Path.Combine(_dir, "full.agsession");
#if NET6_0_OR_GREATER
            File.CreateSymbolicLink(path + SessionFileRecording.PartialSuffix, "/dev/full");
#else
            Assert.Ignore("needs File.CreateSymbolicLink (.NET 6 or later; Unity's profile has none)");
#endif
            using SessionReader source = Sessions.Read(session);
            var recording = new SessionFileRecording(path, source.Header);
            SessionFrame frame = source.CreateFrame();
            IOException failed = null;
            while (failed == null && source.ReadFrame(frame))
            {
                try { recording.Record(frame); }
                catch (IOException e) { failed = e; }
            }
            Assert.That(failed, Is.Not.Null, "a frame's write failed once the buffers filled");
            var completing = Assert.Throws<IOException>(() => recording.Complete());
            StringAssert.Contains(recording.PartialPath, completing.Message);
            Assert.That(recording.IsOpen, Is.False);
            Assert.That(File.Exists(path), Is.False, "nothing at the target");
        }

        [Test]
        public void ACompletedRecordingReadsBackAsItWasFed()
        {
            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            string path = Path.Combine(_dir, "sub", AvatarGoFiles.RecordingFileName("test", new DateTime(2024, 5, 6, 7, 8, 9)));
            Assert.That(Path.GetFileName(path), Is.EqualTo("test-20240506-070809.agsession"));
            int fed = 0;
            using (SessionReader source = Sessions.Read(session))
            {
                var recording = new SessionFileRecording(path, source.Header);
                Assert.That(File.Exists(recording.PartialPath), Is.True);
                SessionFrame frame = source.CreateFrame();
                while (source.ReadFrame(frame))
                {
                    frame.Time += 1000.0; // a live clock: the recording starts at 0
                    recording.Record(frame);
                    fed++;
                }
                Assert.That(File.Exists(path), Is.False, "nothing at the target until completed");
                recording.Complete();
                Assert.That(recording.IsOpen, Is.False);
                Assert.That(File.Exists(recording.PartialPath), Is.False);
            }
            using SessionReader original = Sessions.Read(session);
            using SessionReader copy = SessionReader.Open(path);
            Assert.That(copy.Header.Devices.Count, Is.EqualTo(original.Header.Devices.Count));
            SessionFrame a = original.CreateFrame(), b = copy.CreateFrame();
            int frames = 0, events = 0;
            while (original.ReadFrame(a))
            {
                Assert.That(copy.ReadFrame(b), Is.True);
                Assert.That(b.Time, Is.EqualTo(a.Time).Within(1e-6), "times start at 0 like the original's");
                for (int d = 0; d < a.Samples.Length; d++)
                {
                    Assert.That(b.Samples[d].IsTracked, Is.EqualTo(a.Samples[d].IsTracked));
                    if (a.Samples[d].IsTracked) Assert.That(b.Samples[d].Pose, Is.EqualTo(a.Samples[d].Pose));
                    Assert.That(b.Trigger[d], Is.EqualTo(a.Trigger[d]));
                    Assert.That(b.Grip[d], Is.EqualTo(a.Grip[d]));
                }
                Assert.That(b.Events, Is.EqualTo(a.Events));
                events += a.Events.Count;
                frames++;
            }
            Assert.That(copy.ReadFrame(b), Is.False);
            Assert.That(frames, Is.EqualTo(fed));
            Assert.That(events, Is.GreaterThanOrEqualTo(2), "the calibration's presses were recorded");
        }

        [Test]
        public void CompletingReplacesAnOlderFileOfTheSameName()
        {
            string path = Path.Combine(_dir, "take.agsession");
            File.WriteAllText(path, "an older take");
            var header = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H") });
            using (var recording = new SessionFileRecording(path, header))
            {
                var frame = new SessionFrame(header);
                frame.Samples[0] = new DeviceSample(RigidPose.FromPosition(Vector3.UnitY), true);
                recording.Record(frame);
                Assert.That(File.ReadAllText(path), Is.EqualTo("an older take"), "the older take stays until the new one is whole");
            }
            using SessionReader reader = SessionReader.Open(path);
            SessionFrame f = reader.CreateFrame();
            Assert.That(reader.ReadFrame(f), Is.True);
            Assert.That(reader.ReadFrame(f), Is.False);
        }

        [Test]
        public void AnInterruptedRecordingLeavesItsFramesAndTheTargetUntouched()
        {
            string path = Path.Combine(_dir, "crash.agsession");
            var header = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H") });
            var recording = new SessionFileRecording(path, header);
            var frame = new SessionFrame(header);
            for (int i = 0; i < 5000; i++)
            {
                frame.Time = i / 90.0;
                frame.Samples[0] = new DeviceSample(RigidPose.FromPosition(new Vector3(0, 1.6f, i * 1e-3f)), true);
                recording.Record(frame);
            }
            // A crash: the process ends without Complete. What reached the disk is read as it would be afterwards.
            var written = new MemoryStream();
            using (var s = new FileStream(recording.PartialPath, FileMode.Open, FileAccess.Read, FileShare.ReadWrite)) s.CopyTo(written);
            Assert.That(File.Exists(path), Is.False, "the target never existed");
            using (var reader = new SessionReader(new StringReader(System.Text.Encoding.UTF8.GetString(written.ToArray())), "crash.agsession.partial"))
            {
                SessionFrame f = reader.CreateFrame();
                int read = 0;
                var e = Assert.Throws<FormatException>(() => { while (reader.ReadFrame(f)) read++; });
                Assert.That(e.Message, Does.Contain("truncated").Or.Contain("crash.agsession.partial"));
                Assert.That(read, Is.GreaterThan(4000), "all but the last buffers' frames are readable");
            }
            recording.Abandon();
            Assert.That(File.Exists(recording.PartialPath), Is.False);
            Assert.Throws<InvalidOperationException>(() => recording.Record(frame));
        }

        /// <summary>
        /// A serial the format cannot hold (white space in it, or "-", the format's "no serial") does not stop a recording
        /// (before: the recording was refused, and AvatarGoRecorder logged an error and recorded nothing, for a serial the
        /// user cannot change): it is recorded with '_' in place of each white-space character, "-" as "_", and the
        /// recording's header says so; every other device, and every id, class and role, is recorded as it was.
        /// </summary>
        [Test]
        public void ASerialTheFormatCannotHoldIsRecordedWithUnderscores()
        {
            string path = Path.Combine(_dir, "serials.agsession");
            var header = new SessionHeader(90f, new[]
            {
                new DeviceInfo(0, DeviceClass.Hmd, "has space"),
                new DeviceInfo(3, DeviceClass.Controller, "tab\tand\nnewline", DeviceRole.LeftHand),
                new DeviceInfo(5, DeviceClass.Tracker, "-", DeviceRole.Pelvis),
                new DeviceInfo(7, DeviceClass.Tracker, "LHR-1A2B3C4D"),
                new DeviceInfo(8, DeviceClass.Tracker, ""),
            });
            var recording = new SessionFileRecording(path, header);
            Assert.That(recording.Header, Is.Not.SameAs(header), "a copy with the serials as recorded");
            var frame = new SessionFrame(recording.Header);
            for (int d = 0; d < frame.Samples.Length; d++) frame.Samples[d] = new DeviceSample(new RigidPose(new Vector3(d, 1f, 0f), Quaternion.Identity), true);
            recording.Record(frame);
            recording.Complete();
            using SessionReader copy = SessionReader.Open(path);
            string[] serials = { "has_space", "tab_and_newline", "_", "LHR-1A2B3C4D", "" };
            Assert.That(copy.Header.Devices.Count, Is.EqualTo(header.Devices.Count));
            for (int d = 0; d < serials.Length; d++)
            {
                DeviceInfo read = copy.Header.Devices[d], given = header.Devices[d];
                Assert.That(read.Serial, Is.EqualTo(serials[d]), $"device {given.Id}");
                Assert.That(recording.Header.Devices[d].Serial, Is.EqualTo(serials[d]), $"device {given.Id} in the recording's header");
                Assert.That(read.Id, Is.EqualTo(given.Id));
                Assert.That(read.Class, Is.EqualTo(given.Class));
                Assert.That(read.RuntimeRole, Is.EqualTo(given.RuntimeRole));
            }
            SessionFrame back = copy.CreateFrame();
            Assert.That(copy.ReadFrame(back), Is.True);
            Assert.That(back.Samples[4].Pose.Position, Is.EqualTo(new Vector3(4f, 1f, 0f)));
        }

        [Test]
        public void AHeaderWhoseSerialsTheFormatHoldsIsRecordedAsItIs()
        {
            var header = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "LHR-00AA"), new DeviceInfo(1, DeviceClass.Tracker, "") });
            var recording = new SessionFileRecording(Path.Combine(_dir, "plain.agsession"), header);
            Assert.That(recording.Header, Is.SameAs(header));
            recording.Abandon();
        }
    }
}
