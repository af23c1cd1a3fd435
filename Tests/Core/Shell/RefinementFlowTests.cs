using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free half of the calibrator's refinement exercise (<see cref="RefinementFlow"/>), run as the component
    /// runs it on a synthetic session with the 8 s exercise (<c>avatargo simulate --exercise-seconds 8</c>): mocapbank worn
    /// with a Vive wand in each hand, the avatar the wearer's skeleton with legs +10 % and arms -10 %
    /// (<see cref="ProportionRefinementTests"/>). What the wearer reads, when the exercise begins and ends, what the pipeline
    /// and the bones the calibrator moves look like afterwards, and that the flow allocates nothing per frame.
    /// </summary>
    public class RefinementFlowTests
    {
        private static string _session;

        private static string Session() =>
            _session ??= ProportionRefinementTests.Simulate(BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true }), 1);

        private static ControllerProfile Wand() =>
            ControllerProfile.Parse(File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/vive-wand.json")));

        private static PipelineSettings Settings(ScaleMode mode)
        {
            var settings = new PipelineSettings();
            settings.Calibration.Proportions.Mode = mode;
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right }) settings.Hand(side).Controller = Wand();
            return settings;
        }

        // What the calibrator component does with one frame, in its order; the events of both flows, per frame.
        private sealed class Run
        {
            public readonly SessionReader Reader;
            public readonly SelfAvatarPipeline Pipeline;
            public readonly CalibrationFlow Calibration = new CalibrationFlow();
            public readonly RefinementFlow Refinement = new RefinementFlow { Enabled = true, ExerciseSeconds = 8f };
            public readonly SessionFrame Frame;
            public readonly HumanoidMap Avatar;
            public long LastBytes;

            public Run(ScaleMode mode)
            {
                Reader = Sessions.Read(Session());
                Avatar = Proportions.ScaleLimbs(Reader.Header.TruthHumanoid, 1.1f, 0.9f);
                Pipeline = new SelfAvatarPipeline(Reader.Header.Devices, Avatar, Settings(mode));
                Frame = Reader.CreateFrame();
            }

            public bool Read() => Reader.ReadFrame(Frame);

            public (CalibrationFlowEvents, RefinementFlowEvents) Step()
            {
                long t0 = GC.GetAllocatedBytesForCurrentThread();
                RefinementFlowEvents before = Refinement.BeforeUpdate(Frame, Pipeline);
                long bytes = GC.GetAllocatedBytesForCurrentThread() - t0;
                CalibrationStep step = Pipeline.Update(Frame);
                CalibrationFlowEvents calibration = Calibration.Update(Frame.Time, step, Pipeline.State);
                t0 = GC.GetAllocatedBytesForCurrentThread();
                RefinementFlowEvents after = Refinement.AfterUpdate(Frame.Time, Pipeline, calibration);
                LastBytes = bytes + GC.GetAllocatedBytesForCurrentThread() - t0;
                return (calibration, before | after);
            }
        }

        [Test]
        public void TheExerciseAfterCalibrationRefinesShortArmsAndTheBonesFollow()
        {
            var run = new Run(ScaleMode.Uniform);
            var bind = new Vector3[run.Avatar.Skeleton.JointCount];
            for (int j = 0; j < bind.Length; j++) bind[j] = run.Avatar.Skeleton.GetRestLocal(j).Position;
            var bones = new ProportionedBones(run.Avatar, bind);
            var world = new RigidPose[bind.Length];
            var countdowns = new List<string>();
            var exerciseBytes = new List<long>();
            double began = double.NaN, ended = double.NaN, summaryGone = double.NaN;
            HumanoidMap avatarBefore = null;
            SkeletonPose poseBefore = null;
            double maxToSolver = 0;
            int framesAfter = 0, exerciseFrames = 0;
            while (run.Read())
            {
                (CalibrationFlowEvents calibration, RefinementFlowEvents events) = run.Step();
                bool bonesChanged = bones.Update(run.Pipeline.Profile, true);
                if ((events & RefinementFlowEvents.Began) != 0)
                {
                    Assert.That(calibration & CalibrationFlowEvents.Calibrated, Is.Not.EqualTo(CalibrationFlowEvents.None), "begins on the frame that calibrated");
                    Assert.That(double.IsNaN(began), Is.True, "begins once");
                    began = run.Frame.Time;
                    avatarBefore = run.Pipeline.ScaledAvatar;
                    poseBefore = run.Pipeline.Pose;
                    Assert.That(run.Pipeline.IsRefining, Is.True);
                    Assert.That(bones.Applied.IsUniform, Is.True, "a uniform calibration keeps the bind bones");
                }
                if (run.Refinement.Phase == RefinementPhase.Exercising && (events & RefinementFlowEvents.Began) == 0)
                {
                    if (++exerciseFrames > 30) exerciseBytes.Add(run.LastBytes);
                    if (countdowns.Count == 0 || !ReferenceEquals(countdowns[countdowns.Count - 1], run.Refinement.Message)) countdowns.Add(run.Refinement.Message);
                    Assert.That(run.Refinement.Shown(run.Calibration.Message), Is.SameAs(run.Refinement.Message), "the exercise's prompt replaces the calibration's confirmation");
                }
                if ((events & RefinementFlowEvents.Ended) != 0)
                {
                    ended = run.Frame.Time;
                    Assert.That(events, Is.EqualTo(RefinementFlowEvents.Ended | RefinementFlowEvents.ArmsChanged | RefinementFlowEvents.SaveProfile));
                    // What the drivers key on: the pipeline's scaled avatar and pose are new objects (the Animator IK driver
                    // retargets on a new ScaledAvatar), and this frame is already solved on them, not left in the T-pose.
                    Assert.That(run.Pipeline.ScaledAvatar, Is.Not.SameAs(avatarBefore));
                    Assert.That(run.Pipeline.Pose, Is.Not.SameAs(poseBefore));
                    Assert.That(run.Pipeline.Targets.HipsActive, Is.True, "the frame that ended the exercise was solved on the refined avatar");
                    Assert.That(bonesChanged, Is.True, "the refined arms reach the calibrator's bones the same frame");
                    Assert.That(bones.Applied, Is.EqualTo(run.Refinement.LastReport.After));
                }
                if (!double.IsNaN(ended) && run.Refinement.Phase == RefinementPhase.Idle && double.IsNaN(summaryGone)) summaryGone = run.Frame.Time;
                if (!double.IsNaN(ended) && framesAfter < 600)
                {
                    // The engine stand-in with the refined bones is where the solver has the refined avatar.
                    framesAfter++;
                    ProportionedBonesTests.EngineWorld(run.Avatar, run.Pipeline.Pose, bones, true, run.Pipeline.Profile.AvatarScale, world);
                    for (int j = 0; j < world.Length; j++) maxToSolver = Math.Max(maxToSolver, Vector3.Distance(world[j].Position, run.Pipeline.Pose.World[j].Position) * 1000);
                }
            }
            RefinementReport report = run.Refinement.LastReport;
            TestContext.WriteLine($"began {began:0.000} s, ended {ended:0.000} s, summary down {summaryGone:0.000} s; {exerciseFrames} exercise frames; {report}");
            TestContext.WriteLine(run.Refinement.Summary);
            TestContext.WriteLine($"engine stand-in vs solver after the refinement: max {maxToSolver:0.000} mm over {framesAfter} frames; bones {bones.Applied}");
            Assert.That(ended - began, Is.EqualTo(8.0).Within(1.0 / 90 + 1e-9), "ends when the 8 s are up");
            Assert.That(summaryGone - ended, Is.EqualTo(8.0).Within(1.0 / 90 + 1e-9), "the summary stays up 8 s");
            Assert.That(report.Frames, Is.EqualTo(exerciseFrames), "every frame between the calibration and the end was recorded");
            Assert.That(countdowns.Count, Is.EqualTo(8), "8 s left, 7, ..., 1");
            for (int s = 0; s < 8; s++) Assert.That(countdowns[s], Is.EqualTo(RefinementFlow.Countdown(8 - s)));
            Assert.That(countdowns[0], Does.StartWith(RefinementFlow.Instruction).And.EndWith("8 s left; press a trigger when done."));
            Assert.That(exerciseBytes.Count, Is.GreaterThan(600));
            Assert.That(exerciseBytes, Is.All.EqualTo(0L), "bytes the flow allocates per exercise frame (countdown changes included)");

            // The numbers of ProportionRefinementTests.ShortArmsAreRefinedWithoutFingerBones, through the flow.
            EvaluationReport evaluated = ProportionRefinementTests.Evaluate(Session(), ScaleMode.Uniform, true);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                LimbRefinement arm = report.Arm(side), reference = evaluated.Refinement.Arm(side);
                TestContext.WriteLine($"{side}: flow {arm}; evaluator {reference}");
                Assert.That(arm.Refined, Is.True, $"{side} arm refined");
                Assert.That(arm.ResidualBefore * 1000f, Is.GreaterThan(60f), $"{side}: the arm was ~7 cm short ({arm})");
                Assert.That(Math.Abs(arm.ResidualAfter) * 1000f, Is.LessThan(5f), $"{side}: reachable after ({arm})");
                Assert.That((arm.LengthAfter - arm.LengthBefore) * 1000f, Is.GreaterThan(60f), $"{side}: lengthened by the deficit");
                Assert.That((arm.LengthAfter - reference.LengthAfter) * 1000f, Is.EqualTo(0f).Within(1f), $"{side}: as the evaluator refines it (one frame less recorded)");
                Assert.That(report.Leg(side).Refined, Is.False, "legs reported only");
            }
            Assert.That(run.Refinement.Summary, Is.EqualTo(FormattableString.Invariant(
                $"Arms refined from your motion.\nLeft arm: {report.Arm(BodySide.Left).LengthBefore * 1000f:0} -> {report.Arm(BodySide.Left).LengthAfter * 1000f:0} mm.\nRight arm: {report.Arm(BodySide.Right).LengthBefore * 1000f:0} -> {report.Arm(BodySide.Right).LengthAfter * 1000f:0} mm.")));
            Assert.That(bones.Applied.LeftArm, Is.GreaterThan(1.08f), $"the bones' arms lengthened ({bones.Applied})");
            Assert.That(bones.Applied.LeftLeg, Is.EqualTo(1f), "the legs' bones stay");
            Assert.That(framesAfter, Is.EqualTo(600));
            Assert.That(maxToSolver, Is.LessThan(0.05), "every joint of the engine avatar with the refined bones is where the solver has it (mm)");
        }
    }
}
