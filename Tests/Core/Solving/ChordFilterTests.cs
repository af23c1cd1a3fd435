using System;
using System.Numerics;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The back's chord filter (<see cref="FullBodyIk.ChordCutoffHz"/>): near a straight back the hips-to-head distance
    /// changes with the square of the flexion, so the devices' noise in it flexed the back to and fro and the chest jittered
    /// by a centimetre a frame. The back bends for the filtered distance; the head is left what the filter took out off its
    /// target (a millimetre or two) rather than the shoulders swung to put it back.
    /// </summary>
    public class ChordFilterTests
    {
        // The calibration T-pose of a clip and targets from it: the hips as they are, the head `drop` metres lower and `lean`
        // metres forward (the body faces +Z), plus noise; the feet and hands where the T-pose has them.
        private sealed class Stage
        {
            public readonly FullBodyIkTests.Truth Truth;
            public readonly SkeletonPose Calibration;
            public readonly int Chest, Head;

            public Stage(string clipName)
            {
                Truth = new FullBodyIkTests.Truth(clipName);
                Calibration = new SkeletonPose(Truth.Clip.Skeleton);
                TPoser.Apply(Truth.Map, Calibration, RigidPose.Identity);
                Chest = Truth[HumanoidBone.Chest];
                Head = Truth[HumanoidBone.Head];
            }

            public BodyTargets Targets(float drop, float lean, Vector3 hipsNoise, Vector3 headNoise)
            {
                RigidPose[] t = Calibration.World;
                RigidPose hips = t[Truth[HumanoidBone.Hips]], head = t[Head];
                Vector3 ahead = new Vector3(0f, 0f, 0.3f);
                return new BodyTargets
                {
                    Hips = new RigidPose(hips.Position + hipsNoise, hips.Rotation), HipsActive = true,
                    Head = new RigidPose(head.Position + new Vector3(0f, -drop, lean) + headNoise, head.Rotation), HeadActive = true,
                    SpineBend = Quaternion.Identity,
                    LeftFoot = new LimbTarget(t[Truth[HumanoidBone.LeftFoot]], t[Truth[HumanoidBone.LeftLowerLeg]].Position + ahead),
                    RightFoot = new LimbTarget(t[Truth[HumanoidBone.RightFoot]], t[Truth[HumanoidBone.RightLowerLeg]].Position + ahead),
                    LeftHand = new LimbTarget(t[Truth[HumanoidBone.LeftHand]], t[Truth[HumanoidBone.LeftLowerArm]].Position),
                    RightHand = new LimbTarget(t[Truth[HumanoidBone.RightHand]], t[Truth[HumanoidBone.RightLowerArm]].Position),
                };
            }
        }

        /// <summary>
        /// A wearer standing still with the back a little bent (the head 1.5 cm lower than in the T-pose), 1 mm of noise per
        /// coordinate on the hips and the head, 90 Hz. Measured when written (MocapBank / Rigify): the chest's move a frame p95 /
        /// max 9.3 / 18.7 and 10.9 / 22.2 mm unfiltered, 3.9 / 6.8 and 4.0 / 7.2 mm filtered; the head from its target p95 4.3
        /// and 4.6 mm unfiltered (what the back's stiffness and the polish leave), 5.8 and 6.2 mm filtered.
        /// </summary>
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("rigify_6channel_24fps_first240.bvh")]
        public void AStillBacksChestDoesNotJitterWithTheDevicesNoise(string clipName)
        {
            var stage = new Stage(clipName);
            const int frames = 900;
            var chestP95 = new float[2];
            var chestMax = new float[2];
            var headP95 = new float[2];
            for (int run = 0; run < 2; run++)
            {
                float cutoff = run == 0 ? FullBodyIk.DefaultChordCutoffHz : 0f;
                var ik = new FullBodyIk(stage.Truth.Map, stage.Calibration) { ChordCutoffHz = cutoff };
                var pose = new SkeletonPose(stage.Truth.Clip.Skeleton);
                Func<Vector3> noise = DeviceNoise.Source(3);
                var chestMoves = new float[frames - 1];
                var headLeft = new float[frames];
                Vector3 lastChest = default;
                for (int f = 0; f < frames; f++)
                {
                    BodyTargets targets = stage.Targets(0.015f, 0f, noise(), noise());
                    IkReport report = ik.Solve(in targets, pose, 1f / 90f);
                    Vector3 chest = pose.World[stage.Chest].Position;
                    if (f > 0) chestMoves[f - 1] = Vector3.Distance(chest, lastChest) * 1000f;
                    lastChest = chest;
                    headLeft[f] = report.HeadDistanceLeft * 1000f;
                }
                chestP95[run] = DeviceNoise.Percentile(chestMoves, 0.95);
                chestMax[run] = DeviceNoise.Percentile(chestMoves, 1.0);
                headP95[run] = DeviceNoise.Percentile(headLeft, 0.95);
                TestContext.WriteLine($"{clipName}, cutoff {cutoff} Hz: chest's move a frame p95 / max {chestP95[run]:F1} / {chestMax[run]:F1} mm; head from its target p95 {headP95[run]:F2} mm");
            }
            Assert.That(chestP95[1], Is.GreaterThan(2f * chestP95[0]), "unfiltered, the noise flexes the back (the chest's move a frame, p95): what the filter is for");
            Assert.That(chestP95[0], Is.LessThan(5f), "filtered, the chest about as steady as the devices (its move a frame, p95, mm)");
            Assert.That(chestMax[0], Is.LessThan(10f), "filtered, the chest's move a frame, max (mm)");
            Assert.That(headP95[0], Is.LessThan(headP95[1] + 2.5f), "the head left at most a couple of millimetres further from its target (p95, mm)");
        }

        /// <summary>
        /// The chord's filter follows time, not frames: a slow bow (the head 12 cm forward and 6 cm down and back again over
        /// two seconds, noise-free) puts the chest in the same place at the same time at 45 and at 180 frames a second
        /// (measured when written: 0.97 mm apart at most); the filter's lag leaves the head up to 9.2 / 9.4 mm from its target
        /// at either rate, against 5.0 mm unfiltered (what the one-axis bend and the polish leave).
        /// </summary>
        [Test]
        public void TheChordsFilterFollowsTimeNotFrames()
        {
            var stage = new Stage("mocapbank_30fps.bvh");
            float Bow(double s) => 0.5f * (float)(1.0 - Math.Cos(Math.PI * Math.Min(s, 2.0)));
            Vector3[] ChestAt(int rate, out float headLeft, float cutoff = FullBodyIk.DefaultChordCutoffHz)
            {
                var ik = new FullBodyIk(stage.Truth.Map, stage.Calibration) { ChordCutoffHz = cutoff };
                var pose = new SkeletonPose(stage.Truth.Clip.Skeleton);
                int frames = 2 * rate + 1;
                var chests = new Vector3[frames];
                headLeft = 0f;
                for (int f = 0; f < frames; f++)
                {
                    float b = Bow((double)f / rate);
                    BodyTargets targets = stage.Targets(0.06f * b, 0.12f * b, Vector3.Zero, Vector3.Zero);
                    IkReport report = ik.Solve(in targets, pose, 1f / rate);
                    chests[f] = pose.World[stage.Chest].Position;
                    headLeft = Math.Max(headLeft, report.HeadDistanceLeft * 1000f);
                }
                return chests;
            }
            Vector3[] slow = ChestAt(45, out float slowLeft), fast = ChestAt(180, out float fastLeft);
            ChestAt(90, out float unfilteredLeft, 0f);
            float apart = 0f;
            for (int f = 0; f < slow.Length; f++) apart = Math.Max(apart, Vector3.Distance(slow[f], fast[4 * f]) * 1000f);
            TestContext.WriteLine($"chest apart at 45 and 180 Hz at most {apart:F2} mm; the head from its target at most {slowLeft:F2} / {fastLeft:F2} mm (unfiltered, 90 Hz: {unfilteredLeft:F2} mm)");
            Assert.That(apart, Is.LessThan(1.5f), "the chest at the same time at either rate (mm)");
            Assert.That(Math.Max(slowLeft, fastLeft), Is.LessThan(unfilteredLeft + 6f), "the head's lag behind its target in a slow bow (mm)");
        }

        /// <summary>
        /// A head lost for a while starts the chord's filter again when it comes back: on its first frame back the back is
        /// what a solver that never saw the earlier frames gives (no stale distance from before the loss).
        /// </summary>
        [Test]
        public void AHeadThatComesBackStartsTheChordsFilterAgain()
        {
            var stage = new Stage("mocapbank_30fps.bvh");
            var ik = new FullBodyIk(stage.Truth.Map, stage.Calibration);
            var pose = new SkeletonPose(stage.Truth.Clip.Skeleton);
            for (int f = 0; f < 60; f++)
            {
                BodyTargets targets = stage.Targets(0.03f, 0f, Vector3.Zero, Vector3.Zero);
                if (f >= 30) targets.HeadActive = false;
                ik.Solve(in targets, pose, 1f / 90f);
            }
            // Back 4 cm lower than before it was lost.
            BodyTargets back = stage.Targets(0.07f, 0f, Vector3.Zero, Vector3.Zero);
            ik.Solve(in back, pose, 1f / 90f);
            var fresh = new FullBodyIk(stage.Truth.Map, stage.Calibration);
            var freshPose = new SkeletonPose(stage.Truth.Clip.Skeleton);
            fresh.Solve(in back, freshPose, 1f / 90f);
            float apart = Vector3.Distance(pose.World[stage.Chest].Position, freshPose.World[stage.Chest].Position) * 1000f;
            TestContext.WriteLine($"chest on the head's first frame back: {apart:F3} mm from a fresh solver's");
            Assert.That(apart, Is.LessThan(0.5f), "the first frame back bends for the head's distance, not a filtered memory of the old one (mm)");
        }
    }
}
