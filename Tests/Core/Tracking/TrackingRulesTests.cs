using System.Collections.Generic;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The tracking sources' other engine-free rules: poses, default bindings, tracker roles, role slots, rigs.</summary>
    public class TrackingRulesTests
    {
        [Test]
        public void TheHmdIsReadAtItsCentreEyeWhenItHasOne()
        {
            var both = new List<string> { "DevicePosition", "DeviceRotation", XrPoseRules.CenterEyePosition, XrPoseRules.CenterEyeRotation };
            Assert.That(XrPoseRules.UsesCenterEye(DeviceClass.Hmd, both), Is.True);
            Assert.That(XrPoseRules.UsesCenterEye(DeviceClass.Hmd, new List<string> { "DevicePosition", XrPoseRules.CenterEyePosition }), Is.False, "position without rotation");
            Assert.That(XrPoseRules.UsesCenterEye(DeviceClass.Controller, both), Is.False, "controllers use their device (grip) pose");
            Assert.That(XrPoseRules.UsesCenterEye(DeviceClass.Hmd, null), Is.False);
        }

        [TestCase(true, true, false, false, false, 0u, true)]
        [TestCase(true, true, true, true, true, 3u, true)]
        [TestCase(true, true, true, false, true, 3u, false)]    // isTracked says no
        [TestCase(true, true, true, true, true, 1u, false)]     // rotation not tracked
        [TestCase(true, true, false, false, true, 3u, true)]    // no isTracked feature
        [TestCase(true, true, true, true, false, 0u, true)]     // no trackingState feature
        [TestCase(false, true, true, true, true, 3u, false)]    // no position read
        [TestCase(true, false, true, true, true, 3u, false)]    // no rotation read
        [TestCase(true, true, true, true, true, 63u, true)]     // every InputTrackingState bit
        public void APoseIsTrackedWhenEveryFlagTheDeviceReportsAgrees(bool position, bool rotation, bool hasIsTracked, bool isTracked, bool hasState, uint state, bool expected)
        {
            Assert.That(XrPoseRules.IsTracked(position, rotation, hasIsTracked, isTracked, hasState, state), Is.EqualTo(expected));
        }

        [Test]
        public void TheDefaultBindingsAreTheXrToolkitsForTheHmdAndControllersAndTheTrackerLayoutsForTrackers()
        {
            Assert.That(InputSystemBindings.Position(DeviceRole.Head), Is.EqualTo("<XRHMD>/centerEyePosition"));
            Assert.That(InputSystemBindings.Rotation(DeviceRole.Head), Is.EqualTo("<XRHMD>/centerEyeRotation"));
            Assert.That(InputSystemBindings.TrackingState(DeviceRole.Head), Is.EqualTo("<XRHMD>/trackingState"));
            Assert.That(InputSystemBindings.Position(DeviceRole.LeftHand), Is.EqualTo("<XRController>{LeftHand}/devicePosition"));
            Assert.That(InputSystemBindings.Rotation(DeviceRole.RightHand), Is.EqualTo("<XRController>{RightHand}/deviceRotation"));
            Assert.That(InputSystemBindings.TrackingState(DeviceRole.RightHand), Is.EqualTo("<XRController>{RightHand}/trackingState"));
            Assert.That(InputSystemBindings.Trigger(BodySide.Left), Is.EqualTo("<XRController>{LeftHand}/{Trigger}"));
            Assert.That(InputSystemBindings.Grip(BodySide.Right), Is.EqualTo("<XRController>{RightHand}/{Grip}"));
            Assert.That(InputSystemBindings.Position(DeviceRole.Pelvis), Is.EqualTo("<XRViveTracker>{Waist}/devicePose/position"));
            Assert.That(InputSystemBindings.Rotation(DeviceRole.LeftFoot), Is.EqualTo("<XRViveTracker>{LeftFoot}/devicePose/rotation"));
            Assert.That(InputSystemBindings.TrackingState(DeviceRole.RightFoot), Is.EqualTo("<XRViveTracker>{RightFoot}/devicePose/trackingState"));
            Assert.Throws<System.ArgumentOutOfRangeException>(() => InputSystemBindings.Position(DeviceRole.None));
        }

        [Test]
        public void EveryTrackerRoleHasItsPathItsBitAndItsUsage()
        {
            Assert.That(ViveTrackerRoles.Roles, Is.EqualTo(new[] { DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot }));
            Assert.That(ViveTrackerRoles.RolePath(DeviceRole.Pelvis), Is.EqualTo("/user/vive_tracker_htcx/role/waist"));
            Assert.That(ViveTrackerRoles.RolePath(DeviceRole.LeftFoot), Is.EqualTo("/user/vive_tracker_htcx/role/left_foot"));
            Assert.That(ViveTrackerRoles.RolePath(DeviceRole.RightFoot), Is.EqualTo("/user/vive_tracker_htcx/role/right_foot"));
            foreach (DeviceRole role in ViveTrackerRoles.Roles)
            {
                // What the feature declares is what the classification and the layout read back.
                Assert.That(XrDeviceKind.TryClassify(ViveTrackerRoles.Characteristics(role), out DeviceClass c, out DeviceRole r), Is.True, role.ToString());
                Assert.That(c, Is.EqualTo(DeviceClass.Tracker));
                Assert.That(r, Is.EqualTo(role));
                Assert.That(ViveTrackerRoles.UsageOf(ViveTrackerRoles.Characteristics(role)), Is.EqualTo(ViveTrackerRoles.Usage(role)));
                Assert.That(InputSystemBindings.Device(role), Does.Contain("{" + ViveTrackerRoles.Usage(role) + "}"));
            }
            Assert.That(ViveTrackerRoles.RoleBit(DeviceRole.Pelvis), Is.EqualTo(0x100000u));
            Assert.That(ViveTrackerRoles.RoleBit(DeviceRole.LeftFoot), Is.EqualTo(0x1000u));
            Assert.That(ViveTrackerRoles.RoleBit(DeviceRole.RightFoot), Is.EqualTo(0x2000u));
            Assert.That(ViveTrackerRoles.UsageOf(XrDeviceKind.TrackedDevice), Is.Null, "a tracker without a role");
            Assert.That(ViveTrackerRoles.UsageOf(XrDeviceKind.TrackedDevice | 0x200000u), Is.Null, "a chest tracker");
            Assert.That(ViveTrackerRoles.UsageOf(XrDeviceKind.HeadMounted | XrDeviceKind.TrackedDevice), Is.Null);
            Assert.Throws<System.ArgumentOutOfRangeException>(() => ViveTrackerRoles.RolePath(DeviceRole.Head));
        }

        [Test]
        public void RoleSlotsAreTheSixRolesWithTrackerRolesOnly()
        {
            var slots = new RoleSlotDevices();
            IReadOnlyList<DeviceInfo> d = slots.Header.Devices;
            Assert.That(d.Count, Is.EqualTo(6));
            for (int i = 0; i < 6; i++) Assert.That(d[i].Id, Is.EqualTo(i));
            Assert.That(d[0].Class, Is.EqualTo(DeviceClass.Hmd));
            Assert.That(d[1].Class, Is.EqualTo(DeviceClass.Controller));
            Assert.That(d[2].RuntimeRole, Is.EqualTo(DeviceRole.None), "which hand holds which is the T-pose's to say");
            Assert.That(d[3].RuntimeRole, Is.EqualTo(DeviceRole.Pelvis));
            Assert.That(d[5].RuntimeRole, Is.EqualTo(DeviceRole.RightFoot));
            Assert.That(slots.Version, Is.EqualTo(0));
            Assert.That(slots.SetSerial(DeviceRole.LeftFoot, "LHR-1"), Is.True);
            Assert.That(slots.Version, Is.EqualTo(1));
            Assert.That(slots.Header.Devices[4].Serial, Is.EqualTo("LHR-1"));
            Assert.That(slots.SetSerial(DeviceRole.LeftFoot, "LHR-1"), Is.False, "unchanged: same header");
            Assert.That(slots.Version, Is.EqualTo(1));
            Assert.That(slots.SetSerial(DeviceRole.LeftFoot, null), Is.True);
            Assert.That(slots.Header.Devices[4].Serial, Is.Empty);
        }

        [Test]
        public void RoleSlotsWithSerialsAreTheTransformSourcesHeader()
        {
            // TransformTrackingSource's header, as it was written out before it came from RoleSlotDevices.
            var expected = new[]
            {
                new DeviceInfo(0, DeviceClass.Hmd, "transform-head"),
                new DeviceInfo(1, DeviceClass.Controller, "transform-left-controller"),
                new DeviceInfo(2, DeviceClass.Controller, "transform-right-controller"),
                new DeviceInfo(3, DeviceClass.Tracker, "transform-pelvis", DeviceRole.Pelvis),
                new DeviceInfo(4, DeviceClass.Tracker, "transform-left-foot", DeviceRole.LeftFoot),
                new DeviceInfo(5, DeviceClass.Tracker, "transform-right-foot", DeviceRole.RightFoot),
            };
            var slots = new RoleSlotDevices();
            for (int i = 0; i < expected.Length; i++) slots.SetSerial(BodyRoles.All[i], expected[i].Serial);
            Assert.That(slots.Header.Rate, Is.EqualTo(90f));
            Assert.That(slots.Header.Devices.Count, Is.EqualTo(expected.Length));
            for (int i = 0; i < expected.Length; i++)
            {
                DeviceInfo d = slots.Header.Devices[i];
                Assert.That(d.Id, Is.EqualTo(expected[i].Id), i.ToString());
                Assert.That(d.Class, Is.EqualTo(expected[i].Class), i.ToString());
                Assert.That(d.Serial, Is.EqualTo(expected[i].Serial), i.ToString());
                Assert.That(d.RuntimeRole, Is.EqualTo(expected[i].RuntimeRole), i.ToString());
            }
        }

        [TestCase("<XRController>{LeftHand}/devicePosition", 2, BodySide.Left)]
        [TestCase("<XRController>{RightHand}/pointerPosition", 2, BodySide.Right)]
        [TestCase("<xrcontroller>{righthand}/devicePosition", 2, BodySide.Right)]
        [TestCase("<XRHandDevice>{LeftHand}/devicePosition", 1, BodySide.Left)]
        [TestCase("<XRHMD>/centerEyePosition", 0, BodySide.Left)]
        [TestCase("", 0, BodySide.Left)]
        public void AControllerIsRecognisedByItsPoseBinding(string path, int score, BodySide side)
        {
            Assert.That(XrRigRules.BindingScore(path, out BodySide s), Is.EqualTo(score));
            if (score > 0) Assert.That(s, Is.EqualTo(side));
        }

        [TestCase("LeftHand Controller", 2, BodySide.Left)]      // XRI 2.0-2.3 menu rig
        [TestCase("Right Controller", 2, BodySide.Right)]        // XRI 2.5+ and 3.x starter assets
        [TestCase("LeftHand (Smooth locomotion)", 1, BodySide.Left)] // XRI 2.3 preconfigured rig
        [TestCase("Right Hand", 1, BodySide.Right)]              // a hand-tracking object: below any controller
        [TestCase("Main Camera", 0, BodySide.Left)]
        [TestCase("Left Right Controller", 0, BodySide.Left)]
        [TestCase("Left Teleport Anchor", 0, BodySide.Left)]
        public void AControllerIsRecognisedByItsNameAsALastResort(string name, int score, BodySide side)
        {
            Assert.That(XrRigRules.NameScore(name, out BodySide s), Is.EqualTo(score));
            if (score > 0) Assert.That(s, Is.EqualTo(side));
        }

        [Test]
        public void ResizedTriggerEdgesKeepWhatIsHeld()
        {
            var edges = new TriggerEdges(1, 0.6f, 0.4f);
            var events = new List<DeviceEvent>();
            edges.Feed(0, 0, 1f, false, events);
            TriggerEdges bigger = edges.Resized(3);
            Assert.That(bigger.DeviceCount, Is.EqualTo(3));
            Assert.That(bigger.IsPressed(0), Is.True);
            Assert.That(bigger.IsPressed(2), Is.False);
            Assert.That(bigger.PressAt, Is.EqualTo(0.6f));
            Assert.That(bigger.ReleaseAt, Is.EqualTo(0.4f));
            Assert.That(edges.Resized(0).DeviceCount, Is.EqualTo(0));
        }
    }
}
