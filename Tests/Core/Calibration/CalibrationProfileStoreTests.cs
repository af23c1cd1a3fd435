using System;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class CalibrationProfileStoreTests
    {
        private static Calibrator Calibrated(out Wearer wearer)
        {
            wearer = new Wearer("mocapbank_30fps.bvh", 31);
            var calibrator = new Calibrator(wearer.Devices, wearer.Map);
            wearer.StandInTPose(new RigidPose(new Vector3(-1, 0, 0.5f), Rotations.AngleAxis(130f, Vector3.UnitY)));
            double t = 0;
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            wearer.StandInTPose(calibrator.Profile.Placement);
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.Calibrated), calibrator.LastStep.Message);
            return calibrator;
        }

        [Test]
        public void SaveLoadRoundTripsEveryValue()
        {
            CalibrationProfile p = Calibrated(out _).Profile;
            string dir = Path.Combine(Path.GetTempPath(), "avatargo-profile-" + Guid.NewGuid().ToString("N"));
            string path = Path.Combine(dir, "wearer.json");
            try
            {
                CalibrationProfileStore.Save(p, path);
                CalibrationProfileStore.Save(p, path); // replacing an existing profile
                Assert.That(Directory.GetFiles(dir), Has.Length.EqualTo(1), "no temporary file left behind");
                CalibrationProfile q = CalibrationProfileStore.Load(path);
                Assert.That(q.AvatarScale, Is.EqualTo(p.AvatarScale));
                Assert.That(q.RootToHead, Is.EqualTo(p.RootToHead));
                foreach (DeviceRole role in BodyRoles.All)
                {
                    Assert.That(q.Serial(role), Is.EqualTo(p.Serial(role)));
                    Assert.That(q.DeviceId(role), Is.EqualTo(p.DeviceId(role)));
                    Approx.Near(p.JointInDevice(role), q.JointInDevice(role), 1e-6f, 1e-3f, role.ToString());
                }
                Assert.That(CalibrationProfileStore.Load(path).WithFixedOffsets().JointInDevice(DeviceRole.Pelvis).Position, Is.EqualTo(Vector3.Zero));
            }
            finally { if (Directory.Exists(dir)) Directory.Delete(dir, true); }
        }

        [TestCase("{}")]
        [TestCase("[1, 2")]
        [TestCase("{\"format\": \"avatargo-calibration-profile\", \"version\": 99}")]
        [TestCase("{\"format\": \"something-else\", \"version\": 1}")]
        public void MalformedProfilesAreFormatErrors(string json)
        {
            Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(json));
        }

        [Test]
        public void TruncatedAndTamperedSavesAreFormatErrorsNamingThePlace()
        {
            string json = CalibrationProfileStore.ToJson(Calibrated(out _).Profile);
            var e = Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(json.Substring(0, json.Length / 2)));
            StringAssert.Contains("line", e.Message);
            Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(json.Replace("\"rotation\": [", "\"rotation\": [9, ")));
        }

        [Test]
        public void RestoringWithTheSameDevicesSkipsCalibrationAndGivesTheSameTargets()
        {
            Calibrator first = Calibrated(out Wearer wearer);
            CalibrationProfile loaded = CalibrationProfileStore.FromJson(CalibrationProfileStore.ToJson(first.Profile));
            var second = new Calibrator(wearer.Devices, wearer.Map);
            Assert.That(second.TryRestore(loaded), Is.True);
            Assert.That(second.State, Is.EqualTo(CalibrationState.Calibrated));
            var a = new BodyTargetMapper(first.Profile, wearer.Devices, first.ScaledAvatar, first.AvatarPose);
            var b = new BodyTargetMapper(second.Profile, wearer.Devices, second.ScaledAvatar, second.AvatarPose);
            var samples = new DeviceSample[6];
            wearer.Sample(samples, 0, 0);
            BodyTargets ta = default, tb = default;
            a.Compute(samples, ref ta);
            b.Compute(samples, ref tb);
            Approx.Near(ta.Hips, tb.Hips, 1e-5f, 0.01f, "hips");
            Approx.Near(ta.LeftHand.Goal, tb.LeftHand.Goal, 1e-5f, 0.01f, "left hand");

            var otherDevices = (DeviceInfo[])wearer.Devices.Clone();
            otherDevices[0] = new DeviceInfo(otherDevices[0].Id, otherDevices[0].Class, "SOMEONE-ELSES");
            Assert.That(new Calibrator(otherDevices, wearer.Map).TryRestore(loaded), Is.False, "another tracker is worn");
        }

        /// <summary>
        /// A restore that cannot match its devices says why (found in review: every case was told "its devices are not all
        /// connected", a profile made on a runtime without serials too, and two roles with one serial landed on one device).
        /// </summary>
        [Test]
        public void ARestoreThatCannotMatchItsDevicesSaysWhy()
        {
            Calibrator first = Calibrated(out Wearer wearer);
            string json = CalibrationProfileStore.ToJson(first.Profile);
            var other = (DeviceInfo[])wearer.Devices.Clone();
            other[0] = new DeviceInfo(other[0].Id, other[0].Class, "SOMEONE-ELSES");
            Assert.That(new Calibrator(other, wearer.Map).TryRestore(CalibrationProfileStore.FromJson(json), out string why), Is.False);
            Assert.That(why, Does.Contain("no connected device has the").And.Contain("serial"));
            string left = first.Profile.Serial(DeviceRole.LeftHand), right = first.Profile.Serial(DeviceRole.RightHand);
            Assume.That(left, Is.Not.Empty);
            CalibrationProfile twice = CalibrationProfileStore.FromJson(json.Replace("\"" + right + "\"", "\"" + left + "\""));
            var calibrator = new Calibrator(wearer.Devices, wearer.Map);
            Assert.That(calibrator.TryRestore(twice, out why), Is.False, "two roles, one serial");
            Assert.That(why, Does.Contain("the same serial '" + left + "'"));
            CalibrationProfile none = CalibrationProfileStore.FromJson(json.Replace("\"" + left + "\"", "\"\""));
            Assert.That(calibrator.TryRestore(none, out why), Is.False, "no serial");
            Assert.That(why, Does.Contain("no serial for the LeftHand device"));
            Assert.That(calibrator.State, Is.Not.EqualTo(CalibrationState.Calibrated), "nothing changed");
        }

        [Test]
        public void RescalingKeepsTheAvatarOnItsFloorSpot()
        {
            CalibrationProfile p = Calibrated(out _).Profile;
            CalibrationProfile bigger = p.WithAvatarScale(p.AvatarScale * 1.1f);
            Vector3 origin = p.Placement.Position;
            foreach (DeviceRole role in BodyRoles.All)
            {
                // The joint at calibration moved away from the floor spot by exactly the ratio; device unchanged.
                Vector3 expected = origin + (p.JointAtCalibration(role).Position - origin) * 1.1f;
                Approx.Near(expected, bigger.JointAtCalibration(role).Position, 1e-5f, role.ToString());
                Assert.That(bigger.DeviceAtCalibration(role), Is.EqualTo(p.DeviceAtCalibration(role)));
                Approx.Near(expected, (bigger.DeviceAtCalibration(role) * bigger.JointInDevice(role)).Position, 1e-5f, role + " via offsets");
            }
        }
    }
}
