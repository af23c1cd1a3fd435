using System;
using System.Numerics;
using System.Text;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The calibrator's parts on their own: the averaging window, device identification and the T-pose checks.</summary>
    public class CalibrationPartsTests
    {
        private static DeviceSample At(float x, float y, float z) => new DeviceSample(new RigidPose(new Vector3(x, y, z), Quaternion.Identity), true);

        [Test]
        public void TheWindowAveragesItsLastHalfSecondAndCountsTrackedFrames()
        {
            var window = new SampleWindow(1, new CalibrationSettings(), capacity: 64);
            var one = new DeviceSample[1];
            // 2 s at 90 Hz: x = 0 for the first 1.44 s, then 1 cm, with every fifth frame of the last 0.5 s lost.
            for (int i = 0; i < 180; i++)
            {
                one[0] = i < 130 ? At(0, 1, 0) : i % 5 == 0 ? DeviceSample.Lost : At(0.01f, 1, 0);
                window.Add(i / 90.0, one);
            }
            WindowAverage a = window.Average(0, 179 / 90.0);
            Assert.That(a.Position.X, Is.EqualTo(0.01f).Within(1e-6f), "only the window's samples, lost ones left out");
            Assert.That(a.TrackedFraction, Is.EqualTo(37f / 46f).Within(1e-6f), "46 frames in 0.5 s, 9 of them lost");
            Assert.That(a.IsTracked, Is.True);
            Assert.That(a.IsStill, Is.True);
        }

        [Test]
        public void AMovementOfMoreThanTwoCentimetresIsNotStill()
        {
            var window = new SampleWindow(1, new CalibrationSettings());
            var one = new DeviceSample[1];
            for (int i = 0; i < 45; i++)
            {
                one[0] = At(i * 0.002f, 1, 0); // 9 cm over the window
                window.Add(i / 90.0, one);
            }
            Assert.That(window.Average(0, 44 / 90.0).IsStill, Is.False);
        }

        /// <summary>
        /// A window its frames do not cover yet is not still (found in review: a press two frames after the calibrator was
        /// made averaged those two frames and passed as still); from 80 % of the window on it is.
        /// </summary>
        [Test]
        public void AWindowNotYetCoveredIsNotStill()
        {
            var window = new SampleWindow(1, new CalibrationSettings());
            var one = new DeviceSample[1] { At(0, 1, 0) };
            for (int i = 0; i < 2; i++) window.Add(i / 90.0, one);
            Assert.That(window.Average(0, 1 / 90.0).IsTracked, Is.True);
            Assert.That(window.Average(0, 1 / 90.0).IsStill, Is.False, "two frames");
            for (int i = 2; i < 36; i++) window.Add(i / 90.0, one);
            Assert.That(window.Average(0, 35 / 90.0).IsStill, Is.False, "0.39 s of a 0.5 s window");
            window.Add(36 / 90.0, one);
            Assert.That(window.Average(0, 36 / 90.0).IsStill, Is.True, "0.4 s");
            var small = new SampleWindow(1, new CalibrationSettings(), capacity: 8);
            for (int i = 0; i < 20; i++) small.Add(i / 1000.0, one);
            Assert.That(small.Average(0, 19 / 1000.0).IsStill, Is.True, "a full ring covers what it can hold (1 kHz into 8 frames)");
        }

        [Test]
        public void AnEmptyWindowIsNotTracked()
        {
            var window = new SampleWindow(2, new CalibrationSettings());
            Assert.That(window.Average(1, 0).IsTracked, Is.False);
            Assert.Throws<ArgumentOutOfRangeException>(() => window.Average(2, 0));
        }

        private static readonly DeviceInfo[] Devices =
        {
            new DeviceInfo(0, DeviceClass.Tracker, "T1"), new DeviceInfo(1, DeviceClass.Controller, "C1"), new DeviceInfo(2, DeviceClass.Hmd, "H"),
            new DeviceInfo(3, DeviceClass.Tracker, "T2"), new DeviceInfo(4, DeviceClass.Controller, "C2"), new DeviceInfo(5, DeviceClass.Tracker, "T3"),
            new DeviceInfo(6, DeviceClass.Tracker, "T4"),
        };

        // A wearer facing +Z with eyes at 1.6 m: right hand at +x, a fourth tracker on a table 1.5 m away.
        private static WindowAverage[] TPose()
        {
            WindowAverage A(float x, float y, float z) => new WindowAverage(new RigidPose(new Vector3(x, y, z), Quaternion.Identity), 1f, true);
            return new[] { A(-0.1f, 0.08f, 0.05f), A(0.8f, 1.4f, 0f), A(0f, 1.6f, 0.05f), A(0f, 0.95f, -0.1f), A(-0.8f, 1.4f, 0f), A(0.1f, 0.08f, 0.05f), A(1.5f, 0.9f, 1f) };
        }

        [Test]
        public void IdentificationFindsEveryRoleAndIgnoresATrackerOnATable()
        {
            var identifier = new DeviceIdentifier(Devices, new CalibrationSettings());
            var explanation = new StringBuilder();
            WindowAverage[] averages = TPose();
            Assert.That(identifier.Select(averages, out DeviceSelection chosen, out _, explanation), Is.EqualTo(CalibrationError.None));
            Assert.That(chosen.Hmd, Is.EqualTo(2));
            Assert.That(chosen.Pelvis, Is.EqualTo(3));
            Assert.That(new[] { chosen.FootA, chosen.FootB }, Is.EquivalentTo(new[] { 0, 5 }));
            Assert.That(chosen.EyeHeight, Is.EqualTo(1.6f).Within(1e-6f));
            Assert.That(explanation.ToString(), Does.Contain("ignored"));
            var roles = new PerRole<int>(-1);
            Assert.That(identifier.AssignSides(chosen, averages, Vector3.UnitX, roles, out _), Is.EqualTo(CalibrationError.None));
            Assert.That(roles[DeviceRole.RightHand], Is.EqualTo(1));
            Assert.That(roles[DeviceRole.LeftHand], Is.EqualTo(4));
            Assert.That(roles[DeviceRole.LeftFoot], Is.EqualTo(0));
            Assert.That(roles[DeviceRole.RightFoot], Is.EqualTo(5));
            // Facing the other way, left and right swap.
            Assert.That(identifier.AssignSides(chosen, averages, -Vector3.UnitX, roles, out _), Is.EqualTo(CalibrationError.None));
            Assert.That(roles[DeviceRole.RightHand], Is.EqualTo(4));
        }

        /// <summary>
        /// A spare controller (on a desk, listed before the held ones) is ignored: the two that stand as the hands of a T-pose
        /// are used (found in review: the first two in device order were, and the wearer was told to raise both arms forever).
        /// </summary>
        [Test]
        public void IdentificationIgnoresASpareController()
        {
            var devices = new DeviceInfo[Devices.Length + 1];
            devices[0] = new DeviceInfo(10, DeviceClass.Controller, "SPARE");
            Array.Copy(Devices, 0, devices, 1, Devices.Length);
            WindowAverage[] tpose = TPose();
            var averages = new WindowAverage[tpose.Length + 1];
            averages[0] = new WindowAverage(new RigidPose(new Vector3(0.9f, 0.75f, 0.8f), Quaternion.Identity), 1f, true); // on a desk
            Array.Copy(tpose, 0, averages, 1, tpose.Length);
            var identifier = new DeviceIdentifier(devices, new CalibrationSettings());
            var explanation = new StringBuilder();
            Assert.That(identifier.Select(averages, out DeviceSelection chosen, out _, explanation), Is.EqualTo(CalibrationError.None));
            var roles = new PerRole<int>(-1);
            Assert.That(identifier.AssignSides(chosen, averages, Vector3.UnitX, roles, out _), Is.EqualTo(CalibrationError.None));
            Assert.That(roles[DeviceRole.RightHand], Is.EqualTo(2), "C1, held out to the right");
            Assert.That(roles[DeviceRole.LeftHand], Is.EqualTo(5), "C2, held out to the left");
            Assert.That(explanation.ToString(), Does.Contain("3 controllers are tracked"));
            Assert.That(new TPoseValidator(new CalibrationSettings()).CheckPosture(chosen, averages, out _), Is.EqualTo(CalibrationError.None));
        }

        [Test]
        public void TheValidatorChecksPostureAndThePlane()
        {
            var identifier = new DeviceIdentifier(Devices, new CalibrationSettings());
            var validator = new TPoseValidator(new CalibrationSettings());
            WindowAverage[] averages = TPose();
            identifier.Select(averages, out DeviceSelection chosen, out _, new StringBuilder());
            Assert.That(validator.CheckPosture(chosen, averages, out _), Is.EqualTo(CalibrationError.None));
            Assert.That(validator.FitBodyPlane(chosen, averages, out Vector3 forward), Is.EqualTo(CalibrationError.None));
            Assert.That(Vector3.Dot(forward, Vector3.UnitZ), Is.GreaterThan(0.99f), "the wearer faces +Z");
            // Hands brought together in front: not a T-pose.
            averages[1] = new WindowAverage(new RigidPose(new Vector3(0.1f, 1.4f, 0.4f), Quaternion.Identity), 1f, true);
            averages[4] = new WindowAverage(new RigidPose(new Vector3(-0.1f, 1.4f, 0.4f), Quaternion.Identity), 1f, true);
            Assert.That(validator.CheckPosture(chosen, averages, out string detail), Is.EqualTo(CalibrationError.ArmsNotSpread));
            Assert.That(detail, Does.Contain("0.20 m apart"));
        }
    }
}
