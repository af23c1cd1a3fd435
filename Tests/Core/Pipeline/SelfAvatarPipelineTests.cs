using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The whole pipeline on recorded human motion: calibration from the session's presses (and the presses that must not
    /// calibrate), a restored profile, bad samples mid-motion, the hands on their controllers and the fingers on the
    /// solved body, and frame-rate independence.
    /// </summary>
    public class SelfAvatarPipelineTests
    {
        // Simulated once for the fixture (not System.Lazy: Unity's NUnit, built for .NET 3.5, declares its own Lazy<T>).
        private static string _mocapBank;
        private static string MocapBank => _mocapBank ?? (_mocapBank = Sessions.Simulate("mocapbank_30fps.bvh"));

        private static ControllerProfile Profile(string name) =>
            ControllerProfile.Parse(File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/" + name + ".json")));

        private static PipelineSettings WithController(ControllerProfile controller)
        {
            var settings = new PipelineSettings();
            settings.LeftHand.Controller = settings.RightHand.Controller = controller;
            return settings;
        }

        [Test]
        public void ASessionCalibratesWithItsTwoPresses()
        {
            SelfAvatarPipeline p = Sessions.Replay(MocapBank);
            Assert.That(p.State, Is.EqualTo(CalibrationState.Calibrated), p.LastCalibrationStep.ToString());
            Assert.That(p.Pose, Is.SameAs(p.Pose), "one pose object while calibrated");
            Assert.That(p.Pose.Skeleton, Is.SameAs(p.ScaledAvatar.Skeleton));
        }

        /// <summary>
        /// The offset mode is read when a calibration completes, not only when the pipeline is made: the calibrator's
        /// <c>Offsets</c> set at run time writes it into the live pipeline's settings and relies on this (found in review:
        /// it only stored the field, so a recalibration after switching to the baseline still used exact offsets).
        /// </summary>
        [Test]
        public void AnOffsetModeChangedOnALivePipelineIsUsedByTheNextCalibration()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 67);
            double t = 0;
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map, new PipelineSettings { Offsets = OffsetMode.Exact });
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            Assert.That(pipeline.ActiveProfile.Mode, Is.EqualTo(OffsetMode.Exact));
            // The pelvis tracker is worn on the lower back, centimetres from the hips joint: its exact offset is measured.
            Assert.That(pipeline.ActiveProfile.JointInDevice(DeviceRole.Pelvis).Position.Length(), Is.GreaterThan(0.02f));

            pipeline.Settings.Offsets = OffsetMode.Fixed;
            pipeline.Reset();
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            Assert.That(pipeline.ActiveProfile.Mode, Is.EqualTo(OffsetMode.Fixed));
            // The baseline's offsets: the tracker taken as the hips, the head joint a constant offset from the HMD.
            Assert.That(pipeline.ActiveProfile.JointInDevice(DeviceRole.Pelvis).Position.Length(), Is.EqualTo(0f));
            Assert.That(Vector3.Distance(pipeline.ActiveProfile.JointInDevice(DeviceRole.Head).Position, CalibrationProfile.FixedHeadOffset), Is.EqualTo(0f));
        }

        /// <summary>
        /// After a reset the hands say what they are: no finger IK (with why), not holding, not reached, nothing drawn in them,
        /// until the next calibration sets them up again (found in review: HasFingerIk and Holding stayed true with the solver
        /// gone, so a reader of the hand's state took fingers that were no longer solved for a grip).
        /// </summary>
        [Test]
        public void AResetHandHasNoFingerIkNorGripUntilTheNextCalibration()
        {
            var wearer = new Wearer("mixamo_fingers_30fps.bvh", 12);
            double t = 0;
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map, WithController(Profile("vive-wand")));
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            var samples = new DeviceSample[wearer.Devices.Length];
            for (int i = 0; i < 10; i++)
            {
                wearer.Sample(samples, 0.001f, 0.1f);
                t += 1.0 / 90;
                pipeline.Update(t, samples, default, default, null);
            }
            HandState hand = pipeline.Hand(BodySide.Left);
            Assume.That(hand.HasFingerIk, Is.True, hand.NoFingerIkReason);
            Assume.That(hand.Holding, Is.True);

            pipeline.Reset();
            Assert.That(hand.HasFingerIk, Is.False);
            Assert.That(hand.NoFingerIkReason, Is.Not.Null.And.Not.Empty);
            Assert.That(hand.Holding, Is.False);
            Assert.That(hand.Reached, Is.False);
            Assert.That(hand.DrawnInHand, Is.False);
            Assert.That(hand.ControllerTracked, Is.False);
            Assert.That(hand.SurfaceGap(Finger.Index, FingerPoint.Tip), Is.NaN);

            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            Assert.That(hand.HasFingerIk, Is.True, "set up again by the calibration");
            Assert.That(hand.NoFingerIkReason, Is.Null);
        }

        [Test]
        public void BothControllersPressingInTheSameFrameWithNoSecondPressEndsNotCalibrated()
        {
            // Both triggers at the T-pose, in one frame; the walk-in press removed.
            string session = Sessions.Edit(MocapBank, (i, f) =>
            {
                bool tposePress = f.Events.Exists(e => e.Kind == DeviceEventKind.TriggerPressed && e.DeviceId == 1);
                f.Events.RemoveAll(e => e.Kind == DeviceEventKind.TriggerPressed);
                if (tposePress)
                {
                    f.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerPressed));
                    f.Events.Add(new DeviceEvent(2, DeviceEventKind.TriggerPressed));
                }
            });
            SelfAvatarPipeline p = Sessions.Replay(session);
            Assert.That(p.State, Is.EqualTo(CalibrationState.WalkIn), "the walk-in was not skipped");
            Assert.That(p.Pose, Is.Not.Null, "the avatar stands in T-pose where the wearer stood");
        }

        [Test]
        public void PressesFromATrackerEndNotCalibrated()
        {
            // Every press attributed to device 4, the pelvis tracker of a simulated session.
            string session = Sessions.Edit(MocapBank, (i, f) =>
            {
                for (int e = 0; e < f.Events.Count; e++) f.Events[e] = new DeviceEvent(4, f.Events[e].Kind);
            });
            SelfAvatarPipeline p = Sessions.Replay(session);
            Assert.That(p.State, Is.EqualTo(CalibrationState.WaitingForTPose));
            Assert.That(p.LastCalibrationStep.Outcome, Is.EqualTo(CalibrationStepOutcome.PressIgnored));
            Assert.That(p.LastCalibrationStep.Explanation, Does.Contain("only a controller's trigger"));
            Assert.That(p.Pose, Is.Null, "no avatar is shown before the T-pose step");
        }

        [Test]
        public void ARestoredProfileSolvesLikeTheCalibrationItCameFrom()
        {
            string session = MocapBank;
            SelfAvatarPipeline calibrated = null, restored = null;
            var solvedA = new List<RigidPose>();
            var solvedB = new List<RigidPose>();
            // First run: calibrate from the session; save its profile as the JSON a headset would keep.
            calibrated = Sessions.Replay(session, null, (i, p, f) => { if (p.State == CalibrationState.Calibrated) solvedA.Add(p.Pose.World[p.ScaledAvatar[HumanoidBone.LeftHand]]); });
            string json = CalibrationProfileStore.ToJson(calibrated.Profile);
            // Second run: a new pipeline restores it before the first frame, then plays the same frames after calibration.
            using (SessionReader reader = Sessions.Read(session))
            {
                restored = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid);
                Assert.That(restored.TryRestore(CalibrationProfileStore.FromJson(json)), Is.True);
                SessionFrame frame = reader.CreateFrame();
                bool after = false;
                var replay = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid);
                while (reader.ReadFrame(frame))
                {
                    replay.Update(frame);
                    if (!after) { after = replay.State == CalibrationState.Calibrated; continue; }
                    restored.Update(frame);
                    solvedB.Add(restored.Pose.World[restored.ScaledAvatar[HumanoidBone.LeftHand]]);
                }
            }
            Assert.That(solvedB.Count, Is.EqualTo(solvedA.Count - 1), "the calibration frame itself is not solved");
            for (int i = 0; i < solvedB.Count; i++)
                Approx.Near(solvedA[i + 1], solvedB[i], 1e-4f, 0.05f, $"frame {i}");
            Assert.That(restored.LastCalibrationStep.Message, Does.Contain("restored"));
        }

        [Test]
        public void GarbageSamplesMidMotionNeverThrowNorReachABone()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 41);
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map, WithController(Profile("vive-wand")));
            double t = 0;
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            var samples = new DeviceSample[6];
            wearer.Sample(samples, 0.001f, 0.1f);
            pipeline.Update(t += 1 / 90.0, samples, default, default, null);
            int hips = pipeline.ScaledAvatar[HumanoidBone.Hips];
            RigidPose goodHips = pipeline.Pose.World[hips];
            var bad = new[]
            {
                new DeviceSample(new RigidPose(new Vector3(float.NaN, 1, 0), Quaternion.Identity), true),
                new DeviceSample(new RigidPose(new Vector3(0, 1, 0), new Quaternion(0, 0, 0, 0)), true),
                new DeviceSample(new RigidPose(new Vector3(float.PositiveInfinity, 0, 0), Quaternion.Identity), true),
                new DeviceSample(new RigidPose(new Vector3(0, 1, 0), new Quaternion(0.3f, 0.3f, 0.3f, 0.3f)), true),
                DeviceSample.Lost,
            };
            var trigger = new float[6];
            foreach (bool withHmd in new[] { true, false })
                foreach (DeviceSample garbage in bad)
                {
                    wearer.Sample(samples, 0.001f, 0.1f);
                    foreach (DeviceRole role in withHmd ? new[] { DeviceRole.Pelvis, DeviceRole.Head, DeviceRole.LeftHand } : new[] { DeviceRole.Pelvis, DeviceRole.LeftHand })
                        samples[Array.IndexOf(Wearer.TrueRoles, role)] = garbage;
                    for (int d = 0; d < 6; d++) trigger[d] = float.NaN;
                    var before = (RigidPose[])pipeline.Pose.World.Clone();
                    Assert.DoesNotThrow(() => pipeline.Update(t += 1 / 90.0, samples, trigger, default, null));
                    Assert.That(pipeline.Hand(BodySide.Left).ControllerTracked, Is.False);
                    if (withHmd)
                    {
                        // No HMD, nothing to place the body by: the avatar keeps its last good pose exactly.
                        for (int j = 0; j < before.Length; j++) Assert.That(pipeline.Pose.World[j], Is.EqualTo(before[j]), "frozen");
                    }
                    else
                    {
                        // The pelvis held relative to the head: within the wearer's motion of a frame.
                        Approx.Near(goodHips.Position, pipeline.Pose.World[hips].Position, 0.03f, "the hips held near their last good pose");
                    }
                    foreach (RigidPose p in pipeline.Pose.World) Assert.That(p.IsValid, Is.True, "no NaN anywhere in the avatar");
                    foreach (RigidPose p in pipeline.Pose.Local) Assert.That(p.IsValid, Is.True, "nor in its local poses");
                    Assert.That(pipeline.Hand(BodySide.Left).ControllerPose.IsValid, Is.True);
                }
            Assert.Throws<ArgumentException>(() => pipeline.Update(t, new DeviceSample[5], default, default, null), "a wrong sample count is a programming error");
        }

        [Test]
        public void TheFingersHoldTheControllersOnTheSolvedMixamoBody()
        {
            ControllerProfile controller = Profile("vive-wand");
            string session = Sessions.Simulate("mixamo_fingers_30fps.bvh", new SimulationOptions { Seed = 2, Controller = controller });
            EvaluationReport report;
            using (SessionReader reader = Sessions.Read(session)) report = SessionEvaluator.Evaluate(reader, WithController(controller));
            Assert.That(report.Fingers, Is.Not.Null, "the Mixamo avatar has finger bones");
            Assert.That(report.Fingers.Frames, Is.EqualTo(report.Frames));
            Assert.That(report.Fingers.OpenHandFrames, Is.EqualTo(0), "the palm never leaves the grip");
            Assert.That(report.Fingers.MaxPenetrationMm, Is.LessThanOrEqualTo(1.0), "no finger inside the controller");
            foreach (Finger f in new[] { Finger.Thumb, Finger.Index, Finger.Middle, Finger.Ring, Finger.Little })
                Assert.That(report.Fingers.Gap(f).Median, Is.LessThanOrEqualTo(3.0), $"{f} tip on the surface (mm)");
            // The palm on the grip puts the wrists where the grip says: within the grip's variation (±4 mm, ±4°).
            Assert.That(report.JointPositionMm[HumanoidBone.LeftHand].Median, Is.LessThanOrEqualTo(10.0));
            Assert.That(report.EndEffectorMm.Median, Is.LessThanOrEqualTo(5.0));
        }

        [Test]
        public void AGripKeptWhileTheHandFollowsItsControllerIsTheGripOfANewDescent()
        {
            // The Mixamo session with fingers, every frame's grip against a descent from scratch on that frame's wrist and
            // controller (a second solver on the same hand, opened before each solve so that it never keeps a grip).
            ControllerProfile controller = Profile("vive-wand");
            string session = Sessions.Simulate("mixamo_fingers_30fps.bvh", new SimulationOptions { Controller = controller });
            var reference = new FingerSolver[2];
            int frames = 0, kept = 0;
            float worst = 0f;
            bool calibrated = false;
            Sessions.Replay(session, WithController(controller), (i, pipeline, frame) =>
            {
                if (pipeline.State != CalibrationState.Calibrated) return;
                if (!calibrated)
                {
                    calibrated = true; // the calibrating frame shows the calibration pose; the fingers are solved from the next
                    return;
                }
                for (int s = 0; s < 2; s++)
                {
                    var side = (BodySide)s;
                    HandState hand = pipeline.Hand(side);
                    Assert.That(hand.HasFingerIk, Is.True, hand.NoFingerIkReason);
                    reference[s] ??= new FingerSolver(hand.Solver.Hand, hand.Solver.Profile);
                    RigidPose wrist = pipeline.Pose.World[pipeline.ScaledAvatar[side == BodySide.Left ? HumanoidBone.LeftHand : HumanoidBone.RightHand]];
                    reference[s].Solve(wrist, hand.ControllerPose, GripMode.Open);
                    reference[s].Solve(wrist, hand.ControllerPose, GripMode.Hold);
                    float[] fresh = reference[s].Parameters.ToArray(), solved = hand.Fingers.ToArray();
                    for (int k = 0; k < fresh.Length; k++) worst = Math.Max(worst, Math.Abs(fresh[k] - solved[k]));
                    frames++;
                    if (hand.Solver.LastSolveReused) kept++;
                }
            });
            TestContext.WriteLine($"{kept} of {frames} hand frames kept the grip before; largest difference from a new descent {worst:G3} in t");
            Assert.That(frames, Is.GreaterThan(400));
            // Within the descent's own convergence tolerance (2e-3 in t, 0.2 degrees at a joint).
            Assert.That(worst, Is.LessThanOrEqualTo(2e-3f));
            // A hand the arm reaches stays where its controller holds it: most frames need no descent.
            Assert.That(kept, Is.GreaterThan(frames / 2), "frames whose grip was kept");
        }

        [Test]
        public void AControllerOutOfReachIsDrawnInTheHandWithoutAJump()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 42);
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map);
            double t = 0;
            wearer.Calibrate(pipeline, RigidPose.Identity, ref t);
            Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated));
            int right = Array.IndexOf(Wearer.TrueRoles, DeviceRole.RightHand);
            int wrist = pipeline.ScaledAvatar[HumanoidBone.RightHand];
            RigidPose grip = pipeline.ActiveProfile.JointInDevice(DeviceRole.RightHand).Inverse();
            HandState hand = pipeline.Hand(BodySide.Right);
            var samples = new DeviceSample[6];
            // The right controller moves out along the arm, 1 cm a frame, to 40 cm beyond where the arm reaches in T-pose
            // (an avatar with shorter arms than the wearer's), then back.
            RigidPose previous = RigidPose.Identity;
            float largestStep = 0f;
            bool wasInHand = false, cameBack = false;
            for (int i = 0; i <= 80; i++)
            {
                wearer.Sample(samples, 0f, 0f);
                float out_ = 0.01f * (i <= 40 ? i : 80 - i);
                samples[right] = new DeviceSample(new RigidPose(samples[right].Pose.Position + new Vector3(out_, 0, 0), samples[right].Pose.Rotation), true);
                pipeline.Update(t += 1 / 90.0, samples, default, default, null);
                if (hand.DrawnInHand)
                {
                    wasInHand = true;
                    Assert.That(hand.Reached, Is.False);
                    Approx.Near(pipeline.Pose.World[wrist] * grip, hand.ControllerPose, 1e-4f, 0.01f, "drawn in the grip, in the hand");
                }
                else
                {
                    if (wasInHand) cameBack = true;
                    Approx.Near(samples[right].Pose, hand.ControllerPose, 1e-5f, 0.01f, "at the tracked pose while reached");
                }
                if (i > 0) largestStep = Math.Max(largestStep, Vector3.Distance(previous.Position, hand.ControllerPose.Position));
                previous = hand.ControllerPose;
            }
            Assert.That(wasInHand, Is.True, "40 cm is beyond the arm's reach");
            Assert.That(cameBack, Is.True, "and back within it");
            Assert.That(largestStep, Is.LessThanOrEqualTo(0.0105f), "the drawn controller never moves more than the 1 cm the controller moves per frame");
        }

        [Test]
        public void ARepeatedFrameDoesNotMoveTheShoulders()
        {
            // A recording with a repeated timestamp gives the pipeline the same time again, and so does the recorded-session
            // source while the game is paused (its clock is the game's scaled time; the live sources use real time). Every 200th frame of a 90 Hz session is fed twice:
            // on the repeat the shoulders stay where they were (the held shrug is neither dropped nor released).
            string session = Sessions.Simulate("mocapbank_30fps.bvh", new SimulationOptions { Rate = 90, Seed = 3 });
            using SessionReader reader = Sessions.Read(session);
            var pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid);
            SessionFrame f = reader.CreateFrame();
            float largest = 0f;
            int calibrated = 0, repeats = 0;
            while (reader.ReadFrame(f))
            {
                pipeline.Update(f);
                if (pipeline.State != CalibrationState.Calibrated || ++calibrated % 200 != 0) continue;
                Vector3 left = pipeline.Pose.World[pipeline.ScaledAvatar[HumanoidBone.LeftUpperArm]].Position;
                Vector3 right = pipeline.Pose.World[pipeline.ScaledAvatar[HumanoidBone.RightUpperArm]].Position;
                pipeline.Update(f);
                repeats++;
                largest = Math.Max(largest, Vector3.Distance(left, pipeline.Pose.World[pipeline.ScaledAvatar[HumanoidBone.LeftUpperArm]].Position));
                largest = Math.Max(largest, Vector3.Distance(right, pipeline.Pose.World[pipeline.ScaledAvatar[HumanoidBone.RightUpperArm]].Position));
            }
            TestContext.WriteLine($"{repeats} repeated frames: shoulders moved at most {largest * 1000:F2} mm");
            Assert.That(repeats, Is.GreaterThanOrEqualTo(5));
            Assert.That(largest, Is.LessThan(0.001f), "the shoulders on a repeated frame (m)");
        }

        [Test]
        public void TheSolvedPoseDoesNotDependOnTheFrameRate()
        {
            // The same noise-free motion sampled at 72 and 144 Hz. With one calibration restored into both runs and no shrug
            // held (ShrugReleaseSeconds 0), the per-frame path has nothing that depends on the frame time: at the times both
            // rates share, the avatar is the same up to the IK's convergence (each solve starts from the previous frame's
            // pose, so the history differs: measured 0.47 mm; 1.39 mm since the back flexes about the hip line, on a nearly
            // straight elbow, where a micrometre at the shoulder is a millimetre at the elbow). Calibrated at each rate, the T-pose and walk-in windows hold
            // different samples of a wearer who sways, so the offsets (and the elbow) may differ by a little more: 2.47 mm on
            // one frame since the back's flexion starts 0.01 rad forward, where the spine differs by 2-7 micrometres and the
            // shoulder by 1.06 mm (the elbow's p99 0.083 mm, as before; the chest's largest difference 0.75 mm, 0.91 before).
            // The straight limbs' filters follow time, but a One Euro step of 1/72 s is not two of 1/144 s: with the straight
            // arm's steadying (session 14) the restored run's largest elbow difference went 1.12 -> 1.75 mm (the calibrated
            // runs' 2.47 -> 1.74 mm); the filter's own test puts the same slow reach's elbow 0.49 mm apart at 45 and 180 Hz.
            var sessions = new Dictionary<int, string>();
            foreach (int rate in new[] { 72, 144 })
                sessions[rate] = Sessions.Simulate("mocapbank_30fps.bvh", new SimulationOptions { Rate = rate, PositionNoise = 0, RotationNoiseDegrees = 0, Seed = 3 });
            CalibrationProfile profile = Sessions.Replay(sessions[72]).Profile;
            Assert.That(profile, Is.Not.Null, "the 72 Hz session calibrates");

            (float restored, _) = Difference(rate => Replay(sessions[rate], profile, 0f, HumanoidBone.LeftLowerArm));
            (float calibrated, _) = Difference(rate => Replay(sessions[rate], null, 0f, HumanoidBone.LeftLowerArm));
            Assert.That(restored, Is.LessThanOrEqualTo(0.0022f), "one calibration: left elbow, largest difference (m)");
            Assert.That(calibrated, Is.LessThanOrEqualTo(0.003f), "calibrated at each rate: left elbow, largest difference (m)");

            // Held shrugs are released over seconds at any rate, but what each one holds is the shrug of the frame that
            // needed it, sampled at that frame: the shoulders differ by the arm's motion between samples (a few mm, an order
            // below the 2-4 cm they correct on this clip, Documentation~/solver.md). A nearly straight elbow's position is that
            // sensitive to its shoulder (1 mm nearer the hand moves it ~1.5 cm off the line), so for the elbow the typical
            // frame is compared.
            float release = FullBodyIk.DefaultShrugReleaseSeconds;
            (float shoulder, _) = Difference(rate => Replay(sessions[rate], profile, release, HumanoidBone.LeftUpperArm));
            (_, float elbowMedian) = Difference(rate => Replay(sessions[rate], profile, release, HumanoidBone.LeftLowerArm));
            TestContext.WriteLine($"shrugs held: left shoulder largest difference {shoulder * 1000:F2} mm, left elbow median {elbowMedian * 1000:F2} mm");
            Assert.That(shoulder, Is.LessThanOrEqualTo(0.005f), "shrugs held: left shoulder, largest difference (m)");
            Assert.That(elbowMedian, Is.LessThanOrEqualTo(0.001f), "shrugs held: left elbow, median difference (m)");
        }

        // A joint's world position at every solved frame, keyed by time in 1/720 s (a multiple of both periods).
        private static Dictionary<long, Vector3> Replay(string session, CalibrationProfile restore, float shrugReleaseSeconds, HumanoidBone bone)
        {
            var joints = new Dictionary<long, Vector3>();
            using SessionReader reader = Sessions.Read(session);
            var pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid, new PipelineSettings { ShrugReleaseSeconds = shrugReleaseSeconds });
            if (restore != null) Assert.That(pipeline.TryRestore(restore), Is.True, "the profile's devices are the session's");
            SessionFrame f = reader.CreateFrame();
            while (reader.ReadFrame(f))
            {
                pipeline.Update(f);
                if (pipeline.State == CalibrationState.Calibrated) joints[(long)Math.Round(f.Time * 720)] = pipeline.Pose.World[pipeline.ScaledAvatar[bone]].Position;
            }
            return joints;
        }

        // The largest and the median distance between the 72 Hz and the 144 Hz positions at the times both have (m).
        private static (float largest, float median) Difference(Func<int, Dictionary<long, Vector3>> replay)
        {
            Dictionary<long, Vector3> slow = replay(72), fast = replay(144);
            var distances = new List<float>();
            foreach (KeyValuePair<long, Vector3> s in slow)
                if (fast.TryGetValue(s.Key, out Vector3 f)) distances.Add(Vector3.Distance(s.Value, f));
            Assert.That(distances.Count, Is.GreaterThan(300));
            distances.Sort();
            return (distances[distances.Count - 1], distances[distances.Count / 2]);
        }
    }
}
