using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// A clip written in a left-handed frame reads as its own mirror image: the joints named Left end on the body's right,
    /// and a wearer made from it bends its knees backward (before: calibration succeeded and every knee of the avatar was
    /// flipped). The simulator sees the knees bend backward (<see cref="ClipConventions.CountKneeBends"/>) and mirrors the
    /// clip back (<see cref="SessionSimulator.Mirrored"/>), so the avatar follows it as it follows the original. A clip whose
    /// sides are named the wrong way round is mirrored too: it becomes the mirror image of the motion, a valid person.
    /// </summary>
    public class HandednessTests
    {
        private static BvhClip Clip(string name) => BvhReader.ReadFile(TestData.Mocap(name), new BvhReadOptions { ToMetres = true });

        private static (EvaluationReport report, bool mirrored) Evaluate(BvhClip clip, bool mirrorBackward = true)
        {
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 1, MirrorBackwardClip = mirrorBackward });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            using var reader = new SessionReader(new StringReader(text.ToString()), "handedness");
            return (SessionEvaluator.Evaluate(reader, new PipelineSettings()), simulator.Mirrored);
        }

        [Test]
        public void MirroringMovesEveryJointToTheOtherSideInEveryFrame()
        {
            BvhClip clip = Clip("mixamo_fingers_30fps.bvh"), mirrored = clip.Mirrored();
            int n = clip.Skeleton.JointCount;
            var local = new RigidPose[n];
            var world = new RigidPose[n];
            var mirroredWorld = new RigidPose[n];
            double worst = 0;
            for (int f = 0; f < clip.FrameCount; f++)
            {
                clip.GetWorldPoses(f, local, world);
                mirrored.GetWorldPoses(f, local, mirroredWorld);
                for (int j = 0; j < n; j++)
                {
                    var p = world[j].Position;
                    worst = System.Math.Max(worst, System.Numerics.Vector3.Distance(mirroredWorld[j].Position, new System.Numerics.Vector3(-p.X, p.Y, p.Z)));
                }
            }
            Assert.That(worst, Is.LessThan(1e-5), "metres");
            Assert.That(mirrored.Mirrored().GetValue(clip.FrameCount - 1, clip.ChannelCount - 1), Is.EqualTo(clip.GetValue(clip.FrameCount - 1, clip.ChannelCount - 1)), "mirrored twice is the clip");
        }

        [TestCase("mocapbank_30fps.bvh"), TestCase("mixamo_fingers_30fps.bvh")]
        public void KneesBendForwardInTheSharedClipsAndBackwardInTheirMirrorImages(string name) => AssertKneesBendForward(Clip(name));

        /// <summary>The whole Rigify clip (its first 240 frames, in the package, never bend a knee 20°).</summary>
        [Test, Category("Slow")]
        public void KneesBendForwardInTheWholeRigifyClip() =>
            AssertKneesBendForward(BvhReader.ReadFile(TestData.SharedMocap("rigify_6channel_24fps.bvh"), new BvhReadOptions { ToMetres = true }));

        private static void AssertKneesBendForward(BvhClip clip)
        {
            BvhClip mirrored = clip.Mirrored();
            ClipConventions.CountKneeBends(clip, HumanoidNaming.Detect(clip.Skeleton), out int forward, out int backward);
            ClipConventions.CountKneeBends(mirrored, HumanoidNaming.Detect(mirrored.Skeleton), out int mirroredForward, out int mirroredBackward);
            Assert.That(forward, Is.GreaterThanOrEqualTo(ClipConventions.MirroredMinimumBends));
            Assert.That(backward * 20, Is.LessThanOrEqualTo(forward), "a real clip's knees bend forward (at most 5 % counted backward)");
            Assert.That((mirroredForward, mirroredBackward), Is.EqualTo((backward, forward)), "the mirror image bends each knee the other way");
        }

        /// <summary>
        /// Found in review: the first statistic took the body's forward from the hips-to-head line, so with the trunk folded
        /// forward a knee in front of the body read as bending backward, and a crouch (MocapBank's half-kneel, frames 175–325,
        /// with the right leg given the left leg's rotations reflected: both knees bent, the trunk 58° forward) was mirrored,
        /// its avatar's knees then flipped in every bent frame (MPJPE 73 mm against 14.7). The knee's hinge axis against the
        /// hip line reads the legs and pelvis only.
        /// </summary>
        [Test]
        public void ACrouchWithTheTrunkFoldedForwardIsNotMirrored()
        {
            BvhClip clip = Clip("mocapbank_30fps.bvh");
            Skeleton s = clip.Skeleton;
            var frames = new System.Collections.Generic.List<RigidPose[]>();
            for (int f = 175; f < 325; f++)
            {
                var local = new RigidPose[s.JointCount];
                clip.GetLocalPoses(f, local);
                foreach (string joint in new[] { "Hip", "Knee", "Ankle" })
                {
                    System.Numerics.Quaternion q = local[s.IndexOf("Left" + joint)].Rotation;
                    int right = s.IndexOf("Right" + joint);
                    local[right] = new RigidPose(local[right].Position, new System.Numerics.Quaternion(q.X, -q.Y, -q.Z, q.W));
                }
                frames.Add(local);
            }
            BvhClip crouch = BvhClip.FromPoses(s, frames, clip.FrameTime);
            bool mirrored = ClipConventions.LooksMirrored(crouch, HumanoidNaming.Detect(s), out int forward, out int backward);
            Assert.That(forward, Is.GreaterThanOrEqualTo(2 * ClipConventions.MirroredMinimumBends), "the crouch bends its knees");
            Assert.That(mirrored, Is.False, $"{forward} forward, {backward} backward");
        }

        [Test]
        public void ALeftHandedClipIsMirroredBackAndGivesTheSameAvatar()
        {
            BvhClip clip = Clip("mocapbank_30fps.bvh");
            var (own, ownMirrored) = Evaluate(clip);
            var (other, mirrored) = Evaluate(clip.Mirrored());
            Assert.That(ownMirrored, Is.False, "a right-handed clip is left as it is");
            Assert.That(mirrored, Is.True);
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.01), "MPJPE (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.01), "elbows and knees median (mm)");

            // Kept as it is, the same clip bends the avatar's knees backward in most bent frames.
            var (kept, keptMirrored) = Evaluate(clip.Mirrored(), mirrorBackward: false);
            Assert.That(keptMirrored, Is.False);
            Assert.That(kept.BendPlanes.Where(b => b.Joint == HumanoidBone.LeftLowerLeg || b.Joint == HumanoidBone.RightLowerLeg).Min(b => b.FlippedShare), Is.GreaterThan(0.5));
        }

        /// <summary>
        /// Found in review: after mirroring, callers kept the skeleton they passed in, so the headset-free sample built its
        /// mannequin from the unmirrored one (its left thigh on the right) and demo --out-bvh failed writing the solved poses.
        /// The wearer as simulated is the mirrored skeleton, the same as the session's ground truth.
        /// </summary>
        [Test]
        public void TheWearerOfAMirroredClipIsTheMirroredSkeleton()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"));
            var text = new StringWriter();
            BvhWriter.Write(text, clip.Mirrored());
            string path = Path.Combine(Path.GetTempPath(), "avatargo-mirrored-" + System.Guid.NewGuid().ToString("N") + ".agsession");
            try
            {
                HumanoidMap wearer = HeadsetFreeSession.Write(text.ToString(), "mirrored", path, new SimulationOptions { Seed = 1 });
                using SessionReader reader = SessionReader.Open(path);
                HumanoidMap truth = reader.Header.TruthHumanoid;
                foreach (HumanoidBone bone in new[] { HumanoidBone.LeftUpperLeg, HumanoidBone.LeftUpperArm, HumanoidBone.RightHand })
                {
                    System.Numerics.Vector3 a = wearer.Skeleton.GetRestLocal(wearer[bone]).Position, b = truth.Skeleton.GetRestLocal(truth[bone]).Position;
                    Assert.That(System.Numerics.Vector3.Distance(a, b), Is.LessThan(1e-5f), $"{bone}: {a} against the truth's {b}");
                }
                Assert.That(wearer.Skeleton.GetRestLocal(wearer[HumanoidBone.LeftUpperLeg]).Position.X, Is.LessThan(0f), "the left thigh on the left (-X)");
            }
            finally { File.Delete(path); }
        }

        [Test]
        public void AClipWithItsSidesNamedTheWrongWayRoundBendsNoKneeBackward()
        {
            string text = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            string swapped = Regex.Replace(text, @"^(\s*(?:ROOT|JOINT)\s+)(Left|Right)", m => m.Groups[1].Value + (m.Groups[2].Value == "Left" ? "Right" : "Left"), RegexOptions.Multiline);
            BvhClip clip = BvhReader.Read(new StringReader(swapped), "swapped", new BvhReadOptions { ToMetres = true });
            var (report, mirrored) = Evaluate(clip);
            Assert.That(mirrored, Is.True);
            Assert.That(report.Profile, Is.Not.Null, report.CalibrationMessage);
            foreach (BendPlaneReport bend in report.BendPlanes)
                Assert.That(bend.FlippedShare, Is.LessThanOrEqualTo(0.01), bend.Joint.ToString());
            // The original's figure (18.1 mm, seed 1) within a few tenths: issue 10's 18 mm is missed by 0.1 mm since the
            // wearer calibrates looking straight ahead (Documentation~/solver.md, "The head at the T-pose").
            Assert.That(report.AllJointsMm.Mean, Is.LessThan(18.5), "MPJPE (mm)");
        }
    }
}
