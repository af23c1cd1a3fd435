using System;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>Issue 15: measurements and fitted proportions in the calibration result and the saved profile (version 2); version 1 profiles still load.</summary>
    public class ProfileProportionsTests
    {
        private static Calibrator Calibrated(ScaleMode mode, out Wearer wearer)
        {
            wearer = new Wearer("mocapbank_30fps.bvh", 31);
            var settings = new CalibrationSettings();
            settings.Proportions.Mode = mode;
            var calibrator = new Calibrator(wearer.Devices, Proportions.ScaleLimbs(wearer.Map, 1.1f, 0.9f), settings);
            wearer.StandInTPose(new RigidPose(new Vector3(-1, 0, 0.5f), Rotations.AngleAxis(130f, Vector3.UnitY)));
            double t = 0;
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.WalkIn), calibrator.LastStep.Message);
            wearer.StandInTPose(calibrator.Profile.Placement);
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.Calibrated), calibrator.LastStep.Message);
            return calibrator;
        }

        [Test]
        public void TheResultMeasuresTheWearerAndTheAvatarIsFittedToIt()
        {
            Calibrator c = Calibrated(ScaleMode.Fitted, out Wearer wearer);
            CalibrationProfile p = c.Profile;
            BodyMeasurements truth = ProportionFitter.MeasureSkeleton(wearer.Map);
            Assert.That(p.ScaleMode, Is.EqualTo(ScaleMode.Fitted));
            Assert.That(p.Measurements.Windows, Is.EqualTo(2), "T-pose and walk-in averaged");
            Assert.That(p.Measurements.EyeHeight.Value, Is.EqualTo(truth.EyeHeight.Value).Within(0.005));
            Assert.That(p.Measurements.ArmSpan.Value, Is.EqualTo(truth.ArmSpan.Value).Within(0.01));
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Assert.That(p.Measurements.ArmLength(side).Value, Is.EqualTo(truth.ArmLength(side).Value).Within(p.Measurements.ArmLength(side).Uncertainty));
                Assert.That(p.Measurements.LegLength(side).Value, Is.EqualTo(truth.LegLength(side).Value).Within(p.Measurements.LegLength(side).Uncertainty));
            }
            // The avatar's arms were 10 % short and its legs 10 % long: fitted back to the wearer's.
            Assert.That(p.Proportions.LeftArm, Is.GreaterThan(1.05f));
            Assert.That(p.Proportions.LeftLeg, Is.LessThan(0.96f));
            BodyMeasurements avatar = ProportionFitter.MeasureSkeleton(c.ScaledAvatar);
            Assert.That(avatar.EyeHeight.Value, Is.EqualTo(p.Measurements.EyeHeight.Value).Within(0.001), "eye heights match");
            Assert.That(avatar.LeftArmLength.Value, Is.EqualTo(truth.LeftArmLength.Value).Within(0.012));
            // The offsets were computed on the fitted avatar: the hand joint at the walk-in is the fitted avatar's.
            Assert.That(Vector3.Distance(p.JointAtCalibration(DeviceRole.LeftHand).Position, c.AvatarPose.World[c.ScaledAvatar[HumanoidBone.LeftHand]].Position), Is.LessThan(1e-5f));
        }

        [Test]
        public void UniformModeMeasuresButDoesNotFit()
        {
            Calibrator c = Calibrated(ScaleMode.Uniform, out _);
            CalibrationProfile p = c.Profile;
            Assert.That(p.ScaleMode, Is.EqualTo(ScaleMode.Uniform));
            Assert.That(p.Proportions.IsUniform, Is.True);
            Assert.That(p.Measurements, Is.Not.Null);
            // The paper's scale: the scaled avatar's eyes at the wearer's (this rig has no eye bones: 7 cm above its head
            // joint once scaled, TPoser.ScaleForEyeHeight; it was the ratio of eye heights with that offset unscaled).
            BodyMeasurements scaled = ProportionFitter.MeasureSkeleton(c.ScaledAvatar);
            Assert.That(scaled.EyeHeight.Value, Is.EqualTo(p.WearerEyeHeight).Within(1e-4), "the paper's scale");
        }

        [Test]
        public void ProportionsAndMeasurementsRoundTripAndRestore()
        {
            Calibrator c = Calibrated(ScaleMode.Fitted, out Wearer wearer);
            CalibrationProfile p = c.Profile;
            CalibrationProfile q = CalibrationProfileStore.FromJson(CalibrationProfileStore.ToJson(p));
            Assert.That(q.ScaleMode, Is.EqualTo(ScaleMode.Fitted));
            Assert.That(q.Proportions, Is.EqualTo(p.Proportions));
            var a = p.Measurements.All();
            var b = q.Measurements.All();
            for (int i = 0; i < a.Length; i++) Assert.That(b[i].value, Is.EqualTo(a[i].value), a[i].name);
            // Restored, the same fitted avatar stands where it stood.
            var restored = new Calibrator(wearer.Devices, Proportions.ScaleLimbs(wearer.Map, 1.1f, 0.9f));
            Assert.That(restored.TryRestore(q), Is.True);
            for (int j = 0; j < c.AvatarPose.World.Length; j++)
                Assert.That(Vector3.Distance(restored.AvatarPose.World[j].Position, c.AvatarPose.World[j].Position), Is.LessThan(1e-4f));
        }

        [Test]
        public void VersionOneProfilesLoadAsUniform()
        {
            CalibrationProfile p = Calibrated(ScaleMode.Uniform, out _).Profile;
            JsonNode v2 = JsonNode.Parse(CalibrationProfileStore.ToJson(p));
            // A version 1 file: what the package wrote before issue 15 (no scale mode, proportions or measurements).
            string v1 = CalibrationProfileStore.ToJson(p).Replace("\"version\": 2", "\"version\": 1");
            int start = v1.IndexOf("\"scaleMode\"", StringComparison.Ordinal), end = v1.IndexOf("\"roles\"", StringComparison.Ordinal);
            Assume.That(start, Is.GreaterThan(0));
            v1 = v1.Remove(start, end - start);
            Assert.That(v1, Does.Contain("\"version\": 1").And.Not.Contain("proportions"));
            CalibrationProfile old = CalibrationProfileStore.FromJson(v1);
            Assert.That(old.ScaleMode, Is.EqualTo(ScaleMode.Uniform));
            Assert.That(old.Proportions.IsUniform, Is.True);
            Assert.That(old.Measurements, Is.Null);
            Assert.That(old.AvatarScale, Is.EqualTo(p.AvatarScale));
            Assert.That(v2["version"].Number, Is.EqualTo(2));
        }

        [TestCase("\"leftArm\": 1", "\"leftArm\": 9", "leftArm")]
        [TestCase("\"scaleMode\": \"uniform\"", "\"scaleMode\": \"stretchy\"", "scaleMode")]
        [TestCase("\"version\": 2", "\"version\": 3", "version")]
        public void BadProportionsAreTypedErrorsNamingTheLine(string from, string to, string named)
        {
            string json = CalibrationProfileStore.ToJson(Calibrated(ScaleMode.Uniform, out _).Profile);
            Assume.That(json, Does.Contain(from));
            var e = Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(json.Replace(from, to), "wearer.json"));
            Assert.That(e.Message, Does.StartWith("wearer.json:").And.Contain(named));
        }
    }
}
