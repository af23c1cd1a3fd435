using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The Unity components' decisions, taken engine-free: tracking space, which XR device plays what, trigger edges, recording.</summary>
    public class ShellLogicTests
    {
        [Test]
        public void TrackingSpaceMapsPosesToTheWorldAndBack()
        {
            var space = new TrackingSpace(new RigidPose(new Vector3(3, 0.2f, -1), Rotations.AngleAxis(90f, Vector3.UnitY)), 2f);
            var p = new RigidPose(new Vector3(0, 1.6f, 0.5f), Rotations.AngleAxis(30f, Vector3.UnitX));
            RigidPose w = space.ToWorld(p);
            Approx.Near(new Vector3(3 + 1f, 0.2f + 3.2f, -1), w.Position, 1e-5f, "turned a quarter about y, doubled, moved");
            Approx.Near(p, space.ToTracking(w), 1e-5f, 1e-3f, "and back");
            Approx.Near(p.Position, TrackingSpace.World.ToWorld(p).Position, 0f, "the world is the identity");
            Assert.Throws<ArgumentOutOfRangeException>(() => new TrackingSpace(RigidPose.Identity, 0f));
        }

        [TestCase(XrDeviceKind.HeadMounted | XrDeviceKind.TrackedDevice, true, DeviceClass.Hmd, DeviceRole.None)]
        [TestCase(XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice | XrDeviceKind.Left, true, DeviceClass.Controller, DeviceRole.None)]
        // Unity OpenXR's Microsoft Hand Interaction, Palm Pose and Hand Common Poses devices (com.unity.xr.openxr
        // Runtime/Features/Interactions/MicrosoftHandInteraction.cs, PalmPoseInteraction.cs): hands, not controllers.
        [TestCase(XrDeviceKind.HandTracking | XrDeviceKind.HeldInHand | XrDeviceKind.TrackedDevice | XrDeviceKind.Controller | XrDeviceKind.Left, false, DeviceClass.Tracker, DeviceRole.None)]
        [TestCase(XrDeviceKind.HandTracking | XrDeviceKind.HeldInHand | XrDeviceKind.TrackedDevice | XrDeviceKind.Right, false, DeviceClass.Tracker, DeviceRole.None)]
        [TestCase(XrDeviceKind.TrackedDevice, true, DeviceClass.Tracker, DeviceRole.None)]
        [TestCase(XrDeviceKind.TrackedDevice | XrDeviceKind.TrackerWaist, true, DeviceClass.Tracker, DeviceRole.Pelvis)]
        [TestCase(XrDeviceKind.TrackedDevice | XrDeviceKind.TrackerLeftFoot, true, DeviceClass.Tracker, DeviceRole.LeftFoot)]
        [TestCase(XrDeviceKind.TrackedDevice | XrDeviceKind.TrackerRightFoot, true, DeviceClass.Tracker, DeviceRole.RightFoot)]
        [TestCase(XrDeviceKind.TrackedDevice | 0x200000u, false, DeviceClass.Tracker, DeviceRole.None)]    // chest tracker
        [TestCase(XrDeviceKind.TrackedDevice | XrDeviceKind.TrackingReference, false, DeviceClass.Tracker, DeviceRole.None)] // base station
        [TestCase(XrDeviceKind.HandTracking | XrDeviceKind.TrackedDevice | XrDeviceKind.Left, false, DeviceClass.Tracker, DeviceRole.None)]
        [TestCase(XrDeviceKind.EyeTracking | XrDeviceKind.TrackedDevice, false, DeviceClass.Tracker, DeviceRole.None)]
        [TestCase(XrDeviceKind.EyeTracking | XrDeviceKind.HeadMounted | XrDeviceKind.TrackedDevice, false, DeviceClass.Tracker, DeviceRole.None)] // OpenXR eye gaze: no HMD
        [TestCase(0u, false, DeviceClass.Tracker, DeviceRole.None)]
        public void XrCharacteristicsDecideTheClassAndTheRuntimeRole(uint characteristics, bool used, DeviceClass expectedClass, DeviceRole expectedRole)
        {
            Assert.That(XrDeviceKind.TryClassify(characteristics, out DeviceClass c, out DeviceRole r), Is.EqualTo(used));
            if (!used) return;
            Assert.That(c, Is.EqualTo(expectedClass));
            Assert.That(r, Is.EqualTo(expectedRole));
        }

        [Test]
        public void TriggerEdgesHaveHysteresis()
        {
            var edges = new TriggerEdges(2);
            var events = new List<DeviceEvent>();
            float[] analog = { 0f, 0.5f, 0.76f, 0.6f, 0.3f, 0.8f, 0.2f, float.NaN };
            foreach (float v in analog) edges.Feed(0, 17, v, false, events);
            // 0.76 crosses the press threshold; 0.6, 0.3 and 0.8 keep it pressed; 0.2 is below the release threshold.
            Assert.That(events.ConvertAll(e => e.Kind), Is.EqualTo(new[] { DeviceEventKind.TriggerPressed, DeviceEventKind.TriggerReleased }));
            Assert.That(events[0].DeviceId, Is.EqualTo(17));
            events.Clear();
            edges.Feed(1, 3, float.NaN, true, events);
            edges.Feed(1, 3, float.NaN, true, events);
            edges.Feed(1, 3, float.NaN, false, events);
            Assert.That(events.Count, Is.EqualTo(2), "a button alone presses and releases once each");
        }

        [Test]
        public void TriggerEdgesPressOnceWhileHeldNearTheThreshold()
        {
            var edges = new TriggerEdges(1);
            var events = new List<DeviceEvent>();
            for (int i = 0; i < 50; i++) edges.Feed(0, 1, i % 2 == 0 ? 0.74f : 0.77f, false, events);
            Assert.That(events.Count, Is.EqualTo(1), "no chatter around 0.75");
        }

        /// <summary>
        /// Found in review: a time that is not a number or infinite (a custom source's broken clock) threw out of
        /// SessionRecorder.Record (the recorder component then stopped the recording), and an infinite first time became the
        /// session's start, so every later frame was recorded at time 0. The pipeline takes such a time as a frame in which no
        /// time passed; so does the recorder now.
        /// </summary>
        [Test]
        public void ARecordingTakesATimeThatIsNotFiniteAsOneInWhichNoTimePassed()
        {
            var header = new SessionHeader(90f, new[] { new DeviceInfo(3, DeviceClass.Hmd, "H") });
            var text = new StringWriter();
            double[] fed = { double.NaN, double.PositiveInfinity, 100.0, 100.0 + 1 / 90.0, double.NegativeInfinity, double.NaN, 100.0 + 2 / 90.0 };
            using (var recorder = new SessionRecorder(new SessionWriter(text, header)))
                foreach (double time in fed)
                    recorder.Record(time, new[] { new DeviceSample(RigidPose.FromPosition(new Vector3(0, 1.6f, 0)), true) }, default, default, null);
            using var reader = new SessionReader(new StringReader(text.ToString()), "recording");
            SessionFrame f = reader.CreateFrame();
            var times = new List<double>();
            while (reader.ReadFrame(f)) times.Add(f.Time);
            Assert.That(times, Is.EqualTo(new[] { 0, 0, 0, 1 / 90.0, 1 / 90.0, 1 / 90.0, 2 / 90.0 }).Within(1e-12));
        }

        /// <summary>
        /// Found in review: a tracked pose beyond the format's ±10 km (a driver glitch: 3e38 m, finite, so usable to the
        /// pipeline, whose glitch filter drops it) made SessionRecorder.Record throw, and AvatarGoRecorder then stopped the
        /// whole recording at that frame. Such a sample is now recorded as lost, as a NaN one is, and the recording goes on.
        /// </summary>
        [Test]
        public void ATrackedPoseBeyondTheFormatsRangeIsRecordedAsLost()
        {
            var header = new SessionHeader(90f, new[] { new DeviceInfo(3, DeviceClass.Hmd, "H"), new DeviceInfo(4, DeviceClass.Tracker, "T") });
            var text = new StringWriter();
            var near = new RigidPose(new Vector3(0.2f, 1f, 0.1f), Rotations.AngleAxis(20f, Vector3.UnitY));
            using (var recorder = new SessionRecorder(new SessionWriter(text, header)))
                for (int i = 0; i < 3; i++)
                {
                    var far = new RigidPose(new Vector3(i == 1 ? 3e38f : 2e4f, 1f, 0f), Quaternion.Identity);
                    recorder.Record(i / 90.0, new[] { new DeviceSample(near, true), new DeviceSample(i == 2 ? near : far, true) }, default, default, null);
                }
            using var reader = new SessionReader(new StringReader(text.ToString()), "recording");
            SessionFrame f = reader.CreateFrame();
            var tracked = new List<bool>();
            while (reader.ReadFrame(f))
            {
                Assert.That(f.Samples[0].Pose, Is.EqualTo(near), "the other device as fed");
                tracked.Add(f.Samples[1].IsTracked);
            }
            Assert.That(tracked, Is.EqualTo(new[] { false, false, true }), "beyond 10 km: lost; the frame after as fed");
        }

        [Test]
        public void ARecordingReadsBackAsItWasFed()
        {
            var devices = new[] { new DeviceInfo(3, DeviceClass.Hmd, "H"), new DeviceInfo(8, DeviceClass.Controller, "C") };
            var text = new StringWriter();
            var fed = new List<DeviceSample[]>();
            using (var recorder = new SessionRecorder(new SessionWriter(text, new SessionHeader(90f, devices))))
            {
                var rng = new Random(2);
                for (int i = 0; i < 50; i++)
                {
                    var samples = new[]
                    {
                        new DeviceSample(new RigidPose(new Vector3((float)rng.NextDouble(), 1.6f, 0), Rotations.AngleAxis(i, Vector3.UnitY)), true),
                        i == 7 ? new DeviceSample(new RigidPose(new Vector3(float.NaN, 0, 0), Quaternion.Identity), true) : new DeviceSample(new RigidPose(new Vector3(0, 1, i * 0.01f), Quaternion.Identity), i % 5 != 0),
                    };
                    fed.Add(samples);
                    var events = i == 10 ? new[] { new DeviceEvent(8, DeviceEventKind.TriggerPressed), new DeviceEvent(99, DeviceEventKind.TriggerPressed) } : null;
                    recorder.Record(100.0 + i / 90.0, samples, new[] { float.NaN, i / 50f }, default, events);
                }
            }
            using var reader = new SessionReader(new StringReader(text.ToString()), "recording");
            SessionFrame f = reader.CreateFrame();
            for (int i = 0; reader.ReadFrame(f); i++)
            {
                Assert.That(f.Time, Is.EqualTo(i / 90.0).Within(1e-9), "times start at 0");
                for (int d = 0; d < 2; d++)
                {
                    bool expectTracked = fed[i][d].IsUsable;
                    Assert.That(f.Samples[d].IsTracked, Is.EqualTo(expectTracked), $"frame {i} device {d}: a NaN pose is recorded as lost");
                    if (expectTracked) Assert.That(f.Samples[d].Pose.Position, Is.EqualTo(fed[i][d].Pose.Position));
                }
                Assert.That(f.Trigger[1], Is.EqualTo(i / 50f));
                Assert.That(float.IsNaN(f.Trigger[0]), Is.True);
                Assert.That(f.Events.Count, Is.EqualTo(i == 10 ? 1 : 0), "an event from an unknown device is dropped");
            }
            Assert.That(reader.FrameCount, Is.EqualTo(50));
        }
    }
}
