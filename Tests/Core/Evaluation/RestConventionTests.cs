using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Issue 10: the result depends on the motion only, not on how the skeleton is expressed. A clip and the same clip
    /// rebased (every bone along its joint's +X, with no twist and with 37°; every joint's axes random, three seeds) are
    /// simulated with the same seed and evaluated: calibration succeeds in every convention, and MPJPE, the end-effector
    /// median and the elbows' and knees' median each differ from the clip's own by at most 0.5 mm. The default suite runs
    /// two shipped clips (MocapBank through the walk-in offsets, Mixamo with the palms on the VIVE wand); the slow suite
    /// every shared clip, the full Rigify clip included, with three simulation seeds and both hand placements.
    /// </summary>
    public class RestConventionTests
    {
        internal static readonly (string rest, float twist, int seed)[] Conventions =
        {
            ("x-along", 0f, 0), ("x-along", 37f, 0), ("random", 0f, 1), ("random", 0f, 2), ("random", 0f, 3),
        };

        internal static ControllerProfile ViveWand() =>
            ControllerProfile.Parse(File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/vive-wand.json")));

        /// <summary>
        /// Simulates <paramref name="clip"/> (metres) with <paramref name="seed"/> and evaluates it, palms on the controller or
        /// walk-in offsets, the knees bent as <paramref name="knees"/> chooses.
        /// </summary>
        internal static EvaluationReport Evaluate(BvhClip clip, int seed, bool palm, KneeHintModel knees = KneeHintModel.OuterOfPelvisAndFoot)
        {
            ControllerProfile wand = ViveWand();
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = seed, Controller = wand });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            var settings = new PipelineSettings { KneeHints = knees };
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                settings.Hand(side).Controller = wand;
                settings.Hand(side).Placement = palm ? HandPlacement.PalmOnController : HandPlacement.CalibratedOffset;
            }
            using var reader = new SessionReader(new StringReader(text.ToString()), "rebased");
            return SessionEvaluator.Evaluate(reader, settings);
        }

        internal static BvhClip Read(string path) => BvhReader.ReadFile(path, new BvhReadOptions { ToMetres = true });

        internal static BvhClip Rebased(string path, (string rest, float twist, int seed) c)
        {
            BvhClip rebased = BvhRebaserTests.Rebase(BvhReader.ReadFile(path), c.rest, c.twist, c.seed);
            var text = new StringWriter();
            BvhWriter.Write(text, rebased);
            return BvhReader.Read(new StringReader(text.ToString()), "rebased", new BvhReadOptions { ToMetres = true });
        }

        internal static void AssertSame(EvaluationReport own, EvaluationReport other, string what)
        {
            Assert.That(other.Profile, Is.Not.Null, $"{what}: calibration failed: {other.CalibrationMessage}");
            Assert.That(other.Frames, Is.EqualTo(own.Frames), $"{what}: frames compared");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.5), $"{what}: MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.5), $"{what}: end-effector median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.5), $"{what}: elbows' and knees' median (mm)");
        }

        [TestCase("mocapbank_30fps.bvh", false)]
        [TestCase("mixamo_fingers_30fps.bvh", true)]
        public void TheSameMotionInAnyRestConventionGivesTheSameAvatar(string file, bool palm)
        {
            string path = TestData.Mocap(file);
            EvaluationReport own = Evaluate(Read(path), 1, palm);
            Assert.That(own.Profile, Is.Not.Null, own.CalibrationMessage);
            foreach (var c in Conventions)
                AssertSame(own, Evaluate(Rebased(path, c), 1, palm), $"{file} {c.rest} twist {c.twist} seed {c.seed}");
        }

        private static IEnumerable<TestCaseData> SharedClips()
        {
            foreach (string clip in new[] { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps.bvh" })
                foreach (bool palm in new[] { false, true })
                    yield return new TestCaseData(clip, palm).SetName($"AllConventions {clip} {(palm ? "palm" : "calibrated")}");
        }

        [TestCaseSource(nameof(SharedClips)), Category("Slow")]
        public void EverySharedClipInEveryConventionAndSeedGivesTheSameAvatar(string file, bool palm)
        {
            string path = TestData.SharedMocap(file);
            var rebased = new List<BvhClip>();
            foreach (var c in Conventions) rebased.Add(Rebased(path, c));
            BvhClip clip = Read(path);
            for (int seed = 1; seed <= 3; seed++)
            {
                EvaluationReport own = Evaluate(clip, seed, palm);
                Assert.That(own.Profile, Is.Not.Null, own.CalibrationMessage);
                for (int i = 0; i < Conventions.Length; i++)
                    AssertSame(own, Evaluate(rebased[i], seed, palm), $"{file} {Conventions[i].rest} twist {Conventions[i].twist} seed {Conventions[i].seed}, simulation seed {seed}");
            }
        }

        // Issue 10's bounds, walk-in offsets for the hands, three seeds, where the clip allows them (solver.md): Rigify's
        // left knee bends backward in its data in the few frames it bends 15° or more, so its flips are left out.
        [TestCase("mocapbank_30fps.bvh", true), TestCase("mixamo_fingers_30fps.bvh", true), TestCase("rigify_6channel_24fps.bvh", false)]
        [Category("Slow")]
        public void TheIssuesBoundsHoldWhereTheClipAllows(string file, bool leftKneeFlips)
        {
            BvhClip clip = Read(TestData.SharedMocap(file));
            for (int seed = 1; seed <= 3; seed++)
            {
                EvaluationReport r = Evaluate(clip, seed, false);
                Assert.That(r.Profile, Is.Not.Null, r.CalibrationMessage);
                Assert.That(r.EndEffectorMm.P95, Is.LessThanOrEqualTo(10.0), $"{file} seed {seed}: end effectors p95 (mm)");
                foreach (BendPlaneReport b in r.BendPlanes)
                    if (leftKneeFlips || b.Joint != HumanoidBone.LeftLowerLeg)
                        Assert.That(b.FlippedShare, Is.LessThanOrEqualTo(0.01), $"{file} seed {seed}: {b.Joint} flipped");
                Assert.That(r.AllJointsMm.Mean, Is.LessThanOrEqualTo(18.0), $"{file} seed {seed}: MPJPE (mm)");
                Assert.That(r.MidJointMm.Median, Is.LessThanOrEqualTo(35.0), $"{file} seed {seed}: elbows and knees median (mm)");
                Assert.That(r.MidJointMm.P95, Is.LessThanOrEqualTo(100.0), $"{file} seed {seed}: elbows and knees p95 (mm)");
            }
        }
    }
}
