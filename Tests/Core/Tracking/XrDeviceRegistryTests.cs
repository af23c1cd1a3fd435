using System.Collections.Generic;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The device rules of the Unity XR input-devices source: which devices, in which order, and what a reconnect does.</summary>
    public class XrDeviceRegistryTests
    {
        private const uint Hmd = XrDeviceKind.HeadMounted | XrDeviceKind.TrackedDevice;
        private const uint LeftController = XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice | XrDeviceKind.Left;
        private const uint RightController = XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice | XrDeviceKind.Right;
        private const uint BodyTracker = XrDeviceKind.TrackedDevice; // OpenVR XR plugin: a tracker with a body role
        private const uint BaseStation = XrDeviceKind.TrackingReference | XrDeviceKind.TrackedDevice;
        private const uint EyeGaze = XrDeviceKind.HeadMounted | XrDeviceKind.EyeTracking | XrDeviceKind.TrackedDevice;

        // What the OpenVR XR plugin reports (unity-xr-plugin Providers/Input/Input.cpp): names with the model, serials.
        private static XrDeviceReport OpenVR(uint characteristics, string serial) => new XrDeviceReport(characteristics, "OpenVR Device(" + serial + ")", serial);

        // What Unity's OpenXR plugin reports: no serials; AvatarGo's tracker feature sets the role bits.
        private static XrDeviceReport OpenXRTracker(DeviceRole role) => new XrDeviceReport(ViveTrackerRoles.Characteristics(role), ViveTrackerRoles.DeviceName, "");

        [Test]
        public void TheDevicesPresentAtStartAreSortedWhateverTheRuntimeOrder()
        {
            var registry = new XrDeviceRegistry();
            var reports = new[]
            {
                OpenVR(BodyTracker, "LHR-C"), OpenVR(BaseStation, "LHB-1"), OpenVR(RightController, "LHR-R"), OpenVR(BodyTracker, "LHR-A"),
                OpenVR(Hmd, "LHR-H"), OpenVR(LeftController, "LHR-L"), OpenVR(BodyTracker, "LHR-B"),
            };
            int[] index = registry.ConnectAll(reports);
            Assert.That(index, Is.EqualTo(new[] { 5, -1, 2, 3, 0, 1, 4 }), "HMD, left, right, then trackers by serial; the base station is not used");
            Assert.That(registry.Count, Is.EqualTo(6));
            Assert.That(registry.Header.Devices[0].Class, Is.EqualTo(DeviceClass.Hmd));
            Assert.That(registry.Header.Devices[1].Serial, Is.EqualTo("LHR-L"));
            Assert.That(registry.Header.Devices[3].Serial, Is.EqualTo("LHR-A"));
            for (int i = 0; i < registry.Count; i++)
            {
                Assert.That(registry.Header.Devices[i].Id, Is.EqualTo(i), "ids are header indices");
                Assert.That(registry.IsConnected(i), Is.True);
            }
            var shuffled = new XrDeviceRegistry();
            shuffled.ConnectAll(new[] { reports[6], reports[4], reports[0], reports[5], reports[3], reports[2], reports[1] });
            for (int i = 0; i < 6; i++) Assert.That(shuffled.Header.Devices[i].Serial, Is.EqualTo(registry.Header.Devices[i].Serial), "same order from any enumeration order");
        }

        [Test]
        public void OpenXRTrackersComeInRoleOrderAndKeepTheirRuntimeRole()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[]
            {
                OpenXRTracker(DeviceRole.RightFoot), new XrDeviceReport(Hmd, "Head Tracking - OpenXR", ""), OpenXRTracker(DeviceRole.Pelvis),
                new XrDeviceReport(EyeGaze, "Eye Tracking OpenXR", ""), OpenXRTracker(DeviceRole.LeftFoot),
                new XrDeviceReport(XrDeviceKind.TrackedDevice | 0x200000u, ViveTrackerRoles.DeviceName, ""), // a chest tracker
            });
            Assert.That(registry.Count, Is.EqualTo(4), "eye gaze and the chest tracker are not used");
            Assert.That(registry.Header.Devices[0].Class, Is.EqualTo(DeviceClass.Hmd));
            Assert.That(registry.Header.Devices[1].RuntimeRole, Is.EqualTo(DeviceRole.Pelvis));
            Assert.That(registry.Header.Devices[2].RuntimeRole, Is.EqualTo(DeviceRole.LeftFoot));
            Assert.That(registry.Header.Devices[3].RuntimeRole, Is.EqualTo(DeviceRole.RightFoot));
            Assert.That(registry.Header.Devices[3].Serial, Is.Empty, "OpenXR gives no serial, and none is made up (a saved profile is never restored on a guess)");
        }

        [Test]
        public void ADisconnectedDeviceStaysLostAndComesBackToItsPlace()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { OpenVR(Hmd, "H"), OpenVR(LeftController, "L"), OpenVR(RightController, "R") });
            int version = registry.Version;
            SessionHeader header = registry.Header;
            registry.Disconnect(1);
            Assert.That(registry.IsConnected(1), Is.False);
            Assert.That(registry.Header, Is.SameAs(header), "a disconnection changes no header");
            // Unity reports the reconnected controller as a new InputDevice (a new native id): its serial finds its place.
            Assert.That(registry.Connect(OpenVR(LeftController, "L")), Is.EqualTo(1));
            Assert.That(registry.IsConnected(1), Is.True);
            Assert.That(registry.Version, Is.EqualTo(version), "nor does a reconnection");
            Assert.That(registry.Header, Is.SameAs(header));
        }

        [Test]
        public void ANewDeviceIsAppendedWithANewHeader()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { OpenVR(Hmd, "H"), OpenVR(BodyTracker, "T2") });
            int version = registry.Version;
            Assert.That(registry.Connect(OpenVR(LeftController, "L")), Is.EqualTo(2), "appended, even though a controller sorts before trackers");
            Assert.That(registry.Version, Is.EqualTo(version + 1));
            Assert.That(registry.Header.Devices.Count, Is.EqualTo(3));
            Assert.That(registry.Header.Devices[1].Serial, Is.EqualTo("T2"), "existing places never move");
        }

        [Test]
        public void WithoutSerialsNameAndCharacteristicsIdentifyADevice()
        {
            var registry = new XrDeviceRegistry();
            var left = new XrDeviceReport(LeftController, "Index Controller OpenXR", "");
            var right = new XrDeviceReport(RightController, "Index Controller OpenXR", "");
            registry.ConnectAll(new[] { right, left, OpenXRTracker(DeviceRole.LeftFoot), OpenXRTracker(DeviceRole.RightFoot) });
            Assert.That(XrDeviceRegistry.IdentityOf(left), Is.Not.EqualTo(XrDeviceRegistry.IdentityOf(right)));
            registry.Disconnect(0);
            registry.Disconnect(1);
            registry.Disconnect(3);
            Assert.That(registry.Connect(OpenXRTracker(DeviceRole.RightFoot)), Is.EqualTo(3), "the right-foot role's device, not the left foot's");
            Assert.That(registry.Connect(right), Is.EqualTo(1), "the right-hand device, not the first free place");
            Assert.That(registry.Connect(left), Is.EqualTo(0));
            Assert.That(registry.Count, Is.EqualTo(4));
        }

        [Test]
        public void ASerialIdentifiesADeviceWhateverItsCharacteristics()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { OpenVR(Hmd, "H"), OpenVR(BodyTracker, "LHR-T") });
            int version = registry.Version;
            registry.Disconnect(1);
            // The wearer gave the tracker a held-in-hand role in SteamVR: the OpenVR XR plugin now reports it as a controller.
            Assert.That(registry.Connect(OpenVR(RightController, "LHR-T")), Is.EqualTo(1), "same serial, same place and id");
            Assert.That(registry.Header.Devices[1].Class, Is.EqualTo(DeviceClass.Controller));
            Assert.That(registry.Header.Devices[1].Id, Is.EqualTo(1));
            Assert.That(registry.Version, Is.EqualTo(version + 1), "its class changed: a new header");
        }

        [Test]
        public void ASecondDeviceWithTheSameIdentityGetsItsOwnPlace()
        {
            var registry = new XrDeviceRegistry();
            var tracker = new XrDeviceReport(BodyTracker, "Tracker", "");
            Assert.That(registry.Connect(tracker), Is.EqualTo(0));
            Assert.That(registry.Connect(tracker), Is.EqualTo(1), "the first is still connected");
            registry.DisconnectAll();
            Assert.That(registry.Connect(tracker), Is.EqualTo(0), "the first free place");
        }

        [Test]
        public void EnablingAgainFindsEveryOldPlaceBeforeAddingNewOnes()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { new XrDeviceReport(BodyTracker, "T", ""), OpenVR(Hmd, "H") });
            registry.DisconnectAll();
            int[] index = registry.ConnectAll(new[] { new XrDeviceReport(BodyTracker, "T", ""), new XrDeviceReport(BodyTracker, "T", ""), OpenVR(Hmd, "H") });
            Assert.That(index, Is.EqualTo(new[] { 1, 2, 0 }), "the HMD and one tracker take back their places, the second tracker is added");
        }

        [Test]
        public void UnusedDevicesAreIgnored()
        {
            var registry = new XrDeviceRegistry();
            Assert.That(registry.Connect(OpenVR(BaseStation, "LHB")), Is.EqualTo(-1));
            Assert.That(registry.Connect(new XrDeviceReport(EyeGaze, "Eye Tracking OpenXR", "")), Is.EqualTo(-1));
            Assert.That(registry.Count, Is.EqualTo(0));
            Assert.That(registry.Version, Is.EqualTo(0));
            Assert.That(registry.Header.Devices, Is.Empty);
        }

        [Test]
        public void ATriggerHeldWhileADeviceConnectsIsNotPressedTwice()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { OpenVR(Hmd, "H"), OpenVR(LeftController, "L") });
            var events = new List<DeviceEvent>();
            registry.FeedTrigger(1, 0.9f, false, events);
            Assert.That(events.Count, Is.EqualTo(1));
            for (int t = 0; t < 20; t++) registry.Connect(OpenVR(BodyTracker, "T" + t)); // grows the trigger state past its first size
            registry.FeedTrigger(1, 0.9f, false, events);
            Assert.That(events.Count, Is.EqualTo(1), "still held: no second press");
            registry.Disconnect(1);
            registry.Connect(OpenVR(LeftController, "L"));
            registry.FeedTrigger(1, 0.9f, false, events);
            Assert.That(events.Count, Is.EqualTo(2), "a disconnect releases silently, so a trigger held on return presses again");
            Assert.That(events[1].Kind, Is.EqualTo(DeviceEventKind.TriggerPressed));
            Assert.That(events[1].DeviceId, Is.EqualTo(1));
        }

        [Test]
        public void FeedingTriggersAllocatesNothing()
        {
            var registry = new XrDeviceRegistry();
            registry.ConnectAll(new[] { OpenVR(Hmd, "H"), OpenVR(LeftController, "L"), OpenVR(RightController, "R") });
            var events = new List<DeviceEvent>(64);
            // The first passes warm up (JIT tiering may allocate); the least of later passes is what a frame costs.
            long least = long.MaxValue;
            for (int pass = 0; pass < 5; pass++)
            {
                long before = System.GC.GetAllocatedBytesForCurrentThread();
                Feed(registry, events);
                long bytes = System.GC.GetAllocatedBytesForCurrentThread() - before;
                if (pass >= 2) least = System.Math.Min(least, bytes);
            }
            Assert.That(least, Is.EqualTo(0));
        }

        private static void Feed(XrDeviceRegistry registry, List<DeviceEvent> events)
        {
            for (int f = 0; f < 1000; f++)
            {
                registry.FeedTrigger(1, f % 50 < 25 ? 0.9f : 0.1f, false, events);
                registry.FeedTrigger(2, float.NaN, f % 30 < 15, events);
                if (events.Count > 60) events.Clear();
            }
        }
    }
}
