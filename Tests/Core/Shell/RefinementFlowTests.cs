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

        private static int DeviceOf(SessionHeader header, DeviceClass kind)
        {
            foreach (DeviceInfo d in header.Devices) if (d.Class == kind) return d.Id;
            throw new InvalidOperationException("no " + kind);
        }

        /// <summary>
        /// A controller's press ends the exercise early, but not in its first 2 s (the calibration's own press, or the other
        /// trigger pressed with it), and a tracker's press never does: the calibration's rule.
        /// </summary>
        [Test]
        public void AControllersPressEndsItEarlyButNotTooSoonNorATrackers()
        {
            var run = new Run(ScaleMode.Uniform);
            int controller = DeviceOf(run.Reader.Header, DeviceClass.Controller), tracker = DeviceOf(run.Reader.Header, DeviceClass.Tracker);
            double began = double.NaN, ended = double.NaN;
            var ignored = new List<double>();
            bool early = false, tracked = false, late = false;
            while (run.Read() && double.IsNaN(ended))
            {
                double t = run.Frame.Time - began;
                if (!early && t >= 1.0) { run.Frame.Events.Add(new DeviceEvent(controller, DeviceEventKind.TriggerPressed)); early = true; }
                else if (!tracked && t >= 3.0) { run.Frame.Events.Add(new DeviceEvent(tracker, DeviceEventKind.TriggerPressed)); tracked = true; }
                else if (!late && t >= 4.0) { run.Frame.Events.Add(new DeviceEvent(controller, DeviceEventKind.TriggerPressed)); late = true; }
                (_, RefinementFlowEvents events) = run.Step();
                if ((events & RefinementFlowEvents.Began) != 0) began = run.Frame.Time;
                if ((events & RefinementFlowEvents.PressIgnored) != 0) { ignored.Add(t); TestContext.WriteLine($"{t:0.000} s: {run.Refinement.Explanation}"); }
                if ((events & RefinementFlowEvents.Ended) != 0) { ended = run.Frame.Time; TestContext.WriteLine(run.Refinement.Explanation); }
            }
            Assert.That(ignored.Count, Is.EqualTo(2), "the press at 1 s and the tracker's at 3 s");
            Assert.That(ignored[0], Is.EqualTo(1.0).Within(1.0 / 90 + 1e-9));
            Assert.That(ignored[1], Is.EqualTo(3.0).Within(1.0 / 90 + 1e-9));
            Assert.That(ended - began, Is.EqualTo(4.0).Within(1.0 / 90 + 1e-9), "ended by the controller's press at 4 s");
            Assert.That(run.Refinement.Explanation, Does.Contain("by a trigger press"));
            RefinementReport report = run.Refinement.LastReport;
            Assert.That(report.Frames, Is.InRange(355, 365), "4 s recorded");
            Assert.That(report.Changed, Is.True, $"4 s of the exercise are enough here ({report})");
        }

        /// <summary>
        /// A frame whose time is not a number (a broken clock, a bad recording: the pipeline takes it as a frame in which no
        /// time passed) neither ends the exercise nor breaks its countdown (found in review: NaN compared false with the end
        /// time, so it ended the exercise on that frame, "on time after NaN s", with what was recorded so far).
        /// </summary>
        [Test]
        public void AFrameWithoutATimeDoesNotEndTheExercise()
        {
            var run = new Run(ScaleMode.Uniform);
            double began = double.NaN, ended = double.NaN;
            bool broken = false;
            while (run.Read() && double.IsNaN(ended))
            {
                if (!broken && run.Frame.Time - began >= 2.0)
                {
                    run.Frame.Time = double.NaN;
                    broken = true;
                    (_, RefinementFlowEvents atNaN) = run.Step();
                    Assert.That(atNaN & RefinementFlowEvents.Ended, Is.EqualTo(RefinementFlowEvents.None), run.Refinement.Explanation);
                    Assert.That(run.Refinement.Phase, Is.EqualTo(RefinementPhase.Exercising));
                    Assert.That(run.Refinement.SecondsLeft, Is.InRange(6.0, 6.0 + 1.5 / 90), "the previous frame's time counts");
                    Assert.That(run.Refinement.Message, Is.EqualTo(RefinementFlow.Countdown(7)));
                    continue;
                }
                (_, RefinementFlowEvents events) = run.Step();
                if ((events & RefinementFlowEvents.Began) != 0) began = run.Frame.Time;
                if ((events & RefinementFlowEvents.Ended) != 0) ended = run.Frame.Time;
            }
            Assert.That(broken, Is.True);
            Assert.That(ended - began, Is.EqualTo(8.0).Within(1.0 / 90 + 1e-9), "ends when the 8 s are up");
        }

        /// <summary>The calibration's confirmation stays up through a frame without a time, as it would with one.</summary>
        [Test]
        public void AFrameWithoutATimeKeepsTheConfirmation()
        {
            var flow = new CalibrationFlow();
            var calibrated = new CalibrationStep(CalibrationState.Calibrated, CalibrationStepOutcome.Advanced, CalibrationError.None, "Calibrated.", null);
            var waiting = new CalibrationStep(CalibrationState.Calibrated, CalibrationStepOutcome.Waiting, CalibrationError.None, "Calibrated.", null);
            flow.Update(10.0, calibrated, CalibrationState.Calibrated);
            flow.Update(double.NaN, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.CalibratedMessage), "1 s or 0 s after calibrating, not hidden");
            flow.Update(12.0, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.CalibratedMessage));
            flow.Update(14.1, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.Empty, "gone after its 4 s");
        }

        /// <summary>Fitted proportions already right within the tolerance: the exercise keeps both arms and says so.</summary>
        [Test]
        public void ARightFitIsKeptAndSaysSo()
        {
            var run = new Run(ScaleMode.Fitted);
            RefinementFlowEvents all = RefinementFlowEvents.None;
            HumanoidMap avatar = null;
            while (run.Read())
            {
                (_, RefinementFlowEvents events) = run.Step();
                if ((events & RefinementFlowEvents.Began) != 0) avatar = run.Pipeline.ScaledAvatar;
                all |= events;
            }
            RefinementReport report = run.Refinement.LastReport;
            TestContext.WriteLine(report);
            TestContext.WriteLine(run.Refinement.Summary);
            Assert.That(all, Is.EqualTo(RefinementFlowEvents.Began | RefinementFlowEvents.Ended), "nothing to save, no arms changed");
            Assert.That(run.Pipeline.ScaledAvatar, Is.SameAs(avatar), "the avatar is kept: the drivers have nothing to re-bind");
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                Assert.That(Math.Abs(report.Arm(side).ResidualBefore) * 1000f, Is.LessThan(10f), $"{side}: within the tolerance ({report.Arm(side)})");
            Assert.That(run.Refinement.Summary, Is.EqualTo(FormattableString.Invariant(
                $"Arms kept: they already fit your reach.\nLeft arm: {report.Arm(BodySide.Left).LengthBefore * 1000f:0} mm, kept.\nRight arm: {report.Arm(BodySide.Right).LengthBefore * 1000f:0} mm, kept.")));
        }

        /// <summary>
        /// Off, nothing starts; a reset or a restored calibration drops a running exercise without applying it (the pipeline
        /// stops recording; the restore no longer leaves the old avatar's recording running), and the calibration's message is
        /// shown again.
        /// </summary>
        [Test]
        public void OffNothingStartsAndAResetOrARestoreDropsIt()
        {
            var off = new Run(ScaleMode.Uniform);
            off.Refinement.Enabled = false;
            RefinementFlowEvents all = RefinementFlowEvents.None;
            while (off.Read())
            {
                all |= off.Step().Item2;
                Assert.That(off.Pipeline.IsRefining, Is.False);
                Assert.That(off.Refinement.Shown(off.Calibration.Message), Is.SameAs(off.Calibration.Message));
            }
            Assert.That(all, Is.EqualTo(RefinementFlowEvents.None));

            var run = new Run(ScaleMode.Uniform);
            double began = double.NaN;
            CalibrationProfile profile = null;
            bool reset = false, restored = false;
            while (run.Read() && !restored)
            {
                double t = run.Frame.Time - began;
                (_, RefinementFlowEvents events) = run.Step();
                if ((events & RefinementFlowEvents.Began) != 0) { began = run.Frame.Time; profile = run.Pipeline.Profile; }
                if (!reset && t >= 2.0)
                {
                    // The component's ResetCalibration: the pipeline and the calibration flow reset, then the refinement told.
                    reset = true;
                    run.Pipeline.Reset();
                    CalibrationFlowEvents r = run.Calibration.Reset(run.Frame.Time, run.Pipeline.LastCalibrationStep.Message);
                    Assert.That(run.Refinement.AfterUpdate(run.Frame.Time, run.Pipeline, r), Is.EqualTo(RefinementFlowEvents.Cancelled));
                    Assert.That(run.Refinement.Phase, Is.EqualTo(RefinementPhase.Idle));
                    Assert.That(run.Pipeline.IsRefining, Is.False);
                    Assert.That(run.Refinement.Shown(run.Calibration.Message), Is.EqualTo(CalibrationMessages.Instruction(CalibrationState.WaitingForTPose)));
                    // Restored, then the exercise started again by hand (as a script may): a restore drops it.
                    Assert.That(run.Pipeline.TryRestore(profile), Is.True);
                    run.Calibration.Restored(run.Frame.Time);
                    Assert.That(run.Pipeline.BeginRefinement(), Is.True);
                    Assert.That(run.Pipeline.TryRestore(profile), Is.True);
                    Assert.That(run.Pipeline.IsRefining, Is.False, "a restore drops the recording made on the previous avatar");
                    Assert.That(run.Refinement.LastReport, Is.Null, "nothing was applied");
                    restored = true;
                }
            }
            Assert.That(restored, Is.True);
            // A flow whose exercise runs on a pipeline that was made again (new devices) drops it.
            var other = new Run(ScaleMode.Uniform);
            while (other.Read() && other.Refinement.Phase != RefinementPhase.Exercising) other.Step();
            Assert.That(other.Refinement.BeforeUpdate(other.Frame, run.Pipeline), Is.EqualTo(RefinementFlowEvents.Cancelled));
            Assert.That(other.Refinement.Phase, Is.EqualTo(RefinementPhase.Idle));
            Assert.That(new RefinementFlow { ExerciseSeconds = 0.5f }.ExerciseSeconds, Is.EqualTo(RefinementFlow.MinimumExerciseSeconds));
            Assert.That(new RefinementFlow { ExerciseSeconds = float.NaN }.ExerciseSeconds, Is.EqualTo(RefinementFlow.DefaultExerciseSeconds));
            Assert.That(new RefinementFlow { ExerciseSeconds = 600f }.ExerciseSeconds, Is.EqualTo(RefinementFlow.MaximumExerciseSeconds));
        }

        /// <summary>
        /// The summary's and the ignored presses' times are numbers: NaN gives the defaults, a negative time none (found in
        /// review: a NaN summary time was never up, so the summary stayed on the wearer's view for good).
        /// </summary>
        [Test]
        public void TheSummaryAndIgnoredPressTimesAreNumbers()
        {
            Assert.That(new RefinementFlow { SummarySeconds = float.NaN }.SummarySeconds, Is.EqualTo(8f));
            Assert.That(new RefinementFlow { SummarySeconds = -1f }.SummarySeconds, Is.EqualTo(0f));
            Assert.That(new RefinementFlow { SummarySeconds = float.PositiveInfinity }.SummarySeconds, Is.EqualTo(float.PositiveInfinity), "kept for good");
            Assert.That(new RefinementFlow { IgnorePressesSeconds = float.NaN }.IgnorePressesSeconds, Is.EqualTo(2f));
            Assert.That(new RefinementFlow { IgnorePressesSeconds = -1f }.IgnorePressesSeconds, Is.EqualTo(0f));
        }
}
}
