using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Which device plays which role, end to end: the devices an XR backend reports go through the XR input source's
    /// registry (its header order), and the calibration identifies them from a mocap wearer's T-pose. OpenVR gives serials
    /// and no tracker roles; OpenXR with AvatarGo's tracker feature gives roles and no serials, and a wrong role is refused,
    /// never trusted. Poses are then brought from tracking space to the world through an XR Origin's camera offset.
    /// </summary>
    public class XrBackendCalibrationTests
    {
        private const uint Hmd = XrDeviceKind.HeadMounted | XrDeviceKind.TrackedDevice;
        private const uint LeftController = XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice | XrDeviceKind.Left;
        private const uint RightController = XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice | XrDeviceKind.Right;
        private const uint BaseStation = XrDeviceKind.TrackingReference | XrDeviceKind.TrackedDevice;

        // A report and the body role of the device it describes (where the wearer wears it), or None for a base station.
        private readonly struct Worn
        {
            public readonly XrDeviceReport Report;
            public readonly DeviceRole Role;

            public Worn(XrDeviceReport report, DeviceRole role)
            {
                Report = report;
                Role = role;
            }
        }

        // The registry's header and, per header index, the body role the device is worn at.
        private static (SessionHeader Header, DeviceRole[] WornAt) Register(Worn[] reported)
        {
            var registry = new XrDeviceRegistry();
            var reports = new XrDeviceReport[reported.Length];
            for (int i = 0; i < reported.Length; i++) reports[i] = reported[i].Report;
            int[] index = registry.ConnectAll(reports);
            var wornAt = new DeviceRole[registry.Count];
            for (int i = 0; i < reported.Length; i++)
                if (index[i] >= 0) wornAt[index[i]] = reported[i].Role;
            return (registry.Header, wornAt);
        }

        // Calibrates on the header's devices; each is fed the wearer's pose of the role it is worn at.
        private static Calibrator Calibrate(SessionHeader header, DeviceRole[] wornAt)
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 11, DeviceMountings.Default());
            wearer.StandInTPose(new RigidPose(new Vector3(-0.4f, 0, 0.8f), Rotations.AngleAxis(35f, Vector3.UnitY)));
            var calibrator = new Calibrator(header.Devices, wearer.Map);
            var truth = new DeviceSample[Wearer.TrueRoles.Length];
            var fed = new DeviceSample[header.Devices.Count];
            int trigger = Array.IndexOf(wornAt, DeviceRole.RightHand);
            var press = new List<DeviceEvent> { new DeviceEvent(header.Devices[trigger].Id, DeviceEventKind.TriggerPressed) };
            for (int f = 0; f < 90; f++)
            {
                wearer.Sample(truth, 0.001f, 0.1f);
                for (int d = 0; d < fed.Length; d++) fed[d] = truth[Array.IndexOf(Wearer.TrueRoles, wornAt[d])];
                calibrator.Update(f / 90.0, fed, f == 89 ? press : null);
            }
            return calibrator;
        }

        [Test]
        public void OpenVRTrackersWithoutRolesAreIdentifiedByWhereTheyAreWorn()
        {
            // The OpenVR XR plug-in: trackers with a body role are TrackedDevice only, told apart by serial; the runtime
            // lists devices in any order, with base stations among them.
            var (header, wornAt) = Register(new[]
            {
                new Worn(new XrDeviceReport(XrDeviceKind.TrackedDevice, "OpenVR Tracked Device(VIVE Tracker Pro MV)", "LHR-0C"), DeviceRole.Pelvis),
                new Worn(new XrDeviceReport(BaseStation, "OpenVR Tracking Reference(HTC V2-XD/XE)", "LHB-11"), DeviceRole.None),
                new Worn(new XrDeviceReport(RightController, "OpenVR Controller(VIVE Controller Pro MV) - Right", "LHR-RR"), DeviceRole.RightHand),
                new Worn(new XrDeviceReport(XrDeviceKind.TrackedDevice, "OpenVR Tracked Device(VIVE Tracker Pro MV)", "LHR-0A"), DeviceRole.RightFoot),
                new Worn(new XrDeviceReport(Hmd, "OpenVR Headset(Vive MV)", "LHR-HH"), DeviceRole.Head),
                new Worn(new XrDeviceReport(LeftController, "OpenVR Controller(VIVE Controller Pro MV) - Left", "LHR-LL"), DeviceRole.LeftHand),
                new Worn(new XrDeviceReport(XrDeviceKind.TrackedDevice, "OpenVR Tracked Device(VIVE Tracker Pro MV)", "LHR-0B"), DeviceRole.LeftFoot),
            });
            Assert.That(header.Devices.Count, Is.EqualTo(6), "the base station is not a body device");
            Assert.That(new[] { header.Devices[3].Serial, header.Devices[4].Serial, header.Devices[5].Serial }, Is.EqualTo(new[] { "LHR-0A", "LHR-0B", "LHR-0C" }),
                "trackers without roles come in serial order");
            for (int d = 3; d < 6; d++) Assert.That(header.Devices[d].RuntimeRole, Is.EqualTo(DeviceRole.None));

            Calibrator calibrator = Calibrate(header, wornAt);
            Assert.That(calibrator.LastStep.Error, Is.EqualTo(CalibrationError.None), calibrator.LastStep.Message);
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.Pelvis), Is.EqualTo(5), "LHR-0C, on the waist");
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.LeftFoot), Is.EqualTo(4), "LHR-0B");
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.RightFoot), Is.EqualTo(3), "LHR-0A");
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.LeftHand), Is.EqualTo(1));
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.RightHand), Is.EqualTo(2));
        }

        private static Worn[] OpenXR(DeviceRole roleOnLeftFoot, DeviceRole roleOnRightFoot) => new[]
        {
            new Worn(new XrDeviceReport(ViveTrackerRoles.Characteristics(roleOnRightFoot), ViveTrackerRoles.DeviceName, ""), DeviceRole.RightFoot),
            new Worn(new XrDeviceReport(Hmd, "Head Tracking - OpenXR", ""), DeviceRole.Head),
            new Worn(new XrDeviceReport(ViveTrackerRoles.Characteristics(DeviceRole.Pelvis), ViveTrackerRoles.DeviceName, ""), DeviceRole.Pelvis),
            new Worn(new XrDeviceReport(RightController, "HTC Vive Controller OpenXR", ""), DeviceRole.RightHand),
            new Worn(new XrDeviceReport(ViveTrackerRoles.Characteristics(roleOnLeftFoot), ViveTrackerRoles.DeviceName, ""), DeviceRole.LeftFoot),
            new Worn(new XrDeviceReport(LeftController, "HTC Vive Controller OpenXR", ""), DeviceRole.LeftHand),
        };

        [Test]
        public void OpenXRTrackerRolesThatAgreeWithTheBodyAreAccepted()
        {
            var (header, wornAt) = Register(OpenXR(DeviceRole.LeftFoot, DeviceRole.RightFoot));
            Assert.That(new[] { header.Devices[3].RuntimeRole, header.Devices[4].RuntimeRole, header.Devices[5].RuntimeRole },
                Is.EqualTo(new[] { DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot }), "role order");
            Calibrator calibrator = Calibrate(header, wornAt);
            Assert.That(calibrator.LastStep.Error, Is.EqualTo(CalibrationError.None), calibrator.LastStep.Message);
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.Pelvis), Is.EqualTo(3));
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.LeftFoot), Is.EqualTo(4));
            Assert.That(calibrator.DeviceIndexOf(DeviceRole.RightFoot), Is.EqualTo(5));
        }

        [Test]
        public void OpenXRTrackerRolesSwappedInTheRuntimeAreRefusedNotTrusted()
        {
            // SteamVR's Manage Trackers gave the left-foot role to the tracker on the right foot, and the other way round.
            var (header, wornAt) = Register(OpenXR(DeviceRole.RightFoot, DeviceRole.LeftFoot));
            Calibrator calibrator = Calibrate(header, wornAt);
            Assert.That(calibrator.LastStep.Error, Is.EqualTo(CalibrationError.RuntimeRoleMismatch), calibrator.LastStep.Message);
        }

        [Test]
        public void TrackingSpaceIsBroughtToTheWorldThroughTheXrOriginsCameraOffset()
        {
            // An XR Origin at (2, 0, -3) turned 90 degrees about +y (the app moved the player there), its Camera Offset
            // 1.36 m up (Device tracking mode's CameraYOffset). The runtime reports the HMD 0.1 m right, 0.3 m up and 0.2 m
            // forward of the tracking origin, looking straight ahead.
            var origin = new RigidPose(new Vector3(2f, 0f, -3f), Rotations.AngleAxis(90f, Vector3.UnitY));
            RigidPose cameraOffset = origin * new RigidPose(new Vector3(0f, 1.36f, 0f), Quaternion.Identity);
            var space = new TrackingSpace(cameraOffset);
            var hmd = new RigidPose(new Vector3(0.1f, 0.3f, 0.2f), Quaternion.Identity);

            RigidPose world = space.ToWorld(hmd);
            // Unity's 90 degrees about +y turn +z into +x and +x into -z.
            Approx.Near(new Vector3(2.2f, 1.66f, -3.1f), world.Position, 1e-5f, "HMD in the world");
            Approx.Near(new Vector3(1f, 0f, 0f), Vector3.Transform(Vector3.UnitZ, world.Rotation), 1e-5f, "looking along the origin's forward");

            // A source that reads transforms (the XR Interaction Toolkit's camera, moved by its Tracked Pose Driver) brings
            // their world pose back to the same tracking-space pose the XR input source reports.
            RigidPose back = space.ToTracking(world);
            Approx.Near(hmd.Position, back.Position, 1e-5f, "back in tracking space");
            Assert.That(Math.Abs(Quaternion.Dot(hmd.Rotation, back.Rotation)), Is.EqualTo(1f).Within(1e-6f));
        }
    }
}
