using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free half of AvatarGoCalibrator: the mirrored copy (a true mirror image through a plane in front of the
    /// avatar), the instructions panel in front of the head, what is shown and announced at each step of a recorded
    /// calibration, and which saved file belongs to which avatar.
    /// </summary>
    public class CalibrationPresentationTests
    {
        [Test]
        public void TheMirroredCopyIsTheAvatarsMirrorImage()
        {
            var placement = new RigidPose(new Vector3(1, 0, 2), Rotations.AngleAxis(40f, Vector3.UnitY));
            MirrorPlane mirror = MirrorPlane.InFrontOf(placement, 1.5f);
            Approx.Near(placement.Position + Vector3.Transform(Vector3.UnitZ, placement.Rotation) * 1.5f, mirror.Point, 1e-5f, "1.5 m in front");
            Approx.Near(-Vector3.Transform(Vector3.UnitZ, placement.Rotation), mirror.Normal, 1e-5f, "facing back at the avatar");
            var rng = new Random(3);
            for (int k = 0; k < 20; k++)
            {
                var root = new RigidPose(new Vector3((float)rng.NextDouble(), (float)rng.NextDouble(), (float)rng.NextDouble()),
                    Quaternion.Normalize(new Quaternion((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f, 1f)));
                float scale = 0.5f + (float)rng.NextDouble();
                RigidPose copy = mirror.ReflectRoot(root);
                Assert.That(Rotations.IsUnit(copy.Rotation), Is.True);
                var local = new Vector3((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble(), (float)rng.NextDouble() - 0.5f);
                Vector3 original = root.Position + Vector3.Transform(local * scale, root.Rotation);
                Vector3 mirrored = copy.Position + Vector3.Transform(local * new Vector3(-scale, scale, scale), copy.Rotation);
                Approx.Near(mirror.Reflect(original), mirrored, 1e-5f, "every point of the copy is the reflection of the avatar's");
            }
            Approx.Near(new Vector3(0, 1, 0), mirror.ReflectDirection(new Vector3(0, 1, 0)), 1e-6f, "a vertical mirror keeps up up");
            Assert.Throws<ArgumentException>(() => new MirrorPlane(Vector3.Zero, Vector3.Zero));
        }

        [Test]
        public void AMirrorDistanceIsKeptFiniteWithTheDefaultForNaN()
        {
            Assert.That(MirrorPlane.ValidDistance(2.5f), Is.EqualTo(2.5f));
            Assert.That(MirrorPlane.ValidDistance(float.NaN), Is.EqualTo(1.5f));
            Assert.That(MirrorPlane.ValidDistance(float.PositiveInfinity), Is.EqualTo(10f));
            Assert.That(MirrorPlane.ValidDistance(float.NegativeInfinity), Is.EqualTo(0f));
            Assert.That(MirrorPlane.ValidDistance(-1f), Is.EqualTo(0f), "not behind the avatar");
            var placement = new RigidPose(new Vector3(1, 0, 2), Quaternion.Identity);
            MirrorPlane mirror = MirrorPlane.InFrontOf(placement, MirrorPlane.ValidDistance(float.PositiveInfinity));
            Approx.Near(new Vector3(1, 0, 12), mirror.Point, 1e-5f, "10 m in front, not at infinity");
        }

        [Test]
        public void TheMarkerAndTextSizesAreKeptFinitePositiveWithTheDefaultsForNaN()
        {
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(0.1f), Is.EqualTo(0.1f));
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(float.NaN), Is.EqualTo(0.06f));
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(0f), Is.EqualTo(0.06f), "a marker of no size is the default");
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(-0.1f), Is.EqualTo(0.06f));
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(float.NegativeInfinity), Is.EqualTo(0.06f));
            Assert.That(CalibrationDisplaySizes.ValidMarkerSize(float.PositiveInfinity), Is.EqualTo(0.5f));
            Assert.That(CalibrationDisplaySizes.ValidTextSize(0.004f), Is.EqualTo(0.004f));
            Assert.That(CalibrationDisplaySizes.ValidTextSize(float.NaN), Is.EqualTo(0.0025f));
            Assert.That(CalibrationDisplaySizes.ValidTextSize(-1f), Is.EqualTo(0.0025f));
            Assert.That(CalibrationDisplaySizes.ValidTextSize(float.PositiveInfinity), Is.EqualTo(0.05f));
        }

        [Test]
        public void TheInstructionsFloatInFrontOfTheHeadAndFollowItLazily()
        {
            var panel = new FollowingPanel();
            var head = new RigidPose(new Vector3(0, 1.7f, 0), Rotations.AngleAxis(-30f, Vector3.UnitX)); // looking down
            RigidPose p = panel.Update(head, 0f);
            Approx.Near(new Vector3(0, 1.55f, 1.2f), p.Position, 1e-5f, "in front along the heading, below the eyes, at once");
            Approx.Near(Vector3.UnitZ, Vector3.Transform(Vector3.UnitZ, p.Rotation), 1e-5f, "+Z away from the wearer, upright");
            var turned = new RigidPose(head.Position, Rotations.AngleAxis(90f, Vector3.UnitY));
            Vector3 target = new Vector3(1.2f, 1.55f, 0f);
            float at72 = 0f, at144 = 0f;
            var a = new FollowingPanel(); a.Update(head, 0f);
            var b = new FollowingPanel(); b.Update(head, 0f);
            for (int i = 0; i < 36; i++) at72 = Vector3.Distance(a.Update(turned, 1 / 72f).Position, target);
            for (int i = 0; i < 72; i++) at144 = Vector3.Distance(b.Update(turned, 1 / 144f).Position, target);
            Assert.That(at72, Is.EqualTo(at144).Within(1e-4f), "the same place after half a second at 72 or 144 Hz");
            Assert.That(at72, Is.LessThan(0.5f).And.GreaterThan(0.05f), "on its way, not there at once");
            RigidPose before = a.Pose;
            Assert.That(a.Update(new RigidPose(new Vector3(float.NaN, 0, 0), Quaternion.Identity), 0.1f), Is.EqualTo(before), "a lost head leaves it");
        }

        [Test]
        public void ARecordedCalibrationShowsAndAnnouncesEachStepOnce()
        {
            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            var flow = new CalibrationFlow();
            var events = new List<CalibrationFlowEvents>();
            var messages = new List<string>();
            bool mirrorDuringWalkIn = false, markersAfter = false, avatarBefore = false;
            double calibratedAt = double.NaN, lastTime = 0;
            Sessions.Replay(session, null, (i, p, f) =>
            {
                // The pipeline already ran this frame; what it returned is its LastCalibrationStep or a Waiting step.
                CalibrationFlowEvents e = flow.Update(f.Time, Step(p, f), p.State);
                if (e != CalibrationFlowEvents.None) events.Add(e);
                if (messages.Count == 0 || messages[messages.Count - 1] != flow.Message) messages.Add(flow.Message);
                if (p.State == CalibrationState.WalkIn) mirrorDuringWalkIn |= flow.ShowsMirror;
                if (p.State == CalibrationState.Calibrated) { markersAfter |= flow.ShowsMarkers; if (double.IsNaN(calibratedAt)) calibratedAt = f.Time; }
                if (p.State == CalibrationState.WaitingForTPose) avatarBefore |= p.Pose != null;
                lastTime = f.Time;
            });
            Assert.That(events, Is.EqualTo(new[] { CalibrationFlowEvents.TPoseAccepted, CalibrationFlowEvents.Calibrated | CalibrationFlowEvents.SaveProfile }));
            Assert.That(mirrorDuringWalkIn, Is.True);
            Assert.That(markersAfter, Is.False, "the markers go once calibrated");
            Assert.That(avatarBefore, Is.False, "no avatar before the T-pose step");
            Assert.That(messages[0], Is.EqualTo(CalibrationMessages.Instruction(CalibrationState.WaitingForTPose)));
            Assert.That(messages, Has.Member(CalibrationMessages.Instruction(CalibrationState.WalkIn)));
            Assert.That(messages, Has.Member(CalibrationFlow.CalibratedMessage));
            Assert.That(lastTime - calibratedAt, Is.GreaterThan(flow.ConfirmationSeconds));
            Assert.That(flow.Message, Is.Empty, "the confirmation goes after a few seconds");
            Assert.That(flow.ShowsMirror, Is.False);
            flow.KeepMirrorAfterCalibration = true;
            Assert.That(flow.ShowsMirror, Is.True);
        }

        // The step a frame returned, rebuilt from the pipeline after it (the replay helper does not hand it over): the last
        // step if it happened this frame (a press in the frame's events), otherwise a waiting step.
        private static CalibrationStep Step(SelfAvatarPipeline p, SessionFrame f)
        {
            foreach (DeviceEvent e in f.Events)
                if (e.Kind == DeviceEventKind.TriggerPressed) return p.LastCalibrationStep;
            CalibrationStep last = p.LastCalibrationStep;
            return new CalibrationStep(p.State, CalibrationStepOutcome.Waiting, last.Error, last.Message, null);
        }

        [Test]
        public void RefusalsResetsAndRestoresAreAnnounced()
        {
            var flow = new CalibrationFlow();
            var refused = new CalibrationStep(CalibrationState.WaitingForTPose, CalibrationStepOutcome.Refused, CalibrationError.ArmsNotLevel, "Raise your arms.", null);
            Assert.That(flow.Update(1.0, refused, CalibrationState.WaitingForTPose), Is.EqualTo(CalibrationFlowEvents.StepRefused));
            Assert.That(flow.Message, Is.EqualTo("Raise your arms."), "the refusal's message is shown as it is");
            var ignored = new CalibrationStep(CalibrationState.WaitingForTPose, CalibrationStepOutcome.PressIgnored, CalibrationError.None, "Raise your arms.", "too soon");
            Assert.That(flow.Update(1.1, ignored, CalibrationState.WaitingForTPose), Is.EqualTo(CalibrationFlowEvents.PressIgnored));
            Assert.That(flow.Restored(2.0), Is.EqualTo(CalibrationFlowEvents.Restored));
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.RestoredMessage));
            Assert.That(flow.ShowsMarkers, Is.False);
            Assert.That(flow.Reset(3.0, "Stand in T-pose."), Is.EqualTo(CalibrationFlowEvents.Reset));
            Assert.That(flow.State, Is.EqualTo(CalibrationState.WaitingForTPose));
            Assert.That(flow.Message, Is.EqualTo("Stand in T-pose."));
            Assert.That(flow.ShowsMarkers, Is.True);
        }

        /// <summary>
        /// A saved calibration restored between frames, at a time the source's clock does not continue (0, before the first
        /// frame of a source whose clock is the time since launch, 100 s): the confirmation is shown for its 4 s from the
        /// first frame after the restore (found in review: counted from 0, it was never shown).
        /// </summary>
        [Test]
        public void ARestoresConfirmationCountsFromTheNextFrame()
        {
            var flow = new CalibrationFlow();
            var waiting = new CalibrationStep(CalibrationState.Calibrated, CalibrationStepOutcome.Waiting, CalibrationError.None, "", null);
            flow.Restored(0.0);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.RestoredMessage), "shown at once");
            flow.Update(100.0, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.RestoredMessage), "on the first frame");
            flow.Update(103.9, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.RestoredMessage), "3.9 s later");
            flow.Update(104.1, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.Empty, "gone after its 4 s");
        }

        /// <summary>
        /// A confirmation time that is not a number (set from script) is the default 4 s, a negative one none (found in review:
        /// NaN compared false with every elapsed time, so the confirmation was never shown).
        /// </summary>
        [Test]
        public void AConfirmationTimeThatIsNotANumberIsTheDefault()
        {
            var flow = new CalibrationFlow { ConfirmationSeconds = float.NaN };
            Assert.That(flow.ConfirmationSeconds, Is.EqualTo(4f));
            var calibrated = new CalibrationStep(CalibrationState.Calibrated, CalibrationStepOutcome.Advanced, CalibrationError.None, "", null);
            var waiting = new CalibrationStep(CalibrationState.Calibrated, CalibrationStepOutcome.Waiting, CalibrationError.None, "", null);
            flow.Update(10.0, calibrated, CalibrationState.Calibrated);
            flow.Update(11.0, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.EqualTo(CalibrationFlow.CalibratedMessage), "1 s after calibrating");
            flow.Update(14.1, waiting, CalibrationState.Calibrated);
            Assert.That(flow.Message, Is.Empty, "gone after 4 s");
            Assert.That(new CalibrationFlow { ConfirmationSeconds = -1f }.ConfirmationSeconds, Is.EqualTo(0f));
            Assert.That(new CalibrationFlow { ConfirmationSeconds = float.PositiveInfinity }.ConfirmationSeconds, Is.EqualTo(float.PositiveInfinity), "shown for good");
        }

        [Test]
        public void MessagesAreBrokenIntoLinesAtSpaces()
        {
            Assert.That(TextLines.Wrap("Stand in T-pose, arms level, and press a trigger.", 16), Is.EqualTo("Stand in T-pose,\narms level, and\npress a trigger."));
            Assert.That(TextLines.Wrap("a verylongwordindeed b", 6), Is.EqualTo("a\nverylongwordindeed\nb"), "a longer word stays whole");
            Assert.That(TextLines.Wrap("one\r\ntwo  three", 40), Is.EqualTo("one\ntwo three"));
            Assert.That(TextLines.Wrap(null, 5), Is.Empty);
            Assert.Throws<ArgumentOutOfRangeException>(() => TextLines.Wrap("x", 0));
        }

        [Test]
        public void SavedFilesAreNamedPerAvatarAndOnlyFitTheirAvatar()
        {
            Assert.That(AvatarGoFiles.ProfileFileName("Ready Player Me/ä 1"), Is.EqualTo("calibration-Ready_Player_Me___1.json"));
            Assert.That(AvatarGoFiles.ProfileFileName(""), Is.EqualTo("calibration-avatar.json"));
            Assert.That(AvatarGoFiles.RecordingFileName(null, new DateTime(2025, 1, 2, 3, 4, 5)), Is.EqualTo("session-20250102-030405.agsession"));
            // A second recording within the same second takes the next free name (found in review: it replaced the first).
            var taken = new System.Collections.Generic.HashSet<string> { Path.Combine("rec", "take-20250102-030405.agsession"), Path.Combine("rec", "take-20250102-030405-2.agsession") };
            Assert.That(AvatarGoFiles.NewRecordingPath("rec", "take", new DateTime(2025, 1, 2, 3, 4, 5), taken.Contains), Is.EqualTo(Path.Combine("rec", "take-20250102-030405-3.agsession")));
            Assert.That(AvatarGoFiles.NewRecordingPath("rec", "take", new DateTime(2025, 1, 2, 3, 4, 6), taken.Contains), Is.EqualTo(Path.Combine("rec", "take-20250102-030406.agsession")));
            string data = Path.Combine(Path.GetTempPath(), "data");
            Assert.That(AvatarGoFiles.Folder(data), Is.EqualTo(Path.Combine(data, "AvatarGo")));
            Assert.That(AvatarGoFiles.Resolve("takes/a.agsession", data), Is.EqualTo(Path.GetFullPath(Path.Combine(data, "takes", "a.agsession"))));
            string absolute = Path.GetFullPath(Path.Combine(Path.GetTempPath(), "b.agsession"));
            Assert.That(AvatarGoFiles.Resolve(absolute, data), Is.EqualTo(absolute));
            Assert.That(AvatarGoFiles.Resolve(" ", data), Is.Null);

            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            SelfAvatarPipeline p = Sessions.Replay(session);
            HumanoidMap same;
            using (SessionReader r = Sessions.Read(session)) same = r.Header.TruthHumanoid;
            Assert.That(AvatarGoFiles.ProfileFits(p.Profile, same, out string reason), Is.True, reason);
            HumanoidMap other = HumanoidNaming.Detect(BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true }).Skeleton);
            Assert.That(AvatarGoFiles.ProfileFits(p.Profile, other, out reason), Is.False);
            Assert.That(reason, Does.Contain("another avatar").Or.Contain("eyes at"));
        }

        /// <summary>
        /// A profile calibrated with the joints between the spine bones kept as bound (the Animator IK driver's) fits the same
        /// avatar again when asked the same way (found in review: the check measured the stood-up T-pose, so on a rig whose
        /// bind curves the spine at such joints the saved calibration was refused at every start), and not the other way.
        /// </summary>
        [Test]
        public void AProfileCalibratedWithTheSpineJointsAsBoundFitsTheSameAvatar()
        {
            string session = Sessions.Simulate(AnimatorIkTargetsTests.WithCurvedSpineJoints());
            var settings = new PipelineSettings();
            settings.Calibration.SpineJointsAsBound = true;
            SelfAvatarPipeline p = Sessions.Replay(session, settings);
            Assume.That(p.Profile, Is.Not.Null, p.LastCalibrationStep.Message);
            HumanoidMap same;
            using (SessionReader r = Sessions.Read(session)) same = r.Header.TruthHumanoid;
            Assert.That(AvatarGoFiles.ProfileFits(p.Profile, same, true, out string reason), Is.True, reason);
            Assert.That(AvatarGoFiles.ProfileFits(p.Profile, same, false, out reason), Is.False, "the stood-up T-pose's eyes are elsewhere");
        }
    }
}
