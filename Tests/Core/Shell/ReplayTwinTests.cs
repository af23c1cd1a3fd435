using System.Collections.Generic;
using System.IO;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free twins of the play-mode tests in <c>Tests/Runtime/ReplayPlayModeTests.cs</c>: the same session
    /// (<see cref="ReplayScenario"/>), the same avatar (the wearer's skeleton) bound by its bones' names (<c>HumanoidHierarchy.TryFromNames</c>,
    /// what <c>HumanoidBinding.TryBindByNames</c> calls), the same pipeline settings the calibrator and the fingers write
    /// (exact offsets; Quest Touch in both hands, the grip set to Hold as the play mode does, palm on the controller), the same
    /// calibration flow the wearer's text comes from, and the same assertions (<see cref="ReplayCheck"/>). Where the play
    /// mode reads the bones' world positions from the scene, the twin reads the pose the transform driver copies into them.
    /// </summary>
    public class ReplayTwinTests
    {
        private static string _session;

        private static string Session => _session ??= ReplayScenario.Simulate(ReplayScenario.ClipPath(TestData.PackageRoot));

        // What the play mode does, without the engine: returns the pipeline and the flow after every frame.
        private static (SelfAvatarPipeline pipeline, CalibrationFlow flow, ReplayCheck check, List<string> refused) Play(string session)
        {
            using var reader = Sessions.Read(session);
            Assert.That(HumanoidHierarchy.TryFromNames(ReplayScenario.AvatarNodes(reader.Header.TruthHumanoid), 1f, out HumanoidHierarchy hierarchy, out string error), Is.True, error);
            var settings = new PipelineSettings { Offsets = OffsetMode.Exact };
            ControllerProfile quest = ControllerProfile.Parse(File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/quest-touch.json")));
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                settings.Hand(side).Controller = quest;
                settings.Hand(side).Grip = GripMode.Hold; // the play mode sets Hold (the session records no grip input)
                settings.Hand(side).Placement = HandPlacement.PalmOnController;
            }
            var pipeline = new SelfAvatarPipeline(reader.Header.Devices, hierarchy.Map, settings);
            var flow = new CalibrationFlow();
            flow.Reset(0.0, pipeline.LastCalibrationStep.Message);
            var check = new ReplayCheck();
            var refused = new List<string>();
            SessionFrame frame = reader.CreateFrame();
            bool calibratedBefore = false;
            while (reader.ReadFrame(frame))
            {
                CalibrationStep step = pipeline.Update(frame);
                CalibrationFlowEvents events = flow.Update(frame.Time, step, pipeline.State);
                if ((events & CalibrationFlowEvents.StepRefused) != 0) refused.Add(step.Message);
                if (pipeline.State != CalibrationState.Calibrated) continue;
                if (!calibratedBefore)
                {
                    calibratedBefore = true; // the play mode measures from the frame after calibration
                    continue;
                }
                HumanoidMap scaled = pipeline.ScaledAvatar;
                SkeletonPose pose = pipeline.Pose;
                check.Add(frame, bone => scaled.Has(bone) ? pose.World[scaled[bone]].Position : (System.Numerics.Vector3?)null, pipeline);
            }
            return (pipeline, flow, check, refused);
        }

        /// <summary>Twin of <c>ReplayPlayModeTests.RecordedSessionFollowsTheGroundTruth</c>.</summary>
        [Test]
        public void RecordedSessionFollowsTheGroundTruth()
        {
            var (pipeline, _, check, _) = Play(Session);
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            TestContext.WriteLine(check.ToString());
            // The Mixamo clip's hands have finger bones: both hold the Quest Touch profile, and the fingers' bound applies.
            Assert.That(pipeline.Hand(BodySide.Left).HasFingerIk && pipeline.Hand(BodySide.Right).HasFingerIk, Is.True, "both hands get finger IK");
            Assert.That(check.HoldingFrames, Is.GreaterThan(100), "frames on which the fingers held the controller");
            Assert.That(check.Failures(100), Is.Empty, check.ToString());
        }

        /// <summary>Twin of <c>ReplayPlayModeTests.MalformedTPoseReachesTheWearersMessage</c>.</summary>
        [Test]
        public void MalformedTPoseReachesTheWearersMessage()
        {
            var (pipeline, flow, _, refused) = Play(ReplayScenario.WithOneArmLowered(Session));
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.WaitingForTPose), "a T-pose with one arm low is never accepted");
            Assert.That(pipeline.LastCalibrationStep.Error, Is.EqualTo(CalibrationError.ArmsNotLevel));
            Assert.That(refused, Is.Not.Empty, "the refusal is announced (AvatarGoCalibrator raises OnStepRefused with it)");
            Assert.That(refused[0], Is.EqualTo(pipeline.LastCalibrationStep.Message));
            Assert.That(flow.Message, Does.Contain(pipeline.LastCalibrationStep.Message), "the wearer's text shows the error's message");
            TestContext.WriteLine(flow.Message);
        }

        /// <summary>Twin of <c>ReplayPlayModeTests.LostTrackerDegradesWithoutExceptions</c>.</summary>
        [Test]
        public void LostTrackerDegradesWithoutExceptions()
        {
            var (pipeline, _, check, _) = Play(ReplayScenario.WithATrackerLost(Session));
            Assert.That(check.FramesWithAnUntrackedDevice, Is.GreaterThan(100), "measured frames with the tracker lost (1.5 s at 90 Hz)");
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), "a lost tracker does not undo the calibration");
            TestContext.WriteLine(check.ToString());
            Assert.That(check.Failures(100, accuracy: false), Is.Empty, check.ToString());
        }
    }
}
