using System;
using System.Reflection;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// A bad tracking setting fails where it is set, naming it (found in review: SmoothingBeta = -1 was taken, and every
    /// frame's Update from the calibration on threw, naming the filter's 'minCutoff'; EaseSeconds = NaN would have held a
    /// lost part for good, RecoveryMaxSpeed = 0 never let a part come back).
    /// </summary>
    public class TrackingSettingsTests
    {
        private static readonly string[] Names =
        {
            nameof(TrackingSettings.MaxSpeed), nameof(TrackingSettings.MaxAngularSpeedDegrees), nameof(TrackingSettings.ReacquireSeconds),
            nameof(TrackingSettings.BodyReachFactor), nameof(TrackingSettings.BodyReachMargin), nameof(TrackingSettings.HoldSeconds),
            nameof(TrackingSettings.EaseSeconds), nameof(TrackingSettings.RecoveryTimeConstant), nameof(TrackingSettings.RecoveryMaxSpeed),
            nameof(TrackingSettings.RecoveryMaxAngularSpeedDegrees), nameof(TrackingSettings.SmoothingMinCutoff),
            nameof(TrackingSettings.SmoothingBeta), nameof(TrackingSettings.SwapWindowSeconds), nameof(TrackingSettings.SwapMargin),
        };

        [Test]
        public void EveryNumberIsCheckedWhereItIsSet()
        {
            // Every float setting is in the list (a new one must say what it accepts).
            foreach (PropertyInfo p in typeof(TrackingSettings).GetProperties())
                if (p.PropertyType == typeof(float)) Assert.That(Names, Does.Contain(p.Name), "a new setting: add it here");
            foreach (string name in Names)
            {
                PropertyInfo p = typeof(TrackingSettings).GetProperty(name);
                var settings = new TrackingSettings();
                float before = (float)p.GetValue(settings);
                foreach (float bad in new[] { float.NaN, -1f, float.NegativeInfinity })
                {
                    var e = Assert.Throws<TargetInvocationException>(() => p.SetValue(settings, bad), name + " = " + bad);
                    Assert.That(e.InnerException, Is.TypeOf<ArgumentOutOfRangeException>());
                    Assert.That(((ArgumentOutOfRangeException)e.InnerException).ParamName, Is.EqualTo(name));
                    StringAssert.Contains("TrackingSettings." + name, e.InnerException.Message);
                }
                Assert.That(p.GetValue(settings), Is.EqualTo(before), name + " kept its value");
                p.SetValue(settings, before * 2f); // a plausible change is taken
                Assert.That(p.GetValue(settings), Is.EqualTo(before * 2f));
            }
        }

        /// <summary>
        /// The calibration's and the proportion fit's numbers are checked where they are set too (a NaN window or stillness
        /// never let the wearer count as still; a NaN foot tracker offset put NaN into the placement).
        /// </summary>
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.WindowSeconds), new[] { float.NaN, 0f, -1f, float.PositiveInfinity })]
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.StillPosition), new[] { float.NaN, 0f, -1f })]
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.StillRotationDegrees), new[] { float.NaN, 0f, -1f })]
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.FloorHeight), new[] { float.PositiveInfinity, float.NegativeInfinity })]
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.FootTrackerHeight), new[] { float.NaN, -0.01f, float.PositiveInfinity })]
        [TestCase(typeof(CalibrationSettings), nameof(CalibrationSettings.FootTrackerForward), new[] { float.NaN, float.PositiveInfinity })]
        [TestCase(typeof(ProportionSettings), nameof(ProportionSettings.PelvisTrackerAboveHips), new[] { float.NaN, float.NegativeInfinity })]
        [TestCase(typeof(ProportionSettings), nameof(ProportionSettings.PelvisTrackerTolerance), new[] { float.NaN, -0.01f, float.PositiveInfinity })]
        [TestCase(typeof(ProportionSettings), nameof(ProportionSettings.ControllerTolerance), new[] { float.NaN, -0.01f, float.PositiveInfinity })]
        [TestCase(typeof(ProportionSettings), nameof(ProportionSettings.HmdTolerance), new[] { float.NaN, -0.01f, float.PositiveInfinity })]
        [TestCase(typeof(PipelineSettings), nameof(PipelineSettings.ShrugReleaseSeconds), new[] { float.NaN, -1f, float.PositiveInfinity })]
        [TestCase(typeof(PipelineSettings), nameof(PipelineSettings.SpineChordNoiseMetres), new[] { float.NaN, -0.001f, float.PositiveInfinity })]
        [TestCase(typeof(PipelineSettings), nameof(PipelineSettings.SpineChordCutoffHz), new[] { float.NaN, -1f, float.PositiveInfinity })]
        [TestCase(typeof(PipelineSettings), nameof(PipelineSettings.StraightLegCutoffHz), new[] { float.NaN, -1f, float.PositiveInfinity })]
        [TestCase(typeof(PipelineSettings), nameof(PipelineSettings.StraightArmCutoffHz), new[] { float.NaN, -1f, float.NegativeInfinity })]
        public void TheCalibrationsNumbersAreCheckedWhereTheyAreSet(Type type, string name, float[] bad)
        {
            PropertyInfo p = type.GetProperty(name);
            object settings = Activator.CreateInstance(type);
            object before = p.GetValue(settings);
            foreach (float value in bad)
            {
                var e = Assert.Throws<TargetInvocationException>(() => p.SetValue(settings, value), name + " = " + value);
                Assert.That(((ArgumentOutOfRangeException)e.InnerException).ParamName, Is.EqualTo(name));
                StringAssert.Contains(type.Name + "." + name, e.InnerException.Message);
            }
            Assert.That(p.GetValue(settings), Is.EqualTo(before), "kept");
        }

        [Test]
        public void TheFloorMayBeLeftToTheFeet() => Assert.That(new CalibrationSettings { FloorHeight = float.NaN }.FloorHeight, Is.NaN);

        [TestCase(nameof(TrackingSettings.MaxSpeed)), TestCase(nameof(TrackingSettings.RecoveryMaxSpeed)), TestCase(nameof(TrackingSettings.SmoothingMinCutoff)),
         TestCase(nameof(TrackingSettings.SwapWindowSeconds)), TestCase(nameof(TrackingSettings.BodyReachFactor))]
        public void ALimitThatMustMoveRefusesZero(string name)
        {
            PropertyInfo p = typeof(TrackingSettings).GetProperty(name);
            Assert.Throws<TargetInvocationException>(() => p.SetValue(new TrackingSettings(), 0f));
        }

        /// <summary>
        /// Infinity turns a recovery speed limit off, and a repeated frame time while a part is blended back leaves it where
        /// it was (found in review: infinity times no time was NaN, and the hand's sample NaN).
        /// </summary>
        [Test]
        public void AnInfiniteRecoverySpeedAndARepeatedTimeGiveNoNaN()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 64);
            double t = 0;
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map);
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated));
            var settings = new TrackingSettings { RecoveryMaxSpeed = float.PositiveInfinity, RecoveryMaxAngularSpeedDegrees = float.PositiveInfinity };
            var roles = new PerRole<int>(-1);
            foreach (DeviceRole role in BodyRoles.All) roles[role] = pipeline.DeviceIndexOf(role);
            var continuity = new TrackingContinuity(pipeline.Profile, roles, pipeline.ScaledAvatar, pipeline.Pose, settings);
            var samples = new DeviceSample[6];
            var effective = new DeviceSample[6];
            int hand = pipeline.DeviceIndexOf(DeviceRole.LeftHand);
            wearer.Sample(samples, 0f, 0f);
            continuity.Apply(10.0, samples, pipeline.Pose, effective);
            var lost = (DeviceSample[])samples.Clone();
            lost[hand] = new DeviceSample(samples[hand].Pose, false);
            continuity.Apply(10.1, lost, pipeline.Pose, effective);
            var back = (DeviceSample[])samples.Clone();
            back[hand] = new DeviceSample(new RigidPose(samples[hand].Pose.Position + new System.Numerics.Vector3(0.1f, 0f, 0f),
                Rotations.AngleAxis(30f, System.Numerics.Vector3.UnitY) * samples[hand].Pose.Rotation), true);
            continuity.Apply(10.2, back, pipeline.Pose, effective);
            RigidPose blended = effective[hand].Pose;
            continuity.Apply(10.2, back, pipeline.Pose, effective); // the same time again
            Assert.That(effective[hand].Pose.IsValid, Is.True, effective[hand].Pose.ToString());
            Approx.Near(blended, effective[hand].Pose, 1e-6f, 1e-3f, "no time, no move");
        }

        [Test]
        public void TheFiltersErrorsNameTheirOwnParameter()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OneEuroFilter(1, 1f, -1f)).ParamName, Is.EqualTo("beta"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OneEuroFilter(1, 1f, 1f, 0f)).ParamName, Is.EqualTo("derivativeCutoff"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OneEuroFilter(1, float.PositiveInfinity, 1f)).ParamName, Is.EqualTo("minCutoff"));
        }
    }
}
