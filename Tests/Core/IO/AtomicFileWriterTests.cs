using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text;
using System.Threading;
using System.Threading.Tasks;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Nothing is lost: every file the package writes goes through <see cref="AtomicFileWriter"/>, so a failed write
    /// leaves the previous file byte for byte as it was and no temporary file behind, leftovers of killed writers are
    /// cleaned by the next write, and concurrent writers of one file never fail. (Unix permissions, symbolic links and a
    /// writer process killed mid-write are tested in Tools~, where .NET 7+ and child processes are available.)
    /// </summary>
    public class AtomicFileWriterTests
    {
        private string _dir;

        [SetUp]
        public void MakeFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "avatargo-atomic-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder()
        {
            if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        private string Existing(string name, string content)
        {
            string path = Path.Combine(_dir, name);
            File.WriteAllText(path, content);
            return path;
        }

        private void AssertOnlyFiles(params string[] names) =>
            Assert.That(Directory.GetFiles(_dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal), Is.EqualTo(names.OrderBy(n => n, StringComparer.Ordinal)), "no temporary file left behind");

        [Test]
        public void AWriteThatThrowsMidwayLeavesTheOldFileByteIdenticalAndNoTemporaryFile()
        {
            string path = Existing("clip.bvh", "the previous clip\n");
            byte[] before = File.ReadAllBytes(path);
            Assert.Throws<InvalidOperationException>(() => AtomicFileWriter.WriteText(path, w =>
            {
                w.Write(new string('x', 200000)); // past the buffers: bytes have reached the temporary file
                throw new InvalidOperationException("the disk is full (simulated)");
            }));
            Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
            AssertOnlyFiles("clip.bvh");
        }

        [Test]
        public void ACommittedWriteReplacesTheFileWhole()
        {
            string path = Existing("a.txt", "old");
            AtomicFileWriter.WriteAllText(path, "new content");
            Assert.That(File.ReadAllText(path), Is.EqualTo("new content"));
            AtomicFileWriter.WriteAllText(Path.Combine(_dir, "b.txt"), "first");
            Assert.That(File.ReadAllText(Path.Combine(_dir, "b.txt")), Is.EqualTo("first"));
            AssertOnlyFiles("a.txt", "b.txt");
        }

        [Test]
        public void AnAbandonedWriterDeletesItsTemporaryFile()
        {
            string path = Existing("p.json", "{}");
            string temporary;
            using (var w = new AtomicFileWriter(path))
            {
                w.Stream.Write(new byte[] { 1, 2, 3 }, 0, 3);
                temporary = w.TemporaryPath;
                Assert.That(File.Exists(temporary), Is.True);
                StringAssert.StartsWith(".p.json.", Path.GetFileName(temporary));
            }
            Assert.That(File.Exists(temporary), Is.False);
            Assert.That(File.ReadAllText(path), Is.EqualTo("{}"));
        }

        [Test]
        public void TheNextWriteDeletesTemporaryFilesOfProcessesThatAreGoneAndKeepsLiveOnes()
        {
            string path = Existing("wearer.json", "old");
            // A writer killed mid-write leaves .NAME.PID-RANDOM.tmp behind; no process has this id.
            string dead = Path.Combine(_dir, ".wearer.json.2147483646-0123456789abcdef0123456789abcdef.tmp");
            File.WriteAllText(dead, "half a profile");
            string unrelated = Path.Combine(_dir, ".wearer.json.backup.tmp");
            File.WriteAllText(unrelated, "not ours");
            using (var live = new AtomicFileWriter(path)) // a writer of this process still at work
            {
                AtomicFileWriter.WriteAllText(path, "new");
                Assert.That(File.Exists(dead), Is.False, "the dead writer's leftover is gone");
                Assert.That(File.Exists(live.TemporaryPath), Is.True, "a live writer's temporary file is kept");
                Assert.That(File.Exists(unrelated), Is.True, "only names of the exact pattern are touched");
            }
            Assert.That(File.ReadAllText(path), Is.EqualTo("new"));
            AssertOnlyFiles("wearer.json", ".wearer.json.backup.tmp");
        }

        [Test]
        public void ConcurrentFirstSavesOfOneProfileNeverFail()
        {
            // Issue 14: "two first saves race" (File.Exists, then File.Move). 8 writers, 25 saves each, to a path that
            // does not exist yet; every save must succeed and the file must be whole, one of the profiles written.
            string path = Path.Combine(_dir, "profile.json");
            var texts = Enumerable.Range(0, 8).Select(i => "{\"writer\": " + i + ", \"pad\": \"" + new string((char)('a' + i), 5000) + "\"}\n").ToArray();
            var failures = new List<Exception>();
            var start = new ManualResetEventSlim();
            var tasks = texts.Select(text => Task.Run(() =>
            {
                start.Wait();
                for (int k = 0; k < 25; k++)
                {
                    try { AtomicFileWriter.WriteAllText(path, text); }
                    catch (Exception e) { lock (failures) failures.Add(e); }
                }
            })).ToArray();
            start.Set();
            Task.WaitAll(tasks);
            Assert.That(failures, Is.Empty, string.Join("\n", failures.Select(f => f.Message)));
            Assert.That(texts, Does.Contain(File.ReadAllText(path)));
            AssertOnlyFiles("profile.json");
        }

        [Test]
        public void ReadOnlyFilesAndFoldersAreRefusedBeforeAnythingIsWritten()
        {
            string path = Existing("locked.json", "keep");
            File.SetAttributes(path, FileAttributes.ReadOnly);
            try
            {
                Assert.Throws<UnauthorizedAccessException>(() => AtomicFileWriter.WriteAllText(path, "new"));
                Assert.That(File.ReadAllText(path), Is.EqualTo("keep"));
            }
            finally { File.SetAttributes(path, FileAttributes.Normal); }
            Directory.CreateDirectory(Path.Combine(_dir, "folder"));
            Assert.Throws<IOException>(() => AtomicFileWriter.WriteAllText(Path.Combine(_dir, "folder"), "x"));
            Assert.Throws<DirectoryNotFoundException>(() => AtomicFileWriter.WriteAllText(Path.Combine(_dir, "missing", "x.json"), "x"));
            AssertOnlyFiles("locked.json");
        }

        [Test]
        public void TemporaryNamesAreRecognisedExactly()
        {
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.123-0123456789abcdef0123456789abcdef.tmp", "a.json"), Is.EqualTo(123));
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.123-0123456789abcdef0123456789abcdef.tmp", "b.json"), Is.EqualTo(-1));
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.123-0123456789ABCDEF0123456789abcdef.tmp", "a.json"), Is.EqualTo(-1));
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.x-0123456789abcdef0123456789abcdef.tmp", "a.json"), Is.EqualTo(-1));
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.123-0123.tmp", "a.json"), Is.EqualTo(-1));
            Assert.That(AtomicFileWriter.TemporaryOwner(".a.json.tmp", "a.json"), Is.EqualTo(-1));
        }

        // ---- The package's writers ---------------------------------------------------------------------

        private static SessionHeader HeaderWithJoint(string jointName)
        {
            var skeleton = new Skeleton(new[] { "Hips", jointName }, new[] { -1, 0 },
                new[] { new RigidPose(new Vector3(0, 1, 0), Quaternion.Identity), new RigidPose(new Vector3(0, 0.5f, 0), Quaternion.Identity) });
            var map = new HumanoidMap(skeleton, new[] { new KeyValuePair<HumanoidBone, string>(HumanoidBone.Hips, "Hips") });
            return new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H") }, null, map);
        }

        [Test]
        public void ASessionWhoseHeaderTheFormatCannotHoldLeavesTheOldFileAsItWas()
        {
            // Issue 14: simulate on a clip with spaces in joint names truncated the existing output to 0 bytes.
            string path = Existing("walk.agsession", "the previous session\n");
            byte[] before = File.ReadAllBytes(path);
            Assert.Throws<ArgumentException>(() => SessionWriter.Create(path, HeaderWithJoint("Left Arm")));
            Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
            AssertOnlyFiles("walk.agsession");
        }

        [Test]
        public void ASessionAppearsOnlyWhenCompleteAndADiscardedOneLeavesTheOldFile()
        {
            string path = Existing("walk.agsession", "the previous session\n");
            byte[] before = File.ReadAllBytes(path);
            SessionHeader header = HeaderWithJoint("Head");
            var frame = new SessionFrame(header);
            using (var writer = SessionWriter.Create(path, header))
            {
                for (int i = 0; i < 2000; i++)
                {
                    frame.Clear();
                    frame.Time = i / 90.0;
                    frame.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 1.7f, 0), Quaternion.Identity), true);
                    writer.WriteFrame(frame);
                }
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(before), "not replaced before the session is complete");
                writer.Discard(); // the caller's own code failed mid-session
            }
            Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
            AssertOnlyFiles("walk.agsession");

            using (var writer = SessionWriter.Create(path, header))
            {
                frame.Clear();
                frame.Samples[0] = new DeviceSample(RigidPose.Identity, true);
                writer.WriteFrame(frame);
            }
            using (var reader = SessionReader.Open(path))
            {
                SessionFrame f = reader.CreateFrame();
                Assert.That(reader.ReadFrame(f), Is.True);
                Assert.That(reader.ReadFrame(f), Is.False);
            }
            AssertOnlyFiles("walk.agsession");
        }

        [Test]
        public void ASessionWhoseTextWriterFailsMidwayCannotBeCompleted()
        {
            SessionHeader header = HeaderWithJoint("Head");
            var failing = new FailingWriter(after: 600);
            var writer = new SessionWriter(failing, header);
            var frame = new SessionFrame(header);
            frame.Samples[0] = new DeviceSample(RigidPose.Identity, true);
            Assert.Throws<IOException>(() => { for (int i = 0; i < 100; i++) { frame.Time = i; writer.WriteFrame(frame); } });
            Assert.Throws<InvalidOperationException>(() => writer.WriteFrame(frame), "a torn session is not continued");
            Assert.Throws<InvalidOperationException>(() => writer.Complete(), "nor completed");
            writer.Dispose();
            StringAssert.DoesNotContain("\nend ", failing.Written.ToString());
        }

        [Test]
        public void AProfileSaveThatFailsLeavesTheOldProfile()
        {
            string path = Existing("wearer.json", "{\"old\": true}");
            byte[] before = File.ReadAllBytes(path);
            Assert.Throws<ArgumentException>(() => CalibrationProfileStore.Save(new CalibrationProfile(), path), "a profile that would not load back");
            Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
            AssertOnlyFiles("wearer.json");
        }

        [Test]
        public void BvhWriteFileIsAtomic()
        {
            var skeleton = new Skeleton(new[] { "Hips", "Head" }, new[] { -1, 0 }, new[] { RigidPose.Identity, new RigidPose(new Vector3(0, 1, 0), Quaternion.Identity) });
            BvhClip clip = BvhClip.FromPoses(skeleton, new[] { new[] { RigidPose.Identity, skeleton.GetRestLocal(1) } }, 1f / 30);
            string path = Existing("out.bvh", "old");
            BvhWriter.WriteFile(path, clip);
            Assert.That(BvhReader.ReadFile(path).Skeleton.JointCount, Is.EqualTo(2));
            AssertOnlyFiles("out.bvh");
        }

        /// <summary>A text writer whose storage fills up after some characters.</summary>
        private sealed class FailingWriter : TextWriter
        {
            private readonly int _after;
            public readonly StringBuilder Written = new StringBuilder();

            public FailingWriter(int after) { _after = after; }

            public override Encoding Encoding => Encoding.UTF8;

            public override void Write(char value)
            {
                if (Written.Length >= _after) throw new IOException("no space left on the device (simulated)");
                Written.Append(value);
            }
        }
    }
}
