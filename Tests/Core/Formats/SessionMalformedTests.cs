using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>Hand-broken variants of a valid session: each must fail with a FormatException naming its line.</summary>
    public class SessionMalformedTests
    {
        private static List<string> ValidLines()
        {
            var h = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H"), new DeviceInfo(1, DeviceClass.Tracker, "T") });
            var text = new StringWriter();
            using (var w = new SessionWriter(text, h))
            {
                var f = new SessionFrame(h);
                for (int i = 0; i < 5; i++)
                {
                    f.Clear();
                    f.Time = i * 0.1;
                    f.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 1.7f, 0), Quaternion.Identity), true);
                    f.Samples[1] = new DeviceSample(new RigidPose(new Vector3(0, 1, 0), Rotations.AngleAxis(30, Vector3.UnitY)), true);
                    if (i == 2) f.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerPressed));
                    w.WriteFrame(f);
                }
            }
            return text.ToString().TrimEnd('\n').Split('\n').ToList();
        }

        private static int IndexOf(List<string> lines, string prefix, int nth = 0) =>
            lines.Select((l, i) => (l, i)).Where(x => x.l.StartsWith(prefix)).ElementAt(nth).i;

        private static void AssertFailsAtLine(List<string> lines, int line, string because, string lineEnd = "")
        {
            var e = Assert.Throws<FormatException>(() =>
            {
                using var r = new SessionReader(new StringReader(string.Join("\n", lines) + lineEnd), "broken.agsession");
                var f = r.CreateFrame();
                while (r.ReadFrame(f)) { }
            }, because);
            StringAssert.StartsWith($"broken.agsession:{line}: ", e.Message, because);
        }

        [Test]
        public void TheValidOneReads()
        {
            Assert.That(CountFrames(ValidLines(), "ok"), Is.EqualTo(5));
        }

        // Reads a whole session from its lines and returns how many frames it has.
        private static int CountFrames(List<string> lines, string name)
        {
            using var r = new SessionReader(new StringReader(string.Join("\n", lines)), name);
            var f = r.CreateFrame();
            int n = 0;
            while (r.ReadFrame(f)) n++;
            return n;
        }

        [Test]
        public void TruncatedMidFrameLine()
        {
            var l = ValidLines();
            int i = IndexOf(l, "pose 1", 3);
            l[i] = l[i].Substring(0, l[i].Length - 12);
            AssertFailsAtLine(l.Take(i + 1).ToList(), i + 1, "pose line cut");
        }

        [Test]
        public void TruncatedBetweenFrames()
        {
            var l = ValidLines();
            int i = IndexOf(l, "frame", 4);
            AssertFailsAtLine(l.Take(i).ToList(), i + 1, "no end line", "\n");
            AssertFailsAtLine(l.Take(i).ToList(), i, "the text stops inside the last frame's last line (no line end)");
            AssertFailsAtLine(l.Take(i + 2).ToList(), i + 3, "last frame lacks device 1");
        }

        [Test]
        public void HeaderProblems()
        {
            var l = ValidLines();
            AssertFailsAtLine(l.Skip(1).ToList(), 1, "no magic line");
            l = ValidLines(); l[0] = "avatargo-session 2.0";
            AssertFailsAtLine(l, 1, "unknown major version");
            l = ValidLines(); l.RemoveAt(IndexOf(l, "rate"));
            AssertFailsAtLine(l, IndexOf(l, "end-header") + 1, "no rate");
            l = ValidLines();
            AssertFailsAtLine(l.Take(IndexOf(l, "end-header")).ToList(), IndexOf(l, "end-header") + 1, "header without end");
            l = ValidLines(); l[IndexOf(l, "device 1")] = "device 1 drone T none";
            AssertFailsAtLine(l, IndexOf(l, "device 1") + 1, "unknown device class");
            AssertFailsAtLine(new List<string>(), 1, "empty");
        }

        [Test]
        public void FrameContentProblems()
        {
            var l = ValidLines(); int i = IndexOf(l, "pose 0", 1);
            l[i] = l[i] + " 1";
            AssertFailsAtLine(l, i + 1, "wrong field count");
            l = ValidLines(); i = IndexOf(l, "pose 0", 1);
            l[i] = l[i].Replace("1.7", "one");
            AssertFailsAtLine(l, i + 1, "non-numeric");
            l = ValidLines(); i = IndexOf(l, "pose 1", 2);
            l[i] = l[i].Replace("pose 1", "pose 5");
            AssertFailsAtLine(l, i + 1, "unknown device id");
            l = ValidLines(); i = IndexOf(l, "frame", 3);
            l[i] = "frame 0.05";
            AssertFailsAtLine(l, i + 1, "time goes back");
            l = ValidLines(); i = IndexOf(l, "pose 0", 2);
            l[i] = "pose 0 tracked 0 1.7 0 0 0 0 0";
            AssertFailsAtLine(l, i + 1, "zero quaternion on a tracked pose");
            l = ValidLines(); i = IndexOf(l, "event");
            l[i] = "event 1 sneeze";
            AssertFailsAtLine(l, i + 1, "unknown event");
            l = ValidLines(); i = l.Count - 1;
            l[i] = "end 4";
            AssertFailsAtLine(l, i + 1, "end count disagrees");
        }

        [Test]
        public void MoreFrameContentProblems()
        {
            var l = ValidLines(); int i = IndexOf(l, "pose 1", 1);
            l[i] = "pose 1 tracked 0 NaN 0 0 0 0 1";
            AssertFailsAtLine(l, i + 1, "NaN position");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l[i] = "pose 1 tracked 0 1 0 0 0 0 1e40";
            AssertFailsAtLine(l, i + 1, "overflows a float");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l[i] = "pose 1 tracked 0 1 0 0 0 0 0.9";
            AssertFailsAtLine(l, i + 1, "not a unit quaternion");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l.Insert(i + 1, l[i]);
            AssertFailsAtLine(l, i + 2, "two poses of one device");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l.Insert(i + 1, "input 1 0.5 1.5");
            AssertFailsAtLine(l, i + 2, "analog value above 1");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l.Insert(i + 1, "input 1 0.5 -"); l.Insert(i + 2, "input 1 0.5 -");
            AssertFailsAtLine(l, i + 3, "two input lines");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l.Insert(i + 1, "truth LeftElbow 0 1 0 0 0 0 1");
            AssertFailsAtLine(l, i + 2, "not a HumanBodyBones name");
            l = ValidLines(); i = IndexOf(l, "pose 1", 1);
            l.Insert(i + 1, "wobble 3");
            AssertFailsAtLine(l, i + 2, "unknown line in this minor version");
            l = ValidLines(); i = IndexOf(l, "frame", 1);
            l[i] = "frame Infinity";
            AssertFailsAtLine(l, i + 1, "infinite time");
            l = ValidLines(); i = l.Count - 1;
            l.Add("frame 9");
            AssertFailsAtLine(l, i + 2, "content after the end line");
        }

        [Test]
        public void MoreHeaderProblems()
        {
            var l = ValidLines(); int i = IndexOf(l, "rate");
            l[i] = "rate 1e300";
            AssertFailsAtLine(l, i + 1, "rate overflows a float");
            l = ValidLines(); i = IndexOf(l, "rate");
            l[i] = "rate 0";
            AssertFailsAtLine(l, i + 1, "zero rate");
            l = ValidLines(); i = IndexOf(l, "device 1");
            l.Insert(i + 1, "device 1 tracker X none");
            AssertFailsAtLine(l, i + 2, "device id used twice");
            l = ValidLines(); i = IndexOf(l, "end-header");
            l.Insert(i, "truth-role 0 head");
            AssertFailsAtLine(l, i + 2, "a true role for device 0 only (reported at end-header)");
            l = ValidLines(); i = IndexOf(l, "end-header");
            l.Insert(i, "truth-joint 0 -1 Hips joint Hips 0 1 0 0 0 0 1");
            l.Insert(i + 1, "truth-joint 1 0 - joint Hips 0 1 0 0 0 0 1");
            AssertFailsAtLine(l, i + 2, "joint name used twice");
            l = ValidLines(); i = IndexOf(l, "end-header");
            l.Insert(i, "truth-joint 0 -1 Hips joint Hips 0 1 0 0 0 0 1");
            l.Insert(i + 1, "truth-joint 1 3 - joint Spine 0 1 0 0 0 0 1");
            AssertFailsAtLine(l, i + 2, "parent after child");
            l = ValidLines(); i = IndexOf(l, "rate");
            l.Insert(i + 1, "rate 72");
            AssertFailsAtLine(l, i + 2, "a second rate line");
            l = ValidLines(); l[0] = "avatargo-session 1";
            AssertFailsAtLine(l, 1, "version without minor");
            l = ValidLines(); l[0] = "bvh-session 1.0";
            AssertFailsAtLine(l, 1, "another format");
        }

        [Test]
        public void ErrorsAreOneLineAndNameSourceLineAndVersion()
        {
            var l = ValidLines(); l[0] = "avatargo-session 3.1";
            var e = Assert.Throws<FormatException>(() => new SessionReader(new StringReader(string.Join("\n", l)), "future.agsession"));
            Assert.That(e.Message, Is.EqualTo("future.agsession:1: format version 3.1 is not supported (this reader reads 1.x)"));
        }

        [Test]
        public void ANewerMinorVersionsUnknownLinesAreSkipped()
        {
            var l = ValidLines(); l[0] = "avatargo-session 1.7";
            l.Insert(IndexOf(l, "end-header"), "colour 0 red");
            int i = IndexOf(l, "pose 1", 2);
            l.Insert(i + 1, "haptics 1 0.5 0.1");
            Assert.That(CountFrames(l, "newer"), Is.EqualTo(5));
        }

        [Test]
        public void CrlfTabsCommentsAndNoFinalNewlineReadTheSame()
        {
            var l = ValidLines();
            var edited = new List<string>();
            for (int i = 0; i < l.Count; i++)
            {
                if (i == 3) edited.Add("# a comment line");
                if (i == 6) edited.Add("   ");
                edited.Add(i % 2 == 0 ? l[i].Replace(" ", " \t ") : l[i]);
            }
            string lf = string.Join("\n", l) + "\n", crlf = string.Join("\r\n", edited);
            using var a = new SessionReader(new StringReader(lf), "lf");
            using var b = new SessionReader(new StringReader(crlf), "crlf");
            SessionFrame fa = a.CreateFrame(), fb = b.CreateFrame();
            int n = 0;
            while (a.ReadFrame(fa))
            {
                Assert.That(b.ReadFrame(fb), Is.True);
                Assert.That(fb.Time, Is.EqualTo(fa.Time));
                for (int d = 0; d < 2; d++) Assert.That(fb.Samples[d].Pose.Rotation, Is.EqualTo(fa.Samples[d].Pose.Rotation));
                Assert.That(fb.Events.Count, Is.EqualTo(fa.Events.Count));
                n++;
            }
            Assert.That(b.ReadFrame(fb), Is.False);
            Assert.That(n, Is.EqualTo(5));
        }

        /// <summary>
        /// Found in review: a file starting with a UTF-8 byte-order mark (Windows Notepad's UTF-8) read through
        /// SessionReader.Open or BvhReader.ReadFile (a StreamReader drops the mark), but text handed over as a string (a
        /// TextAsset's text, the Import menu's plan from a reader) was refused with "expected 'avatargo-session 1.0', found
        /// 'avatargo-session'" (the mark invisible in the quote), and "expected HIERARCHY, found 'HIERARCHY'" for BVH. Now
        /// a mark at the start of the text is skipped by both readers, as the stream does.
        /// </summary>
        [Test]
        public void AByteOrderMarkReadsAsTheFileDoes()
        {
            string text = string.Join("\n", ValidLines()) + "\n";
            using (var r = new SessionReader(new StringReader("\uFEFF" + text), "bom.agsession"))
            {
                SessionFrame f = r.CreateFrame();
                int n = 0;
                while (r.ReadFrame(f)) n++;
                Assert.That(n, Is.EqualTo(5));
            }
            RecordingImportPlan plan = RecordingImport.Plan("bom.txt", new StringReader("\uFEFF" + text));
            Assert.That(plan.IsValid, Is.True, plan.Error);
            Assert.That(plan.Kind, Is.EqualTo(RecordingFileKind.Session));
            // Only at the very start: elsewhere it is not white space and stays an error.
            var l = ValidLines();
            l[1] = "\uFEFF" + l[1];
            AssertFailsAtLine(l, 2, "a mark inside the text");

            string bvh = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip plain = BvhReader.Read(new StringReader(bvh), "plain.bvh"), marked = BvhReader.Read(new StringReader("\uFEFF" + bvh), "bom.bvh");
            Assert.That(marked.FrameCount, Is.EqualTo(plain.FrameCount));
            Assert.That(marked.ChannelCount, Is.EqualTo(plain.ChannelCount));
            Assert.That(marked.GetValue(marked.FrameCount - 1, marked.ChannelCount - 1), Is.EqualTo(plain.GetValue(plain.FrameCount - 1, plain.ChannelCount - 1)));
            Assert.That(RecordingImport.Plan("bom.bvh.txt", new StringReader("\uFEFF" + bvh)).IsValid, Is.True);
        }

        [Test]
        public void ARotationSlightlyOffUnitIsRenormalisedAndAZeroOneInALostSampleBecomesIdentity()
        {
            var l = ValidLines(); int i = IndexOf(l, "pose 1", 1);
            l[i] = "pose 1 tracked 0 1 0 0 0.6006 0 0.8";
            int j = IndexOf(l, "pose 0", 1);
            l[j] = "pose 0 lost 0 1.7 0 0 0 0 0";
            using var r = new SessionReader(new StringReader(string.Join("\n", l)), "renorm");
            var f = r.CreateFrame();
            r.ReadFrame(f); r.ReadFrame(f);
            Assert.That(f.Samples[1].Pose.Rotation.Length(), Is.EqualTo(1f).Within(1e-6f), "renormalised");
            Assert.That(f.Samples[1].Pose.Rotation.Y, Is.EqualTo(0.6006f / MathF.Sqrt(0.6006f * 0.6006f + 0.64f)).Within(1e-6f));
            Assert.That(f.Samples[0].Pose.Rotation, Is.EqualTo(Quaternion.Identity));
            Assert.That(f.Samples[0].Pose.Position, Is.EqualTo(new Vector3(0, 1.7f, 0)), "a lost sample keeps its position");
        }

        [Test]
        public void ATruncatedRecordingGivesEveryWholeFrameThenKeepsFailing()
        {
            // A recorder that crashed: the file stops after frame 3's lines (and their line ends), with no 'end' line.
            var l = ValidLines();
            int cut = IndexOf(l, "frame", 3);
            using var r = new SessionReader(new StringReader(string.Join("\n", l.Take(cut)) + "\n"), "crash.agsession");
            var f = r.CreateFrame();
            int n = 0;
            FormatException e = null;
            try { while (r.ReadFrame(f)) n++; }
            catch (FormatException x) { e = x; }
            Assert.That(n, Is.EqualTo(3), "frames 0..2 are whole and delivered");
            Assert.That(e, Is.Not.Null);
            StringAssert.StartsWith($"crash.agsession:{cut + 1}: ", e.Message);
            var again = Assert.Throws<FormatException>(() => r.ReadFrame(f));
            Assert.That(again.Message, Is.EqualTo(e.Message), "a failed reader does not carry on from an unreliable position");
        }

        /// <summary>
        /// Found in review: a recording cut by a crash anywhere in its text gave, as its last frame, values that were never
        /// recorded: cut inside the last number of a frame's last line ("input 1 0.31 0.95" cut to "input 1 0.31 0.9", a
        /// quaternion's W cut to "0.965"), the line still parsed and the frame was delivered with grip 0.9 or a rotation
        /// 0.03° off; SessionPlayback delivers it to the avatar. Now a frame the text ends in the middle of a line is refused
        /// (only the end line may lack its line end), so every frame delivered holds only what was written; a frame cut at
        /// a line end may only lack optional lines (analog values not given, events that never came).
        /// </summary>
        [Test]
        public void ARecordingCutAnywhereDeliversOnlyWhatWasWritten()
        {
            var h = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H"), new DeviceInfo(1, DeviceClass.Controller, "C") });
            var written = new List<SessionFrame>();
            var text = new StringWriter();
            using (var w = new SessionWriter(text, h))
                for (int i = 0; i < 4; i++)
                {
                    var f = new SessionFrame(h) { Time = i / 90.0 };
                    f.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0.1f * i, 1.7f, 0.25f), Rotations.AngleAxis(30 + i, Vector3.UnitY)), true);
                    f.Samples[1] = new DeviceSample(new RigidPose(new Vector3(0.3f, 1.2f, 0.4f), Rotations.AngleAxis(30, Vector3.UnitY)), true);
                    f.Trigger[1] = 0.31f;
                    f.Grip[1] = 0.95f;
                    if (i == 2) f.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerPressed));
                    w.WriteFrame(f);
                    written.Add(f);
                }
            string whole = text.ToString();
            int body = whole.IndexOf("frame ", StringComparison.Ordinal);
            int delivered = 0;
            for (int cut = body; cut < whole.Length - 1; cut++) // the whole file but its last line end reads whole
            {
                using var r = new SessionReader(new StringReader(whole.Substring(0, cut)), "cut.agsession");
                SessionFrame f = r.CreateFrame();
                try
                {
                    for (int i = 0; r.ReadFrame(f); i++)
                    {
                        delivered++;
                        SessionFrame expected = written[i];
                        string where = $"cut at character {cut}, frame {i}";
                        Assert.That(f.Time, Is.EqualTo(expected.Time), where);
                        for (int d = 0; d < 2; d++)
                        {
                            Assert.That(f.Samples[d].IsTracked, Is.EqualTo(expected.Samples[d].IsTracked), where);
                            Assert.That(f.Samples[d].Pose.Position, Is.EqualTo(expected.Samples[d].Pose.Position), where);
                            Assert.That(f.Samples[d].Pose.Rotation, Is.EqualTo(expected.Samples[d].Pose.Rotation), where);
                            Assert.That(float.IsNaN(f.Trigger[d]) || f.Trigger[d] == expected.Trigger[d], Is.True, $"{where}: trigger {f.Trigger[d]}");
                            Assert.That(float.IsNaN(f.Grip[d]) || f.Grip[d] == expected.Grip[d], Is.True, $"{where}: grip {f.Grip[d]}");
                        }
                        Assert.That(f.Events.Count, Is.LessThanOrEqualTo(expected.Events.Count), where);
                    }
                    Assert.Fail($"cut at character {cut}: a file without its end line read whole");
                }
                catch (FormatException e)
                {
                    StringAssert.StartsWith("cut.agsession:", e.Message);
                    // Said to be a cut, not damage (found in review: a quaternion's W "0.2" cut to "0" was "not a unit quaternion").
                    StringAssert.EndsWith("truncated?)", e.Message, $"cut at character {cut}");
                }
            }
            Assert.That(delivered, Is.GreaterThan(0), "the whole frames before a cut are delivered");
        }

        [Test]
        public void RandomDamageNeverGivesAnotherExceptionType()
        {
            // 3000 randomly damaged copies (a character deleted, replaced or inserted, a line dropped or doubled,
            // the text cut anywhere): each either reads or fails with a FormatException naming a line; never
            // IndexOutOfRange, ArgumentException or the like.
            var valid = ValidLines();
            valid.Insert(IndexOf(valid, "end-header"), "truth-joint 0 -1 Hips joint Hips 0 1 0 0 0 0 1");
            valid.Insert(IndexOf(valid, "end-header"), "truth-joint 1 0 Head end Head 0 0.6 0 0 0 0 1");
            valid.Insert(IndexOf(valid, "pose 1", 2) + 1, "truth Head 0 1.6 0 0 0 0 1");
            valid.Insert(IndexOf(valid, "pose 1", 3) + 1, "input 1 0.25 -");
            string text = string.Join("\n", valid) + "\n";
            const string alphabet = " \t\n\r#-.0123456789eEaNfIlosttrackedpose";
            var rng = new Random(1234);
            int failures = 0;
            for (int n = 0; n < 3000; n++)
            {
                var damaged = new System.Text.StringBuilder(text);
                int edits = 1 + rng.Next(3);
                for (int k = 0; k < edits && damaged.Length > 0; k++)
                {
                    int at = rng.Next(damaged.Length);
                    switch (rng.Next(5))
                    {
                        case 0: damaged.Remove(at, 1); break;
                        case 1: damaged[at] = alphabet[rng.Next(alphabet.Length)]; break;
                        case 2: damaged.Insert(at, alphabet[rng.Next(alphabet.Length)]); break;
                        case 3: damaged.Length = at; break;
                        default:
                            var lines = damaged.ToString().Split('\n').ToList();
                            int li = rng.Next(lines.Count);
                            if (rng.Next(2) == 0) lines.RemoveAt(li); else lines.Insert(li, lines[li]);
                            damaged.Clear().Append(string.Join("\n", lines));
                            break;
                    }
                }
                try
                {
                    using var r = new SessionReader(new StringReader(damaged.ToString()), "fuzz");
                    var f = r.CreateFrame();
                    while (r.ReadFrame(f))
                        for (int d = 0; d < f.Samples.Length; d++)
                            Assert.That(f.Samples[d].Pose.IsValid, Is.True, "every delivered pose is valid, tracked or not");
                }
                catch (FormatException e)
                {
                    failures++;
                    StringAssert.IsMatch(@"^fuzz:\d+: \S", e.Message);
                }
            }
            Assert.That(failures, Is.GreaterThan(2000), "most damage is detected (the rest: e.g. a changed digit)");
        }

        [Test]
        public void UntrackedZeroQuaternionIsAccepted()
        {
            var l = ValidLines(); int i = IndexOf(l, "pose 0", 2);
            l[i] = "pose 0 lost 0 0 0 0 0 0 0";
            using var r = new SessionReader(new StringReader(string.Join("\n", l)), "lost");
            var f = r.CreateFrame();
            r.ReadFrame(f); r.ReadFrame(f); r.ReadFrame(f);
            Assert.That(f.Samples[0].IsTracked, Is.False);
            Assert.That(f.Samples[0].Pose.IsValid, Is.True, "a lost pose is replaced by a valid one");
        }
    }
}
