using System;
using System.Collections.Generic;
using System.IO;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The result depends on the motion, not on how the skeleton is built. A clip is rewritten (<see cref="Topology"/>)
    /// into variants whose every remaining joint keeps its world pose in every frame, written to BVH text and read back as
    /// a user's file would be, simulated with the same seed and evaluated:
    /// <list type="bullet">
    /// <item>twist joints halfway along the upper arms, forearms, thighs and shins, and a floor-level root above the hips,
    /// are not humanoid bones: the same joints are found, and MPJPE, the end-effector median and the elbows' and knees'
    /// median equal the original's within 0.5 mm (issue 10's bound for "the same avatar"; measured ≤ 0.003 mm, the
    /// rounding of the rewritten clip);</item>
    /// <item>the clip mirrored left to right gives the original's figures with the sides swapped (below);</item>
    /// <item>optional bones dropped (the clavicles, the neck, the upper of the spine joints) change the skeleton, so only
    /// calibration, finite figures and the end effectors (median ≤ 5 mm, as the devices pin them) are checked; the figures
    /// are printed.</item>
    /// </list>
    /// The default suite runs the shipped MocapBank clip, seed 1; the slow suite every shared clip, the mirror with three
    /// seeds, twist joints and the floor root with seed 1 and, with no shrug held between frames, seeds 1-3 (below).
    /// </summary>
    /// <remarks>
    /// <para><b>The mirror.</b> Every world position has its x negated and every rotation R becomes M R M, M = diag(-1, 1, 1)
    /// (a proper rotation), and Left and Right swap in every name, so the limb now on the left is named left. Two things the
    /// simulator draws from the seed are not left-right symmetric, and the test mirrors them itself:</para>
    /// <para>the device mountings (<see cref="DeviceMountings.Sample"/> draws each device's offset independently, so a seed
    /// gives the left and right hands different offsets): the test draws them once from the seed, gives them to the
    /// original, and gives their mirror image, sides swapped, to the mirrored clip (<see cref="Topology.Mirrored(DeviceMountings)"/>;
    /// each mounting is given in the T-pose's body frame at landmarks the mirror maps onto the other side's);</para>
    /// <para>the tracking noise (drawn per device in the session's device order, so the mirrored left hand would get a
    /// different draw than its mirror image, the original right hand, got): both sessions are simulated without noise and
    /// get 1 mm / 0.1° noise in each device's own frame afterwards, the mirrored one the reflection of the other side's
    /// draw (<see cref="Topology.WithNoise"/>). With the simulator's own noise the per-joint medians differ by up to 2.3 mm
    /// (MocapBank's and Mixamo's forearms) and MPJPE by 0.12 mm; with mirrored noise but unmirrored mountings by 0.2 to
    /// 3.4 mm, as the noise draw goes. Without any noise the mountings cancel out (exact offsets) and the mirror holds to
    /// 0.003 mm either way.</para>
    /// <para>What stays different is rounding: the mirrored clip's floats are not bit for bit the reflection, and in a few
    /// frames near a branch (an arm at its reach) that rounding moves the elbow by up to 3 mm. Measured: MPJPE within
    /// 0.001 mm, per-joint medians within 0.002 mm (MocapBank, Rigify) and 0.23 mm (Mixamo's 297 frames, where 7-22 frames
    /// of an elbow differ). Tested: MPJPE within 0.5 mm, each joint's median within 1 mm of its mirror bone's: four times
    /// the largest rounding effect, and below what an unmirrored noise draw does. The original's sides differ by more than
    /// that (MocapBank's upper arms by 10 mm), which the test checks, so the side swap is what it sees.</para>
    /// <para><b>The held shrug.</b> <see cref="FullBodyIk"/> holds a clavicle's shrug for seconds, so a difference of a
    /// micrometre in a device (the spine's solve moves the chest by a fraction of a millimetre for it) can change the
    /// shoulder for the seconds after, and a shoulder moves a nearly straight elbow many times as far. MocapBank, seed 3:
    /// with twist joints the devices agree to 0.001 mm, yet the elbows' and knees' median moved by 0.25 mm (when the hold was
    /// yes or no); under a floor root the simulator's blend from the T-pose into the clip (which interpolates local
    /// poses, so its path depends on the hierarchy) moves the devices by up to 10 mm in those 89 frames, and the median
    /// moves by 1.3 mm. With no shrug held (<see cref="PipelineSettings.ShrugReleaseSeconds"/> 0) both agree within
    /// 0.005 mm. So seeds 1-3 are compared without held shrugs (seed 1 with them too): that isolates the skeleton's construction, the
    /// question asked here, from the held shrug's memory of the path.</para>
    /// </remarks>
    public class TopologyVariantTests
    {
        private const double SameMm = 0.5;         // issue 10's bound for "the same avatar" (RestConventionTests)
        private const double MirrorJointMm = 1.0;  // see the remarks: 4x the measured rounding effect, 1/3 of a one-sided mounting
        private const double EndEffectorMedianMm = 5.0;

        private static readonly Dictionary<(string, int, bool), EvaluationReport> Originals = new Dictionary<(string, int, bool), EvaluationReport>();

        // --- The variants -------------------------------------------------------------------------------------------

        /// <summary>The clip as a user's file: written to BVH text and read back in metres.</summary>
        private static BvhClip AsFile(BvhClip clip, string name)
        {
            var text = new StringWriter();
            BvhWriter.Write(text, clip);
            return BvhReader.Read(new StringReader(text.ToString()), name, new BvhReadOptions { ToMetres = true });
        }

        private static BvhClip Read(string path) => BvhReader.ReadFile(path, new BvhReadOptions { ToMetres = true });

        // The joints of the optional bones a variant drops: the clavicles, the neck, or the upper of the spine joints
        // below the neck (the one carrying the neck and the clavicles: MocapBank's Chest2, Mixamo's Spine2, Rigify's spine.001).
        private static int[] Optional(HumanoidMap map, string which)
        {
            switch (which)
            {
                case "clavicles": return new[] { map[HumanoidBone.LeftShoulder], map[HumanoidBone.RightShoulder] };
                case "neck": return new[] { map[HumanoidBone.Neck] };
                case "upper spine": return new[] { map.Has(HumanoidBone.UpperChest) ? map[HumanoidBone.UpperChest] : map[HumanoidBone.Chest] };
                default: throw new ArgumentException(which);
            }
        }

        private static readonly string[] Dropped = { "clavicles", "neck", "upper spine" };

        // --- Simulation and evaluation ------------------------------------------------------------------------------

        /// <summary>
        /// Simulates <paramref name="clip"/> with the seed's mountings and noise (the simulator's own) and evaluates it, with
        /// the default settings or, <paramref name="holdShrugs"/> false, with no shrug held between frames.
        /// </summary>
        private static EvaluationReport Evaluate(BvhClip clip, int seed, bool holdShrugs = true)
        {
            using SessionReader reader = Sessions.Read(Sessions.Simulate(clip, new SimulationOptions { Seed = seed }));
            return SessionEvaluator.Evaluate(reader, holdShrugs ? new PipelineSettings() : new PipelineSettings { ShrugReleaseSeconds = 0f });
        }

        private static EvaluationReport Original(string path, int seed, bool holdShrugs = true)
        {
            lock (Originals)
            {
                if (!Originals.TryGetValue((path, seed, holdShrugs), out EvaluationReport r)) Originals[(path, seed, holdShrugs)] = r = Evaluate(Read(path), seed, holdShrugs);
                Assert.That(r.Profile, Is.Not.Null, $"{Path.GetFileName(path)}: {r.CalibrationMessage}");
                return r;
            }
        }

        /// <summary>
        /// Simulates <paramref name="clip"/> with the seed and <paramref name="mountings"/>, without the simulator's noise,
        /// adds 1 mm / 0.1° noise from the seed in each device's frame (mirrored for a mirrored clip) and evaluates it.
        /// </summary>
        private static EvaluationReport EvaluateWithOwnNoise(BvhClip clip, int seed, DeviceMountings mountings, bool mirrored)
        {
            string session = Sessions.Simulate(clip, new SimulationOptions { Seed = seed, Mountings = mountings, PositionNoise = 0f, RotationNoiseDegrees = 0f });
            using SessionReader reader = Sessions.Read(Topology.WithNoise(session, seed, 0.001f, 0.1f, mirrored));
            return SessionEvaluator.Evaluate(reader, new PipelineSettings());
        }

        private static string Figures(EvaluationReport r) =>
            $"MPJPE {r.AllJointsMm.Mean:F2} mm, end effectors {r.EndEffectorMm.Median:F2} / {r.EndEffectorMm.P95:F2} mm (median / p95), elbows & knees {r.MidJointMm.Median:F2} / {r.MidJointMm.P95:F2} mm";

        // --- Checks ------------------------------------------------------------------------------------------------

        // Every joint of the original that the variant keeps (under its name, or its mirror name) is where it was.
        private static void AssertWorldPosesKept(BvhClip original, BvhClip variant, bool mirrored, string what)
        {
            var (mm, degrees) = mirrored
                ? Topology.WorldDeviation(original, variant, Topology.Mirror, Topology.SwapSides)
                : Topology.WorldDeviation(original, variant, p => p, n => n);
            // The BVH text's rounding (Euler degrees, lengths in metres): measured ≤ 0.001 mm and 0.0001°.
            Assert.That(mm, Is.LessThanOrEqualTo(0.01), $"{what}: a kept joint moved (mm)");
            Assert.That(degrees, Is.LessThanOrEqualTo(0.001), $"{what}: a kept joint turned (°)");
        }

        private static void AssertSame(EvaluationReport own, EvaluationReport other, string what)
        {
            TestContext.WriteLine($"{what}: {Figures(other)} (original {Figures(own)})");
            Assert.That(other.Profile, Is.Not.Null, $"{what}: calibration failed: {other.CalibrationMessage}");
            Assert.That(other.Frames, Is.EqualTo(own.Frames), $"{what}: frames compared");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(SameMm), $"{what}: MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(SameMm), $"{what}: end-effector median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(SameMm), $"{what}: elbows' and knees' median (mm)");
        }

        // The largest difference between a joint's median error in the mirrored clip and its mirror bone's in the original.
        private static double WorstMirrorJointMm(EvaluationReport own, EvaluationReport mirrored, out HumanoidBone worst)
        {
            double largest = 0;
            worst = HumanoidBone.Hips;
            foreach (KeyValuePair<HumanoidBone, ErrorSeries> joint in own.JointPositionMm)
            {
                HumanoidBone mirror = HumanoidBones.Mirror(joint.Key);
                Assert.That(mirrored.JointPositionMm.ContainsKey(mirror), Is.True, $"{mirror} is evaluated in the mirrored clip");
                double d = Math.Abs(mirrored.JointPositionMm[mirror].Median - joint.Value.Median);
                if (d > largest) { largest = d; worst = joint.Key; }
            }
            return largest;
        }

        // --- Twist joints and a floor root --------------------------------------------------------------------------

        private static void AssertTwistJointsChangeNothing(string path, int seed, bool holdShrugs = true)
        {
            BvhClip clip = Read(path);
            BvhClip twisted = AsFile(Topology.WithTwistJoints(clip), "twist joints");
            Assert.That(twisted.Skeleton.JointCount, Is.GreaterThan(clip.Skeleton.JointCount), "twist joints were inserted");
            AssertWorldPosesKept(clip, twisted, false, "twist joints");
            AssertSameHumanoidJoints(clip, twisted, "twist joints");
            AssertSame(Original(path, seed, holdShrugs), Evaluate(twisted, seed, holdShrugs), $"{Path.GetFileName(path)} with twist joints, seed {seed}{(holdShrugs ? "" : ", no held shrug")}");
        }

        private static void AssertFloorRootChangesNothing(string path, int seed, bool holdShrugs = true)
        {
            BvhClip clip = Read(path);
            BvhClip rooted = AsFile(Topology.WithFloorRoot(clip), "floor root");
            Assert.That(rooted.Skeleton.GetName(0), Is.EqualTo(Topology.FloorRootName));
            AssertWorldPosesKept(clip, rooted, false, "floor root");
            AssertSameHumanoidJoints(clip, rooted, "floor root");
            AssertSame(Original(path, seed, holdShrugs), Evaluate(rooted, seed, holdShrugs), $"{Path.GetFileName(path)} under a floor root, seed {seed}{(holdShrugs ? "" : ", no held shrug")}");
        }

        // Every humanoid bone is found on the joint of the same name (an inserted joint taken for one would show here).
        private static void AssertSameHumanoidJoints(BvhClip clip, BvhClip variant, string what)
        {
            HumanoidMap a = HumanoidNaming.Detect(clip.Skeleton), b = HumanoidNaming.Detect(variant.Skeleton);
            for (int bone = 0; bone < HumanoidBones.Count; bone++)
                Assert.That(b.NameOf((HumanoidBone)bone), Is.EqualTo(a.NameOf((HumanoidBone)bone)), $"{what}: {(HumanoidBone)bone}");
        }

        [Test]
        public void TwistJointsAlongTheLimbsGiveTheSameAvatar() => AssertTwistJointsChangeNothing(TestData.Mocap("mocapbank_30fps.bvh"), 1);

        [Test]
        public void AFloorLevelRootAboveTheHipsGivesTheSameAvatar() => AssertFloorRootChangesNothing(TestData.Mocap("mocapbank_30fps.bvh"), 1);

        // --- The mirror ---------------------------------------------------------------------------------------------

        private static void AssertMirrorGivesMirroredAvatar(string path, int seed)
        {
            BvhClip clip = Read(path);
            BvhClip mirrored = AsFile(Topology.Mirrored(clip), "mirrored");
            AssertWorldPosesKept(clip, mirrored, true, "mirrored");
            HumanoidMap a = HumanoidNaming.Detect(clip.Skeleton), b = HumanoidNaming.Detect(mirrored.Skeleton);
            for (int bone = 0; bone < HumanoidBones.Count; bone++)
                Assert.That(b[(HumanoidBone)bone], Is.EqualTo(a[HumanoidBones.Mirror((HumanoidBone)bone)]), $"mirrored {(HumanoidBone)bone} is the original's {HumanoidBones.Mirror((HumanoidBone)bone)}");

            DeviceMountings mountings = DeviceMountings.Sample(new Random(seed));
            EvaluationReport own = EvaluateWithOwnNoise(clip, seed, mountings, false);
            EvaluationReport other = EvaluateWithOwnNoise(mirrored, seed, Topology.Mirrored(mountings), true);
            string what = $"{Path.GetFileName(path)} mirrored, seed {seed}";
            double worst = WorstMirrorJointMm(own, other, out HumanoidBone worstBone);
            TestContext.WriteLine($"{what}: {Figures(other)} (original {Figures(own)}); largest per-joint median difference {worst:F3} mm ({worstBone})");
            Assert.That(own.Profile, Is.Not.Null, own.CalibrationMessage);
            Assert.That(other.Profile, Is.Not.Null, $"{what}: calibration failed: {other.CalibrationMessage}");
            Assert.That(other.Frames, Is.EqualTo(own.Frames), $"{what}: frames compared");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(SameMm), $"{what}: MPJPE (mm)");
            // The sides differ by more than the tolerance somewhere (MocapBank's upper arms by 10 mm), so comparing each
            // joint with its mirror bone's, not its own, is what is tested.
            double sides = 0;
            foreach (KeyValuePair<HumanoidBone, ErrorSeries> joint in own.JointPositionMm)
                sides = Math.Max(sides, Math.Abs(joint.Value.Median - own.JointPositionMm[HumanoidBones.Mirror(joint.Key)].Median));
            Assert.That(sides, Is.GreaterThan(MirrorJointMm), $"{what}: the original's sides differ");
            foreach (KeyValuePair<HumanoidBone, ErrorSeries> joint in own.JointPositionMm)
            {
                HumanoidBone mirror = HumanoidBones.Mirror(joint.Key);
                Assert.That(other.JointPositionMm[mirror].Median, Is.EqualTo(joint.Value.Median).Within(MirrorJointMm),
                    $"{what}: the mirrored clip's {mirror} median against the original's {joint.Key} (mm)");
            }
        }

        [Test]
        public void TheMirroredClipGivesTheMirroredAvatar() => AssertMirrorGivesMirroredAvatar(TestData.Mocap("mocapbank_30fps.bvh"), 1);

        // --- Optional bones dropped ---------------------------------------------------------------------------------

        private static void AssertDroppedBonesStillWork(string path, string which, int seed)
        {
            BvhClip clip = Read(path);
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            int[] dropped = Optional(map, which);
            foreach (int j in dropped) Assert.That(j, Is.GreaterThanOrEqualTo(0), $"{which}: the clip has the bone");
            BvhClip without = AsFile(Topology.Without(clip, dropped), "without " + which);
            Assert.That(without.Skeleton.JointCount, Is.EqualTo(clip.Skeleton.JointCount - dropped.Length));
            AssertWorldPosesKept(clip, without, false, "without " + which);
            Assert.That(HumanoidNaming.Detect(without.Skeleton).MissingRequired(), Is.Empty, $"without {which}: required bones");

            EvaluationReport r = Evaluate(without, seed);
            string what = $"{Path.GetFileName(path)} without the {which}, seed {seed}";
            TestContext.WriteLine($"{what}: {Figures(r)}, hands out of reach {r.UnreachedHandFrames} frames ({r.UnreachedWhileBentFrames} bent) (original {Figures(Original(path, seed))})");
            Assert.That(r.Profile, Is.Not.Null, $"{what}: calibration failed: {r.CalibrationMessage}");
            Assert.That(r.Frames, Is.GreaterThan(0), $"{what}: frames compared");
            Assert.That(r.AllJointsMm.InvalidCount, Is.Zero, $"{what}: NaN or infinite joint errors");
            foreach (KeyValuePair<HumanoidBone, ErrorSeries> joint in r.JointPositionMm)
                Assert.That(joint.Value.InvalidCount, Is.Zero, $"{what}: NaN or infinite {joint.Key} errors");
            Assert.That(double.IsNaN(r.AllJointsMm.Mean), Is.False, $"{what}: MPJPE");
            Assert.That(r.EndEffectorMm.Median, Is.LessThanOrEqualTo(EndEffectorMedianMm), $"{what}: end-effector median (mm)");
        }

        // --- Spine joints that are no humanoid bone (UE5's spine_02, neck_02) ----------------------------------------------

        /// <summary>
        /// A joint on the way from the hips to the head that is no humanoid bone, and that turns in the motion as a vertebra
        /// would (MocapBank with a joint inserted halfway between Chest2 and Neck, its rotation halfway between theirs, and
        /// one between Chest and Chest2, which takes the Chest bone), stands up in the T-pose like the spine bones around it.
        /// Kept in its reference rotation (the wearer's first frame, the avatar's rest) it bent the two T-poses differently,
        /// and the hands and head sat up to 11 mm off (end effectors p95 10.8 mm against the original's 3.9); now 3.9.
        /// </summary>
        [Test]
        public void SpineJointsThatAreNoHumanoidBoneStandUpInTheTPose()
        {
            BvhClip clip = Read(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip vertebrae = AsFile(Topology.WithJointsAbove(clip, true, ("Chest2", "ChestMid", 0.5f), ("Neck", "ChestTop", 0.5f)), "vertebrae");
            HumanoidMap b = HumanoidNaming.Detect(vertebrae.Skeleton);
            Assert.That(b.BoneOf(vertebrae.Skeleton.IndexOf("ChestTop")), Is.EqualTo(HumanoidBone.LastBone), "the joint below the neck is no humanoid bone");
            AssertWorldPosesKept(clip, vertebrae, false, "vertebrae");
            EvaluationReport own = Original(TestData.Mocap("mocapbank_30fps.bvh"), 1), other = Evaluate(vertebrae, 1);
            TestContext.WriteLine($"with vertebrae: {Figures(other)} (original {Figures(own)})");
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), "end-effector median (mm)");
            Assert.That(other.EndEffectorMm.P95, Is.EqualTo(own.EndEffectorMm.P95).Within(0.3), "end-effector p95 (mm)");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(1.5), "MPJPE (mm)");
        }

        // --- A joint between the clavicle and the upper arm (MakeHuman's shoulder01) ---------------------------------------

        /// <summary>
        /// A joint between the clavicle and the upper arm that is no humanoid bone (MakeHuman's default rig has
        /// clavicle.L, shoulder01.L, upperarm01.L) carries the arm from the clavicle, so a shrug moves the arm with it
        /// (MocapBank with a joint inserted halfway along each clavicle, every joint's world pose kept). Before, the arm was
        /// solved from where that joint had been before the shrug, then moved with it: hands off their controllers.
        /// </summary>
        [Test]
        public void AJointBetweenTheClavicleAndTheUpperArmMovesWithTheShrug()
        {
            string path = TestData.Mocap("mocapbank_30fps.bvh");
            BvhClip clip = Read(path);
            BvhClip girdle = AsFile(Topology.WithJointsAbove(clip, ("LeftShoulder", "LeftGirdle", 0.5f), ("RightShoulder", "RightGirdle", 0.5f)), "girdle");
            HumanoidMap map = HumanoidNaming.Detect(girdle.Skeleton);
            Assert.That(map.BoneOf(girdle.Skeleton.IndexOf("LeftGirdle")), Is.EqualTo(HumanoidBone.LastBone), "the inserted joint is no humanoid bone");
            Assert.That(map.NameOf(HumanoidBone.LeftShoulder), Is.EqualTo("LeftCollar"));
            Assert.That(map.NameOf(HumanoidBone.LeftUpperArm), Is.EqualTo("LeftShoulder"));
            AssertWorldPosesKept(clip, girdle, false, "girdle");
            EvaluationReport own = Original(path, 1), other = Evaluate(girdle, 1);
            TestContext.WriteLine($"with a joint along each clavicle: {Figures(other)} (original {Figures(own)})");
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), "end-effector median (mm)");
            Assert.That(other.EndEffectorMm.P95, Is.EqualTo(own.EndEffectorMm.P95).Within(0.1), "end-effector p95 (mm)");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.1), "MPJPE (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.5), "elbows and knees median (mm)");
            Assert.That(other.UnreachedHandFrames, Is.EqualTo(own.UnreachedHandFrames).Within(2), "frames with a hand out of reach");
        }

        // --- Thighs under the first spine joint (3ds Max Biped) ------------------------------------------------------------

        // The clip with a pair of bones (left, right) moved under the joint of another bone, every joint's world pose kept,
        // simulated and evaluated beside the original: the two reports, what the messages call it, and the moved clip.
        private static (EvaluationReport own, EvaluationReport other, string what, BvhClip moved) EvaluateMovedUnder(
            string path, int seed, HumanoidBone left, HumanoidBone right, HumanoidBone newParent, string description)
        {
            BvhClip clip = Read(path);
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            string parent = map.NameOf(newParent);
            BvhClip moved = AsFile(Topology.Reparented(clip, (map.NameOf(left), parent), (map.NameOf(right), parent)), description);
            AssertWorldPosesKept(clip, moved, false, description);
            AssertSameHumanoidJoints(clip, moved, description);
            EvaluationReport own = Original(path, seed), other = Evaluate(moved, seed);
            string what = $"{Path.GetFileName(path)} with its {description}, seed {seed}";
            TestContext.WriteLine($"{what}: {Figures(other)} (original {Figures(own)})");
            Assert.That(other.Profile, Is.Not.Null, $"{what}: calibration failed: {other.CalibrationMessage}");
            return (own, other, what, moved);
        }

        private static void AssertThighsUnderTheSpineKeepTheEndEffectors(string path, int seed, double endEffectorP95Mm, double mpjpeMarginMm = 7.0)
        {
            var (own, other, what, _) = EvaluateMovedUnder(path, seed, HumanoidBone.LeftUpperLeg, HumanoidBone.RightUpperLeg, HumanoidBone.Spine, "thighs under the first spine joint");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.3), $"{what}: end-effector median (mm)");
            Assert.That(other.EndEffectorMm.P95, Is.LessThanOrEqualTo(endEffectorP95Mm), $"{what}: end-effector p95 (mm)");
            Assert.That(other.AllJointsMm.Mean, Is.LessThanOrEqualTo(own.AllJointsMm.Mean + mpjpeMarginMm), $"{what}: MPJPE (mm)");
        }

        /// <summary>
        /// 3ds Max Biped hangs its thighs from its first spine bone. With the thighs moved under the first spine joint (every
        /// joint's world pose kept), the T-pose levels them from that joint, and the hips only stand the spine up: before,
        /// the hips levelled a hip line that the spine joint's turn, still to come, then moved, so the wearer's and the
        /// avatar's T-poses differed (their twists come from different references) and every end effector sat ~32 mm off
        /// (MocapBank seed 1: end effectors 32.2 / 34.0 mm median / p95, MPJPE 33.5 mm). Now 2.20 / 4.02 and 23.4 against the
        /// original's 2.18 / 3.90 and 17.6: the rest is the spine's bend, which now swings the thighs with it. Since the back
        /// flexes about the hip line with a stiffness (2026-12-02; the first spine joint takes the bend's share but no
        /// flexion, which would only swing the thighs): 2.06 / 3.84 and 24.3 against 2.03 / 3.83 and 17.75, so the MPJPE
        /// margin is 7 mm (was 6.5).
        /// </summary>
        [Test]
        public void ThighsUnderTheFirstSpineJointKeepTheEndEffectors() => AssertThighsUnderTheSpineKeepTheEndEffectors(TestData.Mocap("mocapbank_30fps.bvh"), 1, 5.0);

        // --- Clavicles under the neck (3ds Max Biped) -------------------------------------------------------------------

        private static void AssertClaviclesUnderTheNeckChangeLittle(string path, int seed, double mpjpeMm = 1.2, double midMm = 1.5)
        {
            var (own, other, what, moved) = EvaluateMovedUnder(path, seed, HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder, HumanoidBone.Neck, "clavicles under the neck");
            HumanoidMap b = HumanoidNaming.Detect(moved.Skeleton);
            Assert.That(moved.Skeleton.GetParent(b[HumanoidBone.LeftShoulder]), Is.EqualTo(b[HumanoidBone.Neck]), "the clavicles hang from the neck");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(mpjpeMm), $"{what}: MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.05), $"{what}: end-effector median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(midMm), $"{what}: elbows' and knees' median (mm)");
        }

        /// <summary>
        /// 3ds Max Biped hangs its clavicles from its Neck bone. The same motion with the clavicles moved under the neck, every
        /// joint's world pose kept, gives nearly the original's avatar: the neck follows the head as on any rig
        /// (<see cref="FullBodyIk.NeckFollowsHead"/>) and the clavicles are held in the frame of the joint below it, as they
        /// are on a rig whose clavicles hang from the chest, so a nod no longer swings the shoulders (their roots still ride
        /// on the neck). MocapBank seed 1: MPJPE 17.56 mm against the original's 17.57 and elbows and knees median 43.1
        /// against 42.9; before, 18.33 and 48.3. In the slow suite every shared clip, within 1.2 mm (Mixamo: 10.86 against
        /// 9.88, before 11.01; Rigify 15.29 against 15.27, before 16.21).
        /// </summary>
        [Test]
        public void ClaviclesUnderTheNeckGiveNearlyTheSameAvatar() => AssertClaviclesUnderTheNeckChangeLittle(TestData.Mocap("mocapbank_30fps.bvh"), 1, 0.25, 0.5);

        [TestCase("clavicles"), TestCase("neck"), TestCase("upper spine")]
        public void DroppedOptionalBonesStillCalibrateAndFollow(string which) => AssertDroppedBonesStillWork(TestData.Mocap("mocapbank_30fps.bvh"), which, 1);

        /// <summary>
        /// A rig without clavicles: the spine joint that carries the upper arms is levelled across them (<see cref="TPoser"/>),
        /// so the rest convention changes nothing and the wearer's and avatar's T-poses agree. Before, that joint's twist came
        /// from the reference pose (the wearer's first frame, the avatar's rest): MocapBank without clavicles put the hands
        /// 16 mm off their controllers (end effectors p95 17.3 mm) and gave MPJPE 19.8 / 23.9 / 97.3 mm in its own rest,
        /// rebased along X with 37° of twist, and with random axes.
        /// </summary>
        [Test]
        public void ARigWithoutClaviclesGivesTheSameAvatarInEveryRestConvention()
        {
            BvhClip clip = Read(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip without = AsFile(Topology.Without(clip, Optional(HumanoidNaming.Detect(clip.Skeleton), "clavicles")), "without clavicles");
            EvaluationReport own = Evaluate(without, 1);
            Assert.That(own.EndEffectorMm.P95, Is.LessThanOrEqualTo(10.0), "issue 10's end-effector p95 (mm): the hands on their controllers");
            AssertSame(own, Evaluate(BvhRebaser.AlongX(without, 37f), 1), "without clavicles, along X with 37° of twist");
            AssertSame(own, Evaluate(BvhRebaser.RandomAxes(without, 1), 1), "without clavicles, random axes (seed 1)");
        }

        // --- Slow: every shared clip --------------------------------------------------------------------------------

        private static readonly string[] SharedClipFiles = { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps.bvh" };

        private static IEnumerable<TestCaseData> SharedClips()
        {
            foreach (string clip in SharedClipFiles) yield return new TestCaseData(clip).SetName($"TopologyVariants {clip}");
        }

        [TestCaseSource(nameof(SharedClips)), Category("Slow")]
        public void EverySharedClipGivesTheSameAvatarOnEveryVariant(string file)
        {
            string path = TestData.SharedMocap(file);
            AssertTwistJointsChangeNothing(path, 1);
            AssertFloorRootChangesNothing(path, 1);
            for (int seed = 1; seed <= 3; seed++)
            {
                AssertTwistJointsChangeNothing(path, seed, false);
                AssertFloorRootChangesNothing(path, seed, false);
                AssertMirrorGivesMirroredAvatar(path, seed);
            }
            foreach (string which in Dropped) AssertDroppedBonesStillWork(path, which, 1);
            AssertClaviclesUnderTheNeckChangeLittle(path, 1);
            // Rigify's legs, near full stretch, miss their feet when the bend lifts the thighs: measured p95 11.6 mm. Its
            // original now stands its hips up by the spine (15.3 -> 13.1 mm), which the hips of this variant, standing only
            // the spine up, do not (20.4 mm before and after): 7.5 mm apart.
            AssertThighsUnderTheSpineKeepTheEndEffectors(path, 1, 15.0, file.StartsWith("rigify", StringComparison.Ordinal) ? 7.5 : 7.0);
        }
    }
}
