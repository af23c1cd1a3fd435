using System;
using System.IO;
using System.Linq;
using System.Text;
using System.Threading;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Issue 14's hostile BVH files, each built from its description: deep nesting, many End Sites, headers claiming
    /// huge motions, long lines and absurd numbers. Each must parse, or fail with the documented one-line
    /// <c>SOURCE:LINE: problem</c>, quickly and without another exception type.
    /// </summary>
    public class BvhHostileInputTests
    {
        private const string Channels3 = "CHANNELS 3 Zrotation Xrotation Yrotation";
        private const string Root = "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";

        private static string Motion(int frames, int channels, int frameLines, string frameTime = "0.0333")
        {
            var sb = new StringBuilder($"MOTION\nFrames: {frames}\nFrame Time: {frameTime}\n");
            string line = string.Join(" ", Enumerable.Repeat("0", channels));
            for (int f = 0; f < frameLines; f++) sb.Append(line).Append('\n');
            return sb.ToString();
        }

        // A chain `depth` joints deep under the root, each with `channels` (e.g. "CHANNELS 0").
        private static string Nested(int depth, string channels)
        {
            var sb = new StringBuilder(Root);
            for (int i = 0; i < depth; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\n").Append(channels).Append('\n');
            for (int i = 0; i < depth; i++) sb.Append("}\n");
            return sb.Append("}\n").ToString();
        }

        private static string EndSites(int count)
        {
            var sb = new StringBuilder(Root);
            for (int i = 0; i < count; i++) sb.Append("End Site\n{\nOFFSET 0 1 0\n}\n");
            return sb.Append("}\n").Append(Motion(1, 6, 1)).ToString();
        }

        private static BvhClip Read(string text, string name = "hostile.bvh") => BvhReader.Read(new StringReader(text), name);

        private static FormatException AssertFailsAtLine(string text, int line, string contains)
        {
            var e = Assert.Throws<FormatException>(() => Read(text));
            StringAssert.StartsWith($"hostile.bvh:{line}: ", e.Message);
            StringAssert.Contains(contains, e.Message);
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), "one line");
            Assert.That(e.Message.Length, Is.LessThan(300), "a short message");
            return e;
        }

        // Runs on a thread with a 256 KB stack: a parser that recursed once per level could not go 60,000 levels deep.
        private static void OnSmallStack(Action action)
        {
            Exception failure = null;
            var thread = new Thread(() =>
            {
                try { action(); }
                catch (Exception e) { failure = e; }
            }, 256 << 10);
            thread.Start();
            thread.Join();
            if (failure != null) throw new AssertionException("on a 256 KB stack: " + failure);
        }

        [Test]
        public void NestingOf100000JointsIsRefusedAtTheJointLimitNotAStackOverflow()
        {
            // Issue 14: "a BVH with deeply nested joints kills the process with a stack overflow".
            string text = Nested(100000, "CHANNELS 0") + Motion(1, 6, 1);
            OnSmallStack(() =>
            {
                // The root is joint 1: joint j65534 is the 65,536th; j65535 (on line 5 + 65535 * 4 + 1) is one too many.
                AssertFailsAtLine(text, 5 + 65535 * 4 + 1, $"more than {BvhReader.MaxJoints} joints");
            });
        }

        [Test]
        public void NestingUpToTheJointLimitReadsAndWritesWithoutRecursion()
        {
            int depth = BvhReader.MaxJoints - 1;
            string text = Nested(depth, "CHANNELS 0") + Motion(2, 6, 2);
            OnSmallStack(() =>
            {
                BvhClip clip = Read(text);
                Assert.That(clip.Skeleton.JointCount, Is.EqualTo(BvhReader.MaxJoints));
                Assert.That(clip.Skeleton.GetParent(clip.Skeleton.JointCount - 1), Is.EqualTo(clip.Skeleton.JointCount - 2));
                Assert.That(clip.Skeleton.IsAncestorOrSelf(0, clip.Skeleton.JointCount - 1), Is.True);
                // The writer and the humanoid naming walk the chain too (indentation stops growing, so the text stays linear).
                var written = new StringWriter();
                BvhWriter.Write(written, clip);
                Assert.That(written.ToString().Length, Is.LessThan(10 * text.Length), "linear in the joints (indentation is capped)");
                Assert.That(Read(written.ToString(), "written.bvh").Skeleton.JointCount, Is.EqualTo(clip.Skeleton.JointCount));
                HumanoidNaming.Detect(clip.Skeleton);
            });
        }

        [Test]
        public void DeepNestingCostsLinearTime()
        {
            Scaling.AssertLinear(depth => Nested(depth, Channels3) + Motion(1, 6 + 3 * depth, 1), text => Read(text), 4000, "reading a chain of joints");
        }

        [Test]
        public void TwentyThousandEndSitesUnderOneJointReadInLinearTime()
        {
            // Issue 14: "many End Sites under one joint take quadratic time" (the 20,000th searched 20,000 names).
            BvhClip clip = Read(EndSites(20000));
            Assert.That(clip.Skeleton.JointCount, Is.EqualTo(20001));
            Assert.That(clip.Skeleton.GetName(1), Is.EqualTo("Hips_End"));
            Assert.That(clip.Skeleton.GetName(2), Is.EqualTo("Hips_End2"));
            Assert.That(clip.Skeleton.GetName(20000), Is.EqualTo("Hips_End20000"));
            Scaling.AssertLinear(EndSites, text => Read(text), 5000, "reading End Sites under one joint");
        }

        [Test]
        public void EndSiteNamesStillAvoidJointsOfTheSameName()
        {
            string text = Root + "JOINT Hips_End2\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\nEnd Site\n{\nOFFSET 0 1 0\n}\nEnd Site\n{\nOFFSET 0 1 0\n}\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n" + Motion(1, 6, 1);
            BvhClip clip = Read(text);
            Assert.That(clip.Skeleton.Names, Is.EqualTo(new[] { "Hips", "Hips_End2", "Hips_End", "Hips_End3", "Hips_End4" }));
        }

        [Test]
        public void AHeaderClaimingHugeMotionsFailsAtOnceWithoutOverflow()
        {
            // Issue 14: "a BVH whose header claims frames for many channels throws OverflowException or commits gigabytes".
            var sb = new StringBuilder(Root);
            for (int i = 0; i < 2000; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n}\n");
            string hierarchy = sb.Append("}\n").ToString();
            int framesLine = hierarchy.Count(c => c == '\n') + 2;
            AssertFailsAtLine(hierarchy + Motion(2000000000, 12006, 1), framesLine, "more than 134217728 values");
            AssertFailsAtLine(hierarchy + Motion(int.MaxValue, 12006, 0), framesLine, "values (the reader's limit)");
            // The count as written (read through a float, 16777217 was 16777216, and 2147483647 negative where float to int
            // conversions do not saturate, as on Mono).
            AssertFailsAtLine(hierarchy + Motion(16777217, 12006, 0), framesLine, "16777217 frames of 12006 channels");
            // Within the limit, a claim the file does not back fails where the file ends.
            string oneChannel = "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 1 Xrotation\n}\n";
            AssertFailsAtLine(oneChannel + Motion(100000000, 1, 3), 13, "the file ends after 3 of 100000000 frames");
        }

        [Test]
        public void ChannelAndLineLimitsAreFormatErrorsNamingTheLine()
        {
            // The root's 6 and 21,843 joints of 3 make 65,535 channels; one more joint of 3 is beyond the limit.
            var sb = new StringBuilder(Root);
            for (int i = 0; i < 21843; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\n").Append(Channels3).Append("\n}\n");
            sb.Append("JOINT last\n{\nOFFSET 0 1 0\n").Append(Channels3).Append("\n}\n}\n").Append(Motion(1, 65538, 1));
            AssertFailsAtLine(sb.ToString(), 5 + 21843 * 5 + 4, $"more than {BvhReader.MaxChannels} channels");

            string longLine = Root + "}\nMOTION\nFrames: 1\nFrame Time: 0.033\n" + new string('0', BvhReader.MaxLineLength + 10) + "\n";
            AssertFailsAtLine(longLine, 10, $"a line longer than {BvhReader.MaxLineLength} characters");
            string longName = Root.Replace("ROOT Hips", "ROOT " + new string('H', BvhReader.MaxLineLength)) + "}\n" + Motion(1, 6, 1);
            AssertFailsAtLine(longName, 2, "a line longer than");
        }

        [TestCase("1e39", "is not a number within")]
        [TestCase("3.4e38", "is not a number within")]
        [TestCase("10000001", "is not a number within")]
        public void OffsetsAndValuesBeyondTheRangeAreRefused(string number, string message)
        {
            AssertFailsAtLine(Root.Replace("OFFSET 0 0 0", $"OFFSET 0 {number} 0") + "}\n" + Motion(1, 6, 1), 4, message);
            AssertFailsAtLine(Root + "}\nMOTION\nFrames: 1\nFrame Time: 0.033\n0 " + number + " 0 0 0 0\n", 10, "frame 0, value 2");
        }

        [TestCase("0")]
        [TestCase("1e-45")]
        [TestCase("0.00001")]
        [TestCase("1e38")]
        [TestCase("3600")]
        [TestCase("Infinity")]
        public void FrameTimesOutsideTheRangeAreRefused(string frameTime)
        {
            AssertFailsAtLine(Root + "}\n" + Motion(1, 6, 1, frameTime), 9, "frame time must be from 0.0001 to 60 seconds");
        }

        [Test]
        public void FramesZeroIsAValidSkeletonWithoutMotion()
        {
            BvhClip clip = Read(Root + "}\n" + Motion(0, 6, 0));
            Assert.That(clip.FrameCount, Is.EqualTo(0));
            Assert.That(clip.Skeleton.JointCount, Is.EqualTo(1));
        }

        [Test]
        public void LoneCarriageReturnsEndLinesAsReadLineDoes()
        {
            BvhClip clip = Read((Root + "}\n" + Motion(2, 6, 2)).Replace('\n', '\r'));
            Assert.That(clip.FrameCount, Is.EqualTo(2));
            clip = Read((Root + "}\n" + Motion(2, 6, 2)).Replace("\n", "\r\n"));
            Assert.That(clip.FrameCount, Is.EqualTo(2));
        }
    }
}
