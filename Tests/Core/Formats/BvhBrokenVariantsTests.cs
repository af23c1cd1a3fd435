using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// More hand-broken variants of a real clip (from the parallel BVH work): each must give a one-line
    /// FormatException of the form <c>source:LINE: problem</c>; the line conventions here are this reader's.
    /// </summary>
    public class BvhBrokenVariantsTests
    {
        private static List<string> Lines()
        {
            string text = File.ReadAllText(TestData.Mocap("mixamo_fingers_30fps.bvh"));
            return new List<string>(text.Replace("\r\n", "\n").TrimEnd('\n').Split('\n'));
        }

        private static int IndexOf(List<string> lines, Func<string, bool> match)
        {
            for (int i = 0; i < lines.Count; i++) if (match(lines[i])) return i;
            throw new InvalidOperationException("test setup: line not found");
        }

        private static int MotionLine(List<string> lines) => IndexOf(lines, l => l.Trim() == "MOTION");

        // Each case edits the clip and returns the 0-based index of the line the error must name.
        private static int Break(string kind, List<string> lines)
        {
            int motion = MotionLine(lines);
            int lastFrame = lines.Count - 1;
            switch (kind)
            {
                case "truncated hierarchy":
                    lines.RemoveRange(100, lines.Count - 100);
                    return 99;
                case "truncated motion":
                    lines.RemoveRange(lines.Count - 5, 5);
                    return lines.Count - 1;
                case "missing HIERARCHY":
                    lines.RemoveAt(0);
                    return 0;
                case "missing MOTION":
                    lines.RemoveAt(motion);
                    return motion; // the Frames: line that moved up
                case "wrong channel count":
                {
                    int i = IndexOf(lines, l => l.Contains("CHANNELS 3"));
                    lines[i] = lines[i].Replace("CHANNELS 3", "CHANNELS 4");
                    return i;
                }
                case "unknown channel":
                {
                    int i = IndexOf(lines, l => l.Contains("CHANNELS 3"));
                    lines[i] = lines[i].Replace("Yrotation", "Wrotation");
                    return i;
                }
                case "non-numeric offset":
                {
                    int i = IndexOf(lines, l => l.Contains("OFFSET"));
                    lines[i] = lines[i].Replace("OFFSET", "OFFSET x");
                    return i;
                }
                case "non-numeric value":
                {
                    int i = motion + 10;
                    lines[i] = "abc " + lines[i].Substring(lines[i].IndexOf(' ') + 1);
                    return i;
                }
                case "too few values":
                {
                    int i = motion + 20;
                    lines[i] = lines[i].Substring(0, lines[i].TrimEnd().LastIndexOf(' '));
                    return i;
                }
                case "too many values":
                    lines[motion + 5] += " 1.5";
                    return motion + 5;
                case "negative frame time":
                    lines[motion + 2] = "Frame Time: -0.0333";
                    return motion + 2;
                case "NaN frame time":
                    lines[motion + 2] = "Frame Time:\tNaN";
                    return motion + 2;
                case "missing frame time":
                    lines.RemoveAt(motion + 2);
                    return motion + 2; // the first frame line, where 'Frame Time:' was expected
                case "non-numeric frame count":
                    lines[motion + 1] = "Frames: many";
                    return motion + 1;
                case "more frames declared":
                    lines[motion + 1] = "Frames: 70";
                    return lastFrame;
                case "huge frame count":
                    // 700,000 frames of 168 channels fit the reader's limit of values: memory grows with the frame
                    // lines read, and the file fails where it ends.
                    lines[motion + 1] = "Frames: 700000";
                    return lastFrame;
                case "frame count beyond the limit":
                    // 10,000,000 × 168 values cannot be held: refused at once, at the Frames line.
                    lines[motion + 1] = "Frames: 10000000";
                    return motion + 1;
                case "offset beyond float range":
                {
                    int i = IndexOf(lines, l => l.Contains("OFFSET"));
                    lines[i] = lines[i].Replace("OFFSET", "OFFSET 1e39");
                    return i;
                }
                case "fewer frames declared":
                    lines[motion + 1] = "Frames: 68";
                    return lastFrame;
                case "unclosed joint":
                    lines.RemoveAt(motion - 1);
                    return motion - 1; // MOTION, one line up
                case "duplicate joint":
                {
                    int i = IndexOf(lines, l => l.Contains("JOINT mixamorig:Spine1"));
                    lines[i] = lines[i].Replace("Spine1", "Spine");
                    return i;
                }
                case "End without Site":
                {
                    int i = IndexOf(lines, l => l.Trim() == "End Site");
                    lines[i] = lines[i].Replace("End Site", "End Point");
                    return i;
                }
                case "empty":
                    lines.Clear();
                    return 0;
                default:
                    throw new ArgumentException(kind);
            }
        }

        [TestCase("truncated hierarchy")]
        [TestCase("truncated motion")]
        [TestCase("missing HIERARCHY")]
        [TestCase("missing MOTION")]
        [TestCase("wrong channel count")]
        [TestCase("unknown channel")]
        [TestCase("non-numeric offset")]
        [TestCase("non-numeric value")]
        [TestCase("too few values")]
        [TestCase("too many values")]
        [TestCase("negative frame time")]
        [TestCase("NaN frame time")]
        [TestCase("missing frame time")]
        [TestCase("non-numeric frame count")]
        [TestCase("more frames declared")]
        [TestCase("fewer frames declared")]
        [TestCase("huge frame count")]
        [TestCase("frame count beyond the limit")]
        [TestCase("offset beyond float range")]
        [TestCase("unclosed joint")]
        [TestCase("duplicate joint")]
        [TestCase("End without Site")]
        [TestCase("empty")]
        public void BrokenClipThrowsFormatExceptionNamingSourceAndLine(string kind)
        {
            List<string> lines = Lines();
            int line = Break(kind, lines) + 1;
            string text = string.Join("\n", lines) + (lines.Count > 0 ? "\n" : "");
            var e = Assert.Throws<FormatException>(() => BvhReader.Read(new StringReader(text), "broken.bvh"));
            var m = System.Text.RegularExpressions.Regex.Match(e.Message, @"^broken\.bvh:(\d+): (.+)$");
            Assert.That(m.Success, Is.True, $"{kind}: '{e.Message}'");
            // The line named is where the problem is, or, when the file ends early, the line after the last one.
            int named = int.Parse(m.Groups[1].Value);
            Assert.That(Math.Abs(named - line), Is.LessThanOrEqualTo(1), $"{kind}: expected about line {line}: {e.Message}");
            Assert.That(m.Groups[2].Value.Length, Is.GreaterThan(5), "the message explains the problem");
        }

        [Test]
        public void EveryTruncationThrowsOnlyFormatException()
        {
            // Cutting the file anywhere before its last line leaves fewer frames than 'Frames:' declares (or a
            // broken hierarchy or header), so every cut must give a FormatException, never another exception type.
            string text = string.Join("\n", Lines());
            int lastLine = text.LastIndexOf('\n');
            for (int cut = 0; cut < lastLine; cut += 97)
            {
                try
                {
                    BvhReader.Read(new StringReader(text.Substring(0, cut)), "cut");
                    Assert.Fail($"a cut at {cut} of {text.Length} characters was accepted");
                }
                catch (FormatException e)
                {
                    Assert.That(e.Message, Does.StartWith("cut:"));
                }
            }
        }
    }
}
