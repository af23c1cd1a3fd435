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
                    f.Samples[0] = new DeviceSample(new Pose(new Vector3(0, 1.7f, 0), Quaternion.Identity), true);
                    f.Samples[1] = new DeviceSample(new Pose(new Vector3(0, 1, 0), Rotations.AngleAxis(30, Vector3.UnitY)), true);
                    if (i == 2) f.Events.Add(new InputEvent(1, InputEventKind.TriggerPressed));
                    w.WriteFrame(f);
                }
            }
            return text.ToString().TrimEnd('\n').Split('\n').ToList();
        }

        private static int IndexOf(List<string> lines, string prefix, int nth = 0) =>
            lines.Select((l, i) => (l, i)).Where(x => x.l.StartsWith(prefix)).ElementAt(nth).i;

        private static void AssertFailsAtLine(List<string> lines, int line, string because)
        {
            var e = Assert.Throws<FormatException>(() =>
            {
                using var r = new SessionReader(new StringReader(string.Join("\n", lines)), "broken.agsession");
                var f = r.CreateFrame();
                while (r.ReadFrame(f)) { }
            }, because);
            StringAssert.StartsWith($"broken.agsession:{line}: ", e.Message, because);
        }

        [Test]
        public void TheValidOneReads()
        {
            using var r = new SessionReader(new StringReader(string.Join("\n", ValidLines())), "ok");
            var f = r.CreateFrame();
            int n = 0;
            while (r.ReadFrame(f)) n++;
            Assert.That(n, Is.EqualTo(5));
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
            AssertFailsAtLine(l.Take(i).ToList(), i + 1, "no end line");
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
