using System;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using System.Text;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Issue 14's hostile session headers and frames, each built from its description: many devices, truth roles and
    /// truth joints (quadratic before), many events, absurd rates, times and positions. Each must read, or fail with
    /// the documented <c>SOURCE:LINE: problem</c>; what the writer writes the reader reads.
    /// </summary>
    public class SessionHostileInputTests
    {
        private const string Start = "avatargo-session 1.0\nunits m s\nhandedness left y-up z-forward\nrate 90\n";

        private static string Devices(int count, bool truthRoles)
        {
            var sb = new StringBuilder(Start);
            for (int i = 0; i < count; i++) sb.Append("device ").Append(i).Append(" tracker S").Append(i).Append(" none\n");
            if (truthRoles) for (int i = 0; i < count; i++) sb.Append("truth-role ").Append(i).Append(" none\n");
            sb.Append("end-header\nframe 0\n");
            for (int i = 0; i < count; i++) sb.Append("pose ").Append(i).Append(" tracked 0 1 0 0 0 0 1\n");
            return sb.Append("end 1\n").ToString();
        }

        private static string TruthJoints(int count)
        {
            var sb = new StringBuilder(Start + "device 0 hmd H none\n");
            for (int i = 0; i < count; i++) sb.Append("truth-joint ").Append(i).Append(' ').Append(i - 1).Append(" - joint J").Append(i).Append(" 0 0.01 0 0 0 0 1\n");
            return sb.Append("end-header\nframe 0\npose 0 tracked 0 1 0 0 0 0 1\nend 1\n").ToString();
        }

        private const string OneDevice = "device 0 hmd H none\nend-header\n";

        private static int ReadAll(string text)
        {
            using var reader = new SessionReader(new StringReader(text), "hostile.agsession");
            SessionFrame frame = reader.CreateFrame();
            int n = 0;
            while (reader.ReadFrame(frame)) n++;
            return n;
        }

        private static void AssertFailsAtLine(string text, int line, string contains)
        {
            var e = Assert.Throws<FormatException>(() => ReadAll(text));
            StringAssert.StartsWith($"hostile.agsession:{line}: ", e.Message);
            StringAssert.Contains(contains, e.Message);
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), "one line");
        }

        [Test]
        public void A100000DeviceHeaderIsRefusedAtTheDeviceLimitInUnderASecond()
        {
            // Issue 14: "100,000 devices: 14 s". The reader now stops at the limit's first excess line, and every check
            // up to it is a hash look-up (the linear growth is asserted below, on truth joints, which the limit lets grow further).
            string text = Devices(100000, truthRoles: true);
            var clock = Stopwatch.StartNew();
            AssertFailsAtLine(text, 4 + SessionLimits.MaxDevices + 1, $"more than {SessionLimits.MaxDevices} devices");
            Assert.That(clock.ElapsedMilliseconds, Is.LessThan(1000));
        }

        [Test]
        public void AHeaderAtTheDeviceLimitReads()
        {
            Assert.That(ReadAll(Devices(SessionLimits.MaxDevices, truthRoles: true)), Is.EqualTo(1));
            Scaling.AssertLinear(n => Devices(n, truthRoles: true), text => ReadAll(text), SessionLimits.MaxDevices / 4, "reading devices and truth roles");
        }

        [Test]
        public void TruthJointsUpToTheLimitReadInLinearTime()
        {
            // The truth-joint names were checked against a list (quadratic); 65,536 joints now read in milliseconds.
            using (var reader = new SessionReader(new StringReader(TruthJoints(SessionLimits.MaxTruthJoints)), "many"))
                Assert.That(reader.Header.TruthHumanoid.Skeleton.JointCount, Is.EqualTo(SessionLimits.MaxTruthJoints));
            Scaling.AssertLinear(TruthJoints, text => ReadAll(text), SessionLimits.MaxTruthJoints / 4, "reading truth joints");
            AssertFailsAtLine(TruthJoints(SessionLimits.MaxTruthJoints + 1), 5 + SessionLimits.MaxTruthJoints + 1, "more than 65536 truth joints");
        }

        [Test]
        public void TruthRolesCannotOutnumberTheDeviceLimit()
        {
            var sb = new StringBuilder(Start + "device 0 hmd H none\n");
            for (int i = 0; i <= SessionLimits.MaxDevices; i++) sb.Append("truth-role ").Append(i).Append(" none\n");
            AssertFailsAtLine(sb.Append("end-header\nend 0\n").ToString(), 5 + SessionLimits.MaxDevices + 1, "more than 1024 truth-role lines");
        }

        [Test]
        public void EventsPerFrameAreLimited()
        {
            var sb = new StringBuilder(Start + OneDevice + "frame 0\npose 0 tracked 0 1 0 0 0 0 1\n");
            for (int i = 0; i <= SessionLimits.MaxEventsPerFrame; i++) sb.Append("event 0 trigger-pressed\n");
            AssertFailsAtLine(sb.Append("end 1\n").ToString(), 8 + SessionLimits.MaxEventsPerFrame + 1, "more than 1024 events in one frame");
        }

        [TestCase("1e-45")]
        [TestCase("0.5")]
        [TestCase("10001")]
        [TestCase("3.4e38")]
        public void RatesOutsideTheRangeAreRefused(string rate)
        {
            AssertFailsAtLine(Start.Replace("rate 90", "rate " + rate) + OneDevice + "end 0\n", 4, "the rate must be from 1 to 10000 Hz");
        }

        [TestCase("1e300")]
        [TestCase("-1e11")]
        [TestCase("1.7976931348623157e308")]
        public void FrameTimesBeyondTheRangeAreRefused(string time)
        {
            AssertFailsAtLine(Start + OneDevice + $"frame {time}\npose 0 tracked 0 1 0 0 0 0 1\nend 1\n", 7, "is beyond ±10000000000 s");
        }

        [Test]
        public void TrackedAndTruthPositionsBeyondTenKilometresAreRefused()
        {
            AssertFailsAtLine(Start + OneDevice + "frame 0\npose 0 tracked 1e30 1 0 0 0 0 1\nend 1\n", 8, "position (1e30 1 0) is beyond ±10000 m");
            AssertFailsAtLine(Start + "device 0 hmd H none\ntruth-joint 0 -1 Hips joint Hips 0 20000 0 0 0 0 1\nend-header\nend 0\n", 6, "is beyond ±10000 m");
            AssertFailsAtLine(Start + OneDevice + "frame 0\npose 0 tracked 0 1 0 0 0 0 1\ntruth Head 0 -3e38 0 0 0 0 1\nend 1\n", 9, "is beyond");
            // A lost pose only needs to be finite: it carries whatever the runtime last reported.
            Assert.That(ReadAll(Start + OneDevice + "frame 0\npose 0 lost 1e30 1 0 0 0 0 0\nend 1\n"), Is.EqualTo(1));
        }

        [Test]
        public void AnEndPointWithAJointBelowItIsRefused()
        {
            // Found in review: it was read, and `evaluate --bvh-out` wrote the solved motion as a BVH no reader takes.
            AssertFailsAtLine(Start + "device 0 hmd H none\ntruth-joint 0 -1 Hips joint Hips 0 1 0 0 0 0 1\n" +
                "truth-joint 1 0 - end Tip 0 0.1 0 0 0 0 1\ntruth-joint 2 1 - joint Below 0 0.1 0 0 0 0 1\nend-header\nend 0\n", 8, "is an end point");
        }

        [Test]
        public void LongLinesAreRefusedBeforeTheyAreHeld()
        {
            AssertFailsAtLine(Start + "# " + new string('x', SessionLimits.MaxLineLength + 5) + "\n" + OneDevice + "end 0\n", 5, "a line longer than");
        }

        [Test]
        public void ErrorMessagesQuoteLongTokensShortened()
        {
            var e = Assert.Throws<FormatException>(() => ReadAll(Start + "device 0 " + new string('d', 100000) + " H none\nend-header\nend 0\n"));
            Assert.That(e.Message.Length, Is.LessThan(200), e.Message.Substring(0, 100));
        }

        [Test]
        public void WhatTheWriterRefusesIsWhatTheReaderRefuses()
        {
            var devices = new[] { new DeviceInfo(0, DeviceClass.Hmd, "H") };
            Assert.Throws<ArgumentOutOfRangeException>(() => new SessionHeader(0.5f, devices));
            Assert.Throws<ArgumentOutOfRangeException>(() => new SessionHeader(20000f, devices));
            var many = new DeviceInfo[SessionLimits.MaxDevices + 1];
            for (int i = 0; i < many.Length; i++) many[i] = new DeviceInfo(i, DeviceClass.Tracker, "T" + i);
            Assert.Throws<ArgumentException>(() => new SessionHeader(90f, many));

            var header = new SessionHeader(90f, devices);
            using var writer = new SessionWriter(new StringWriter(), header);
            var frame = new SessionFrame(header);
            frame.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 2e4f, 0), Quaternion.Identity), true);
            Assert.Throws<ArgumentException>(() => writer.WriteFrame(frame), "a tracked pose beyond 10 km");
            frame.Samples[0] = new DeviceSample(RigidPose.Identity, true);
            frame.Time = 1e11;
            Assert.Throws<ArgumentException>(() => writer.WriteFrame(frame), "a time beyond 1e10 s");
            frame.Time = 0;
            for (int i = 0; i <= SessionLimits.MaxEventsPerFrame; i++) frame.Events.Add(new DeviceEvent(0, DeviceEventKind.TriggerPressed));
            Assert.Throws<ArgumentException>(() => writer.WriteFrame(frame), "too many events");
            frame.Events.Clear();
            writer.WriteFrame(frame);
            Assert.That(writer.FrameCount, Is.EqualTo(1), "a rejected frame leaves the session as it was");
        }
    }
}
