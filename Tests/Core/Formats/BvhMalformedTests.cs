using System;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>Hand-broken variants of a real clip: each must fail with a FormatException naming its line.</summary>
    public class BvhMalformedTests
    {
        private static string[] Lines() =>
            File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh")).Replace("\r\n", "\n").TrimEnd('\n').Split('\n');

        private static void AssertFailsAtLine(string text, int expectedLine, string because)
        {
            var e = Assert.Throws<FormatException>(() => BvhReader.Read(new StringReader(text), "broken.bvh"), because);
            StringAssert.StartsWith($"broken.bvh:{expectedLine}: ", e.Message, because);
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), "one-line message");
        }

        private static int LineOf(string[] lines, string startsWith)
        {
            for (int i = 0; i < lines.Length; i++) if (lines[i].TrimStart().StartsWith(startsWith)) return i;
            throw new InvalidOperationException(startsWith);
        }

        [Test]
        public void TruncatedInTheMotion()
        {
            string[] l = Lines();
            int motion = LineOf(l, "MOTION");
            AssertFailsAtLine(string.Join("\n", l, 0, motion + 10), motion + 11, "ends after 7 frames");
        }

        [Test]
        public void TruncatedMidFrameLine()
        {
            string[] l = Lines();
            int motion = LineOf(l, "MOTION");
            l[motion + 5] = l[motion + 5].Substring(0, l[motion + 5].Length / 2);
            AssertFailsAtLine(string.Join("\n", l), motion + 6, "half a frame line");
        }

        [Test]
        public void TruncatedInTheHierarchy()
        {
            string[] l = Lines();
            AssertFailsAtLine(string.Join("\n", l, 0, 40), 41, "hierarchy cut");
        }

        [Test]
        public void WrongChannelCount()
        {
            string[] l = Lines();
            int i = LineOf(l, "CHANNELS 3");
            l[i] = l[i].Replace("CHANNELS 3", "CHANNELS 4");
            AssertFailsAtLine(string.Join("\n", l), i + 1, "4 channels announced, 3 listed");
        }

        [Test]
        public void NonNumericValue()
        {
            string[] l = Lines();
            int motion = LineOf(l, "MOTION");
            l[motion + 4] = Regex.Replace(l[motion + 4], @"^(\S+\s+\S+\s+)\S+", "${1}abc");
            AssertFailsAtLine(string.Join("\n", l), motion + 5, "abc in a frame");
            l = Lines();
            int o = LineOf(l, "OFFSET");
            l[o] = l[o].Replace("0.0000", "zero");
            AssertFailsAtLine(string.Join("\n", l), o + 1, "bad offset");
        }

        [Test]
        public void MissingHeaderOrMotion()
        {
            string[] l = Lines();
            AssertFailsAtLine(string.Join("\n", l, 1, l.Length - 1), 1, "no HIERARCHY");
            int motion = LineOf(l, "MOTION");
            l[motion] = "MOTON";
            AssertFailsAtLine(string.Join("\n", l), motion + 1, "no MOTION");
            AssertFailsAtLine("", 1, "empty file");
        }

        [Test]
        public void FrameCountAndTimeProblems()
        {
            string[] l = Lines();
            int frames = LineOf(l, "Frames:");
            l[frames] = "Frames:\t456";
            AssertFailsAtLine(string.Join("\n", l), l.Length + 1, "one frame short");
            l = Lines();
            l[frames] = "Frames:\t400";
            AssertFailsAtLine(string.Join("\n", l), frames + 2 + 401, "extra frames");
            l = Lines();
            l[frames + 1] = "Frame Time:\t-0.03";
            AssertFailsAtLine(string.Join("\n", l), frames + 2, "negative frame time");
            l = Lines();
            l[frames + 1] = "Frame Time:\tNaN";
            AssertFailsAtLine(string.Join("\n", l), frames + 2, "NaN frame time");
        }

        [Test]
        public void UnknownChannelAndTooManyValues()
        {
            string[] l = Lines();
            int i = LineOf(l, "CHANNELS 3");
            l[i] = l[i].Replace("Xrotation", "Wrotation");
            AssertFailsAtLine(string.Join("\n", l), i + 1, "unknown channel");
            l = Lines();
            int motion = LineOf(l, "MOTION");
            l[motion + 3] += " 1.0";
            AssertFailsAtLine(string.Join("\n", l), motion + 4, "one value too many");
        }
    }
}
