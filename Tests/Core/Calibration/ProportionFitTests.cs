using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Issue 15: the wearer measured at calibration and the avatar's legs and arms fitted to them, through the whole
    /// pipeline on recorded motion (mocap → synthetic session with random mountings and noise → calibration → solve),
    /// against the true joints. The avatar is the wearer's own skeleton with its legs 10 % longer and its arms 10 % shorter
    /// (<see cref="Proportions.ScaleLimbs"/>), or unchanged. What is asserted, and why it differs from the wording:
    /// fitting removes the error that the proportions cause, so the fitted avatar's knees and elbows are as close as the
    /// wearer's own proportions get (within a few mm), and the error uniform scaling adds over that is at least halved. The
    /// issue's "median at least halved" is not met on every joint, because with the wearer's own proportions the solver
    /// already has 15-95 mm of knee and elbow error on these clips (shoulders the six devices do not see, solver.md) that
    /// no scaling removes; the numbers are in Documentation~/calibration.md.
    /// </summary>
    public class ProportionFitTests
    {
        internal static string Simulate(BvhClip clip, int seed)
        {
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = seed });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            return text.ToString();
        }

        internal static EvaluationReport Evaluate(string session, ScaleMode mode, float legScale, float armScale)
        {
            using var reader = new SessionReader(new StringReader(session), "fit");
            HumanoidMap avatar = reader.Header.TruthHumanoid;
            if (legScale != 1f || armScale != 1f) avatar = Proportions.ScaleLimbs(avatar, legScale, armScale);
            var settings = new PipelineSettings();
            settings.Calibration.Proportions.Mode = mode;
            return SessionEvaluator.Evaluate(reader, settings, avatar);
        }

        // The mean of the two sides' medians.
        internal static double Median(EvaluationReport r, HumanoidBone left, HumanoidBone right) =>
            0.5 * (r.JointPositionMm[left].Median + r.JointPositionMm[right].Median);

        internal static double Knees(EvaluationReport r) => Median(r, HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg);
        internal static double Elbows(EvaluationReport r) => Median(r, HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm);

        /// <summary>Every measured length within <paramref name="tolerance"/> of the wearer's true one, and the truth within the stated uncertainty.</summary>
        internal static void AssertMeasured(EvaluationReport r, double tolerance, string what)
        {
            Assert.That(r.Profile, Is.Not.Null, $"{what}: calibration failed: {r.CalibrationMessage}");
            var measured = r.Profile.Measurements.All();
            var truth = r.TrueMeasurements.All();
            for (int i = 0; i < measured.Length; i++)
            {
                if (measured[i].name == "shoulderWidth") continue; // not observed: the avatar's, scaled (its uncertainty says so)
                Assert.That(measured[i].value.Value, Is.EqualTo(truth[i].value.Value).Within(tolerance), $"{what}: {measured[i].name} (m)");
                Assert.That(Math.Abs(measured[i].value.Value - truth[i].value.Value), Is.LessThanOrEqualTo(measured[i].value.Uncertainty),
                    $"{what}: {measured[i].name} within its stated uncertainty");
            }
        }

        internal static void AssertFittedBeatsUniform(string session, string what)
        {
            EvaluationReport own = Evaluate(session, ScaleMode.Uniform, 1f, 1f);
            EvaluationReport uniform = Evaluate(session, ScaleMode.Uniform, 1.1f, 0.9f);
            EvaluationReport fitted = Evaluate(session, ScaleMode.Fitted, 1.1f, 0.9f);
            Assert.That(fitted.Profile, Is.Not.Null, fitted.CalibrationMessage);
            AssertMeasured(fitted, 0.01, what);
            // The fitted avatar has the wearer's limbs (the avatar's were +10 % / -10 %), within the measurement's 1 cm.
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Assert.That(fitted.AvatarMeasurements.LegLength(side).Value, Is.EqualTo(fitted.TrueMeasurements.LegLength(side).Value).Within(0.012), $"{what}: fitted {side} leg (m)");
                Assert.That(fitted.AvatarMeasurements.ArmLength(side).Value, Is.EqualTo(fitted.TrueMeasurements.ArmLength(side).Value).Within(0.012), $"{what}: fitted {side} arm (m)");
            }
            Assert.That(fitted.AvatarMeasurements.EyeHeight.Value, Is.EqualTo(fitted.Profile.Measurements.EyeHeight.Value).Within(0.001), $"{what}: eye heights match");
            foreach (var (name, err) in new (string, Func<EvaluationReport, double>)[] { ("knees", Knees), ("elbows", Elbows) })
            {
                double excessUniform = err(uniform) - err(own), excessFitted = err(fitted) - err(own);
                TestContext.WriteLine($"{what} {name}: own {err(own):0.0} mm, uniform {err(uniform):0.0} mm, fitted {err(fitted):0.0} mm");
                // Where the proportions cost uniform scaling something measurable, fitting takes at least half of it back.
                if (excessUniform > 5.0) Assert.That(excessFitted, Is.LessThanOrEqualTo(0.5 * excessUniform), $"{what}: fitting removes at least half of what the proportions add at the {name}");
            }
            foreach (HumanoidBone joint in new[] { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg, HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm })
                Assert.That(fitted.JointPositionMm[joint].Median, Is.LessThanOrEqualTo(own.JointPositionMm[joint].Median + 5.0),
                    $"{what}: fitted {joint} median within 5 mm of the wearer's own proportions (uniform: {uniform.JointPositionMm[joint].Median:0.0} mm)");
            TestContext.WriteLine($"{what} unreachable with the arm bent: own {own.UnreachedWhileBentFrames}, uniform {uniform.UnreachedWhileBentFrames}, fitted {fitted.UnreachedWhileBentFrames} of {fitted.Frames}");
            Assert.That(fitted.UnreachedWhileBentFrames, Is.LessThanOrEqualTo(uniform.UnreachedWhileBentFrames / 2), $"{what}: hands reach far more often");
            // Issue 15: no frame with a hand out of reach while the wearer's own arm is bent (the held shrugs bring the
            // shoulders where the hands reach; before them mocapbank had 141 such frames fitted and 142 with its own arms).
            Assert.That(fitted.UnreachedWhileBentFrames, Is.EqualTo(0), $"{what}: no hand out of reach while the wearer's arm is bent");
            Assert.That(own.UnreachedWhileBentFrames, Is.EqualTo(0), $"{what}: nor with the wearer's own arms");
        }

        internal static void AssertOwnProportionsUnchanged(string session, string what)
        {
            EvaluationReport uniform = Evaluate(session, ScaleMode.Uniform, 1f, 1f);
            EvaluationReport fitted = Evaluate(session, ScaleMode.Fitted, 1f, 1f);
            Assert.That(fitted.Profile, Is.Not.Null, fitted.CalibrationMessage);
            BodyProportions p = fitted.Profile.Proportions;
            foreach (float ratio in new[] { p.LeftLeg, p.RightLeg, p.LeftArm, p.RightArm })
                Assert.That(ratio, Is.EqualTo(1f).Within(0.01), $"{what}: no segment changed by more than 1 % ({p})");
            Assert.That(fitted.Profile.AvatarScale, Is.EqualTo(uniform.Profile.AvatarScale).Within(0.01 * uniform.Profile.AvatarScale), $"{what}: overall scale");
            Assert.That(fitted.AllJointsMm.Mean, Is.EqualTo(uniform.AllJointsMm.Mean).Within(0.5), $"{what}: MPJPE (mm)");
            Assert.That(fitted.EndEffectorMm.Median, Is.EqualTo(uniform.EndEffectorMm.Median).Within(0.5), $"{what}: end effectors (mm)");
            foreach (KeyValuePair<HumanoidBone, ErrorSeries> joint in uniform.JointPositionMm)
                Assert.That(fitted.JointPositionMm[joint.Key].Median, Is.EqualTo(joint.Value.Median).Within(0.5), $"{what}: {joint.Key} median (mm)");
        }

        [Test]
        public void FittedLimbsFollowLikeTheWearersOwn()
        {
            string session = Simulate(BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true }), 1);
            AssertFittedBeatsUniform(session, "mocapbank");
        }

        [Test]
        public void OwnProportionsAreLeftAlone()
        {
            string session = Simulate(BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true }), 2);
            AssertOwnProportionsUnchanged(session, "mixamo");
        }

        [Test, Category("Slow")]
        public void EverySharedClipFitsAndOwnProportionsStay([Values("mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps.bvh")] string clip)
        {
            string session = Simulate(BvhReader.ReadFile(TestData.SharedMocap(clip), new BvhReadOptions { ToMetres = true }), 1);
            AssertFittedBeatsUniform(session, clip);
            AssertOwnProportionsUnchanged(session, clip);
        }

        /// <summary>The measured lengths within 1 cm of the true ones on every shared clip in every rest convention of the rebasing tool.</summary>
        [Test, Category("Slow")]
        public void MeasurementsDoNotDependOnTheRestConvention([Values("mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps.bvh")] string clip)
        {
            string path = TestData.SharedMocap(clip);
            var clips = new List<(string, BvhClip)> { ("own", RestConventionTests.Read(path)) };
            foreach (var c in RestConventionTests.Conventions) clips.Add(($"{c.rest} {c.twist} {c.seed}", RestConventionTests.Rebased(path, c)));
            BodyMeasurements first = null;
            foreach (var (name, bvh) in clips)
            {
                // The first 20 s of motion are enough to calibrate and solve; measuring happens at calibration.
                EvaluationReport r = Evaluate(Simulate(bvh, 1), ScaleMode.Fitted, 1.1f, 0.9f);
                AssertMeasured(r, 0.01, $"{clip} {name}");
                if (first == null) { first = r.Profile.Measurements; continue; }
                var a = first.All();
                var b = r.Profile.Measurements.All();
                for (int i = 0; i < a.Length; i++)
                    Assert.That(b[i].value.Value, Is.EqualTo(a[i].value.Value).Within(0.001), $"{clip} {name}: {a[i].name} as in the clip's own convention (m)");
            }
        }
    }
}
