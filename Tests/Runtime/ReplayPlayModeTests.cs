using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using AvatarGo.Core;
using AvatarGo.Simulation;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace AvatarGo.Tests.Runtime
{
    /// <summary>
    /// A recorded session played frame by frame through the package's components (a <see cref="RecordedSessionTrackingSource"/>
    /// in stepped mode, the <see cref="AvatarGoCalibrator"/>, the <see cref="AvatarGoFingers"/> and the driver the calibrator
    /// adds) on an avatar of the wearer's skeleton: GameObjects bound by their names (the Transform driver), or, in
    /// <see cref="AnimatorIKDriverFollowsARecordedSession"/>, a humanoid mannequin driven by Animator IK. Each test has an engine-free twin in
    /// <c>Tests/Core/Shell/ReplayTwinTests.cs</c> with the same name, session and assertions (<see cref="ReplayCheck"/>).
    /// Needs the bundled clip on disk (<c>Tests/Core/Data~</c>, in the package folder): run in the Editor's play mode.
    /// </summary>
    public class ReplayPlayModeTests
    {
        private readonly List<GameObject> _made = new List<GameObject>();
        private string _file;

        [TearDown]
        public void CleanUp()
        {
            foreach (GameObject go in _made) if (go != null) UnityEngine.Object.Destroy(go);
            _made.Clear();
            if (_file != null && File.Exists(_file)) File.Delete(_file);
        }

        /// <summary>Twin: <c>ReplayTwinTests.RecordedSessionFollowsTheGroundTruth</c>.</summary>
        [UnityTest]
        public IEnumerator RecordedSessionFollowsTheGroundTruth()
        {
            var run = new Run();
            yield return Play(Session(), run);
            Assert.That(run.Calibrator.Pipeline.State, Is.EqualTo(CalibrationState.Calibrated), run.Calibrator.Pipeline.LastCalibrationStep.Message);
            SelfAvatarPipeline pipeline = run.Calibrator.Pipeline;
            Assert.That(pipeline.Hand(BodySide.Left).HasFingerIk && pipeline.Hand(BodySide.Right).HasFingerIk, Is.True, "both hands get finger IK");
            Assert.That(run.Check.HoldingFrames, Is.GreaterThan(100), "frames on which the fingers held the controller");
            Assert.That(run.Check.Failures(100), Is.Empty, run.Check.ToString());
        }

        /// <summary>Twin: <c>ReplayTwinTests.MalformedTPoseReachesTheWearersMessage</c>.</summary>
        [UnityTest]
        public IEnumerator MalformedTPoseReachesTheWearersMessage()
        {
            var run = new Run();
            yield return Play(ReplayScenario.WithOneArmLowered(Session()), run);
            SelfAvatarPipeline pipeline = run.Calibrator.Pipeline;
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.WaitingForTPose), "a T-pose with one arm low is never accepted");
            Assert.That(pipeline.LastCalibrationStep.Error, Is.EqualTo(CalibrationError.ArmsNotLevel));
            // The twin also checks the refusal is announced (OnStepRefused's argument); here that needs UnityEvent<T>.AddListener
            // in the surface, not added yet.
            Assert.That(run.Calibrator.Flow.Message, Does.Contain(pipeline.LastCalibrationStep.Message), "the wearer's text shows the error's message");
        }

        /// <summary>Twin: <c>ReplayTwinTests.LostTrackerDegradesWithoutExceptions</c>. An exception or error log fails a UTF test by itself.</summary>
        [UnityTest]
        public IEnumerator LostTrackerDegradesWithoutExceptions()
        {
            var run = new Run();
            yield return Play(ReplayScenario.WithATrackerLost(Session()), run);
            Assert.That(run.Check.FramesWithAnUntrackedDevice, Is.GreaterThan(100), "measured frames with the tracker lost (1.5 s at 90 Hz)");
            Assert.That(run.Calibrator.Pipeline.State, Is.EqualTo(CalibrationState.Calibrated), "a lost tracker does not undo the calibration");
            Assert.That(run.Check.Failures(100, accuracy: false), Is.Empty, run.Check.ToString());
        }

        private sealed class Run
        {
            public AvatarGoCalibrator Calibrator;
            public readonly ReplayCheck Check = new ReplayCheck();
        }

        private static string _session;

        private static string Session() => _session ?? (_session = ReplayScenario.Simulate(ReplayScenario.ClipPath(PackageRoot())));

        // The package folder on disk: embedded (Packages/<name>) or installed (Library/PackageCache/<name>@<hash>).
        private static string PackageRoot()
        {
            const string name = "com.avatargo.selfavatar";
            string embedded = Path.GetFullPath(Path.Combine("Packages", name));
            if (File.Exists(Path.Combine(embedded, "package.json"))) return embedded;
            string cache = Path.GetFullPath(Path.Combine("Library", "PackageCache"));
            if (Directory.Exists(cache))
                foreach (string dir in Directory.GetDirectories(cache, name + "@*")) return dir;
            Assert.Ignore($"the package folder of {name} was not found on disk (the bundled clip is read from Tests/Core/Data~)");
            return null;
        }

        /// <summary>
        /// Twins: <c>AnimatorIkTargetsTests.TheTargetsReproduceThePipelinesSolve</c> (the goals, hints, hips and bone
        /// rotations the driver sets reproduce the pipeline's solve within 1 mm) with <c>ReplayTwinTests.RecordedSessionFollowsTheGroundTruth</c>
        /// (that solve follows the truth within these bounds). Here Unity's own humanoid IK does the solving, on a mannequin
        /// of the wearer's skeleton made a humanoid with <see cref="MannequinBuilder"/>: the default Animator IK driver's path.
        /// </summary>
        [UnityTest]
        public IEnumerator AnimatorIKDriverFollowsARecordedSession()
        {
            var run = new Run();
            yield return Play(Session(), run, humanoid: true);
            SelfAvatarPipeline pipeline = run.Calibrator.Pipeline;
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
            Assert.That(run.Calibrator.Animator.GetComponent<AvatarGoAnimatorIKDriver>(), Is.Not.Null, "the calibrator added the Animator IK driver");
            Assert.That(run.Check.Failures(100), Is.Empty, run.Check.ToString());
        }

        private IEnumerator Play(string session, Run run, bool humanoid = false)
        {
            _file = Path.Combine(Path.GetTempPath(), "avatargo-playmode-" + Guid.NewGuid().ToString("N") + ".agsession");
            File.WriteAllText(_file, session);
            HumanoidMap wearer;
            using (SessionReader reader = SessionReader.Open(_file)) wearer = reader.Header.TruthHumanoid;

            // The avatar. Humanoid: a mannequin of the wearer's skeleton in T-pose with a humanoid Animator (Animator IK).
            // Otherwise the wearer's skeleton in its rest pose, one GameObject per joint, bound by the bones' names.
            Animator animator = null;
            Transform root = null;
            if (humanoid)
            {
                animator = MannequinBuilder.Build(MannequinBlueprint.Create(wearer), null, null);
                Assert.That(animator, Is.Not.Null, "Unity built the mannequin's humanoid Avatar");
                _made.Add(animator.gameObject);
            }
            else
            {
                List<HierarchyNode> nodes = ReplayScenario.AvatarNodes(wearer);
                var made = new Transform[nodes.Count];
                for (int n = 0; n < nodes.Count; n++)
                {
                    var go = new GameObject(nodes[n].Name);
                    made[n] = go.transform;
                    if (nodes[n].Parent >= 0) made[n].SetParent(made[nodes[n].Parent], false);
                    else _made.Add(go);
                    made[n].localPosition = nodes[n].LocalPosition.ToUnity();
                    made[n].localRotation = nodes[n].LocalRotation.ToUnity();
                }
                root = made[0];
            }

            // The prefab's components, as the prefab wires them, with the recorded source in the tracking slot.
            var rig = new GameObject("AvatarGo");
            _made.Add(rig);
            var source = rig.AddComponent<RecordedSessionTrackingSource>();
            source.FilePath = _file;
            source.Mode = RecordedSessionTrackingSource.PlaybackMode.Stepped;
            Assert.That(source.Restart(), Is.True);
            run.Calibrator = rig.AddComponent<AvatarGoCalibrator>();
            run.Calibrator.Source = source;
            if (animator != null) run.Calibrator.Animator = animator;
            else run.Calibrator.AvatarRoot = root;
            run.Calibrator.Offsets = OffsetMode.Exact;
            // Every test calibrates from its own session: a profile saved by an earlier test (same simulated serials, same
            // avatar) must not be restored, and none is written to the user's data folder.
            run.Calibrator.RestoresSavedProfileOnStart = false;
            run.Calibrator.SavesProfile = false;
            var fingers = rig.AddComponent<AvatarGoFingers>();
            fingers.Calibrator = run.Calibrator;
            fingers.SetGrip(BodySide.Left, GripMode.Hold);
            fingers.SetGrip(BodySide.Right, GripMode.Hold);

            // One recorded frame per rendered frame. A [UnityTest] resumes after Update, before LateUpdate: the bones seen
            // now were written in the previous frame's LateUpdate, from the previous recorded frame, whose truth is kept.
            SessionFrame previous = null;
            bool measuring = false, calibratedEarlier = false;
            while (source.Step())
            {
                yield return null;
                SelfAvatarPipeline pipeline = run.Calibrator.Pipeline;
                if (pipeline == null || !run.Calibrator.HasFrame) continue;
                if (measuring && previous != null)
                {
                    HumanoidBinding binding = run.Calibrator.Binding;
                    run.Check.Add(previous, bone => binding[bone] != null ? binding[bone].position.ToCore() : (System.Numerics.Vector3?)null, pipeline);
                }
                // The twin skips the first calibrated frame and measures from the second on. Its bones are seen one resume
                // later (written in this frame's LateUpdate), so the flag set now is for the frame read now.
                bool calibrated = pipeline.State == CalibrationState.Calibrated;
                measuring = calibrated && calibratedEarlier;
                calibratedEarlier |= calibrated;
                if (previous == null) previous = new SessionFrame(source.Header);
                SessionFrame current = run.Calibrator.CurrentFrame;
                Array.Copy(current.Truth, previous.Truth, previous.Truth.Length);
                Array.Copy(current.HasTruth, previous.HasTruth, previous.HasTruth.Length);
                Array.Copy(current.Samples, previous.Samples, previous.Samples.Length); // the lost-frame count reads them
            }
        }
    }
}
