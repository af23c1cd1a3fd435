using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// <see cref="FullBodyIk"/> against real motion: each frame of a mocap clip gives the true world poses; the
    /// targets are built from them (hips, head, ankles and wrists as goals, true knees and elbows as hints, the
    /// spine bend as the body solver computes it), the IK poses the same skeleton, and the result is compared with
    /// the truth joint by joint.
    /// </summary>
    public class FullBodyIkTests
    {
        internal sealed class Truth
        {
            public BvhClip Clip;
            public HumanoidMap Map;
            public RigidPose[] Local, World;
            public Vector3 RestRootToHead;
            public Quaternion RestHipsRotation;

            public Truth(string clipName) : this(BvhReader.ReadFile(TestData.Mocap(clipName), new BvhReadOptions { ToMetres = true })) { }

            public Truth(BvhClip clip)
            {
                Clip = clip;
                Map = HumanoidNaming.Detect(Clip.Skeleton);
                Local = new RigidPose[Clip.Skeleton.JointCount];
                World = new RigidPose[Clip.Skeleton.JointCount];
                var rest = new SkeletonPose(Clip.Skeleton);
                RestRootToHead = rest.World[Map[HumanoidBone.Head]].Position - rest.World[Map[HumanoidBone.Hips]].Position;
                RestHipsRotation = rest.World[Map[HumanoidBone.Hips]].Rotation;
            }

            public int this[HumanoidBone b] => Map[b];

            /// <summary>Loads frame <paramref name="frame"/>'s truth and fills the targets from it.</summary>
            public void Targets(int frame, ref BodyTargets t)
            {
                Clip.GetWorldPoses(frame, Local, World);
                RigidPose hips = World[Map[HumanoidBone.Hips]], head = World[Map[HumanoidBone.Head]];
                t.Hips = hips;
                t.HipsActive = true;
                t.Head = head;
                t.HeadActive = true;
                // The paper's α: from the rest root-to-head vector turned with the root, to the current one.
                Vector3 w0 = Vector3.Transform(RestRootToHead, hips.Rotation * Quaternion.Inverse(RestHipsRotation));
                t.SpineBend = Rotations.FromTo(w0, head.Position - hips.Position);
                t.LeftFoot = new LimbTarget(World[Map[HumanoidBone.LeftFoot]], World[Map[HumanoidBone.LeftLowerLeg]].Position);
                t.RightFoot = new LimbTarget(World[Map[HumanoidBone.RightFoot]], World[Map[HumanoidBone.RightLowerLeg]].Position);
                t.LeftHand = new LimbTarget(World[Map[HumanoidBone.LeftHand]], World[Map[HumanoidBone.LeftLowerArm]].Position);
                t.RightHand = new LimbTarget(World[Map[HumanoidBone.RightHand]], World[Map[HumanoidBone.RightLowerArm]].Position);
            }
        }

        private static float Median(float[] values)
        {
            var copy = (float[])values.Clone();
            Array.Sort(copy);
            return copy[copy.Length / 2];
        }

        private static float Error(SkeletonPose pose, Truth truth, HumanoidBone bone) =>
            Vector3.Distance(pose.World[truth[bone]].Position, truth.World[truth[bone]].Position);

        /// <summary>
        /// The whole body from true targets, every frame solved from the rest pose. Hips and head are set, the legs
        /// hang from the exact hips: all of these must be exact to float rounding (1 mm is the bound, 0.1 mm
        /// what the analytic solve gives). The chest, clavicles and so the shoulders are not given by the targets (six
        /// devices do not observe them): the spine takes the paper's even bend, so wrists are reached when the arm
        /// can reach from where the shoulder ends up (reported otherwise), and elbows are off by the shoulder's error.
        /// The bounds on those are measured values with a margin (2026-12-02, frames solved from rest, the back flexed about
        /// the hip line until the head is on its target: mocapbank elbow error median 21.6 mm, max 62.8 mm, no unreached
        /// hand, head over 1 mm from its target in 11 of 455 frames; mixamo 45.5 mm / 67.1 mm / 0 of 69 / 0. Before, when
        /// the back bent about the bend's own axis: 37.6 / 71.5 mm, 101 of 455 unreached, 27 over 1 mm; 46.7 / 67.9 mm,
        /// 45 of 69, 0).
        /// Rigify is not used: its joints carry per-frame position channels, so its bones change length and no
        /// rotation-only IK on the rest skeleton can match it (see LimbsFromTrueShouldersMatchTheTruth).
        /// </summary>
        [TestCase("mocapbank_30fps.bvh", 30f, 0.05f, 0.04f)]
        [TestCase("mixamo_fingers_30fps.bvh", 52f, 0.10f, 0.02f)]
        public void TrueTargetsGiveTheTrueBody(string clipName, float elbowMedianMm, float unreachedShare, float headMissShare)
        {
            var truth = new Truth(clipName);
            var ik = new FullBodyIk(truth.Map) { ChordNoiseMetres = 0f }; // noise-free targets: the back flexes until the head is on its target
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var targets = new BodyTargets();
            int frames = truth.Clip.FrameCount, unreached = 0, headMissed = 0;
            var elbows = new float[frames];
            for (int f = 0; f < frames; f++)
            {
                truth.Targets(f, ref targets);
                pose.ResetToRest();
                IkReport r = ik.Solve(in targets, pose);
                string at = $"{clipName} frame {f}";
                Approx.Near(targets.Hips, pose.World[truth[HumanoidBone.Hips]], 1e-5f, 0.01f, at + " hips");
                Approx.Near(targets.Head.Rotation, pose.World[truth[HumanoidBone.Head]].Rotation, 0.01f, at + " head rotation");
                float head = Error(pose, truth, HumanoidBone.Head);
                Assert.That(r.HeadDistanceLeft, Is.EqualTo(head).Within(1e-5f), at + " reported head distance");
                if (head > 0.001f) headMissed++;
                Assert.That(head, Is.LessThan(0.01f), at + " head (m)");
                foreach (HumanoidBone b in new[] { HumanoidBone.LeftFoot, HumanoidBone.RightFoot, HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg })
                    Assert.That(Error(pose, truth, b), Is.LessThan(1e-4f), $"{at} {b} (m)");
                Approx.Near(targets.LeftFoot.Goal.Rotation, pose.World[truth[HumanoidBone.LeftFoot]].Rotation, 0.01f, at + " left foot rotation");
                // A reached hand is on its goal (within the 1 mm tolerance); an unreached one says so with the true distance.
                foreach (var (bone, result) in new[] { (HumanoidBone.LeftHand, r.LeftHand), (HumanoidBone.RightHand, r.RightHand) })
                {
                    float e = Error(pose, truth, bone);
                    Assert.That(result.DistanceLeft, Is.EqualTo(e).Within(1e-5f), $"{at} {bone} reported distance");
                    Assert.That(result.Reached, Is.EqualTo(e <= TwoBoneIk.ReachedTolerance), $"{at} {bone} reached flag");
                }
                if (!r.LeftHand.Reached || !r.RightHand.Reached) unreached++;
                Assert.That(r.LeftFoot.Reached && r.RightFoot.Reached, Is.True, at + " feet");
                elbows[f] = 0.5f * (Error(pose, truth, HumanoidBone.LeftLowerArm) + Error(pose, truth, HumanoidBone.RightLowerArm));
            }
            TestContext.WriteLine($"{clipName}: head over 1 mm {headMissed}/{frames}, unreached {unreached}, elbow median {Median(elbows) * 1000f} max {elbows.Max() * 1000f}");
            // The head: within 1 mm in nearly all frames (the rest are poses the even bend plus polishing leaves a
            // few mm short, never 10 mm: asserted per frame above).
            Assert.That(headMissed, Is.LessThanOrEqualTo((int)(headMissShare * frames)), "frames with the head over 1 mm from its target");
            Assert.That(unreached, Is.LessThanOrEqualTo((int)(unreachedShare * frames)), "frames with an unreached hand");
            Assert.That(Median(elbows) * 1000f, Is.LessThan(elbowMedianMm), "elbow error median (mm)");
        }

        /// <summary>
        /// The limbs alone on real motion: the body above each limb is the truth (so the shoulders and hips are the
        /// true ones), the limb starts from its rest pose, and TwoBoneIk with the true wrist/ankle as goal and the true
        /// elbow/knee as hint must give back the true limb. The middle joint is determined exactly by the plane of the
        /// hint and the two bone lengths, so 0.1 mm (float rounding plus the solver's 0.01 mm stretch margin for the
        /// nearly straight legs) is the bound. Rigify is included: the limb's lengths are taken from the current pose.
        /// </summary>
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        [TestCase("rigify_6channel_24fps_first240.bvh")]
        public void LimbsFromTrueShouldersMatchTheTruth(string clipName)
        {
            var truth = new Truth(clipName);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            Skeleton s = truth.Clip.Skeleton;
            var limbs = new[]
            {
                (HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot),
                (HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot),
                (HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand),
                (HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, HumanoidBone.RightHand),
            };
            var chains = new LimbChain[limbs.Length];
            for (int i = 0; i < limbs.Length; i++) chains[i] = new LimbChain(s, truth[limbs[i].Item1], truth[limbs[i].Item2], truth[limbs[i].Item3]);
            var unused = new BodyTargets();
            int step = Math.Max(1, truth.Clip.FrameCount / 400);
            for (int f = 0; f < truth.Clip.FrameCount; f += step)
            {
                truth.Targets(f, ref unused);
                Array.Copy(truth.Local, pose.Local, pose.Local.Length);
                foreach (LimbChain c in chains)
                    foreach (int j in c.Path) pose.Local[j] = pose.Local[j].WithRotation(s.GetRestLocal(j).Rotation);
                pose.UpdateWorld();
                for (int i = 0; i < limbs.Length; i++)
                {
                    var (root, middle, end) = limbs[i];
                    LimbResult r = TwoBoneIk.Solve(pose, chains[i], truth.World[truth[end]], truth.World[truth[middle]].Position);
                    string at = $"{clipName} frame {f}";
                    Assert.That(r.Reached, Is.True, $"{at} {end}");
                    Approx.Near(truth.World[truth[end]], pose.World[truth[end]], 1e-4f, 0.01f, $"{at} {end}");
                    Approx.Near(truth.World[truth[middle]].Position, pose.World[truth[middle]].Position, 1e-4f, $"{at} {middle}");
                    Approx.Near(truth.World[truth[root]].Position, pose.World[truth[root]].Position, 1e-6f, $"{at} {root}");
                }
            }
        }

        [Test]
        public void InactivePartsKeepTheirPreviousPose()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var ik = new FullBodyIk(truth.Map);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var targets = new BodyTargets();
            truth.Targets(10, ref targets);
            ik.Solve(in targets, pose);
            var before = (RigidPose[])pose.Local.Clone();
            truth.Targets(200, ref targets);
            targets.HipsActive = false;
            targets.HeadActive = false;
            targets.LeftHand.IsActive = false;
            targets.RightFoot.IsActive = false;
            IkReport r = ik.Solve(in targets, pose);
            Assert.That(pose.Local[truth[HumanoidBone.Hips]], Is.EqualTo(before[truth[HumanoidBone.Hips]]), "hips");
            foreach (HumanoidBone b in new[] { HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.Neck, HumanoidBone.Head, HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand, HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot })
                if (truth.Map.Has(b)) Assert.That(pose.Local[truth[b]], Is.EqualTo(before[truth[b]]), b.ToString());
            // The active limbs still follow their goals from where the body was left.
            Assert.That(r.LeftFoot.Reached, Is.True);
            Approx.Near(targets.LeftFoot.Goal.Position, pose.World[truth[HumanoidBone.LeftFoot]].Position, 0.001f, "left foot");
        }

        /// <summary>
        /// The solve updates only the world poses it reads on the way (a handful of joints above the spine, legs and arms)
        /// and runs the whole skeleton's forward kinematics once, at the end. So what a pose's world transforms held on
        /// entry must never matter: a pose whose world transforms are overwritten with NaN before every frame is solved to
        /// exactly the same local and world transforms as one whose world transforms are the last frame's, on rigs with
        /// joints between the humanoid bones (a floor-level root above the hips, a joint below the spine's first bone and
        /// above each clavicle, twist joints), with clavicles hanging from the neck and with none, with the thighs hanging
        /// from the spine through joints of their own, over 120 frames with the shrugs held. And every limb reported as
        /// reached ends within <see cref="TwoBoneIk.ReachedTolerance"/> of its goal in the pose returned (a limb solved from
        /// world poses of its parents older than the spine's solve would be moved off it by the final update; found in review).
        /// The world poses returned are exactly the forward kinematics of the local ones (the final update skips the joints
        /// the solve has just posed, when it solved every part), also on frames that leave a part out.
        /// </summary>
        [TestCase("plain")]
        [TestCase("floor root")]
        [TestCase("joints between")]
        [TestCase("twist joints")]
        [TestCase("clavicles under the neck")]
        [TestCase("no clavicles")]
        [TestCase("legs under the spine")]
        public void EveryWorldPoseTheSolveReadsIsUpToDate(string rig)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            HumanoidMap original = HumanoidNaming.Detect(clip.Skeleton);
            string Name(HumanoidBone b) => clip.Skeleton.GetName(original[b]);
            clip = rig switch
            {
                "floor root" => Topology.WithFloorRoot(clip),
                "joints between" => Topology.WithJointsAbove(clip, (Name(HumanoidBone.Chest), "LowerBack", 0.3f),
                    (Name(HumanoidBone.LeftShoulder), "LeftGirdle", 0.5f), (Name(HumanoidBone.RightShoulder), "RightGirdle", 0.5f)),
                "twist joints" => Topology.WithTwistJoints(clip),
                "clavicles under the neck" => Topology.Reparented(clip, (Name(HumanoidBone.LeftShoulder), Name(HumanoidBone.Neck)),
                    (Name(HumanoidBone.RightShoulder), Name(HumanoidBone.Neck))),
                "no clavicles" => Topology.Without(clip, original[HumanoidBone.LeftShoulder], original[HumanoidBone.RightShoulder]),
                "legs under the spine" => Topology.WithJointsAbove(
                    Topology.Reparented(clip, (Name(HumanoidBone.LeftUpperLeg), Name(HumanoidBone.Spine)), (Name(HumanoidBone.RightUpperLeg), Name(HumanoidBone.Spine))),
                    (Name(HumanoidBone.LeftUpperLeg), "LeftPelvis", 0.5f), (Name(HumanoidBone.RightUpperLeg), "RightPelvis", 0.5f)),
                _ => clip,
            };
            var truth = new Truth(clip);
            var kept = new SkeletonPose(clip.Skeleton);
            var stale = new SkeletonPose(clip.Skeleton);
            var keptIk = new FullBodyIk(truth.Map);
            var staleIk = new FullBodyIk(truth.Map);
            var targets = new BodyTargets();
            var nan = new RigidPose(new Vector3(float.NaN), new Quaternion(float.NaN, float.NaN, float.NaN, float.NaN));
            var forward = new RigidPose[clip.Skeleton.JointCount];
            for (int f = 0; f < Math.Min(120, clip.FrameCount); f++)
            {
                truth.Targets(f * clip.FrameCount / 120, ref targets);
                // Every tenth frame leaves one part out in turn (the head, a foot, a hand).
                if (f % 10 == 5)
                    switch (f / 10 % 5)
                    {
                        case 0: targets.HeadActive = false; break;
                        case 1: targets.LeftFoot.IsActive = false; break;
                        case 2: targets.RightFoot.IsActive = false; break;
                        case 3: targets.LeftHand.IsActive = false; break;
                        default: targets.RightHand.IsActive = false; break;
                    }
                Array.Fill(stale.World, nan);
                IkReport report = keptIk.Solve(in targets, kept, 1f / 30f);
                staleIk.Solve(in targets, stale, 1f / 30f);
                foreach (var (limb, result, goal) in new[]
                {
                    (HumanoidBone.LeftFoot, report.LeftFoot, targets.LeftFoot.Goal), (HumanoidBone.RightFoot, report.RightFoot, targets.RightFoot.Goal),
                    (HumanoidBone.LeftHand, report.LeftHand, targets.LeftHand.Goal), (HumanoidBone.RightHand, report.RightHand, targets.RightHand.Goal),
                })
                    if (result.Reached)
                        Assert.That(Vector3.Distance(kept.World[truth[limb]].Position, goal.Position), Is.LessThanOrEqualTo(TwoBoneIk.ReachedTolerance),
                            $"{rig}, frame {f}: {limb} reported reached");
                clip.Skeleton.ComputeWorld(kept.Local, forward, kept.Origin);
                for (int j = 0; j < clip.Skeleton.JointCount; j++)
                {
                    string at = $"{rig}, frame {f}, {clip.Skeleton.GetName(j)}";
                    Assert.That(stale.Local[j], Is.EqualTo(kept.Local[j]), at + " local");
                    Assert.That(stale.World[j], Is.EqualTo(kept.World[j]), at + " world");
                    Assert.That(kept.World[j], Is.EqualTo(forward[j]), at + " world from the local poses");
                }
            }
        }

        /// <summary>
        /// The head swept sideways over the hips in 0.1 mm steps, 1 cm and 2 mm below the reference's hips-to-head reach and
        /// 1 cm above it (beyond the back's reach: 1.5 mm a step with the axis blended toward the hip line, the first fix
        /// a review tried), moves the chest continuously: at most 1 mm a step. The bend's own axis turns half a turn as the head passes over
        /// the hips, and the curve the shorter reach needs swung with it while the back flexed about that axis (now it
        /// flexes about the hip line) (found in review: 54.5 mm of chest in one 0.1 mm
        /// step 1 cm below, 23.6 mm 2 mm below; 1 mm of head noise about upright moved the chest 21.6 mm a frame, median).
        /// </summary>
        [TestCase(0.01f)]
        [TestCase(0.002f)]
        [TestCase(-0.01f)]
        public void TheChestMovesContinuouslyAsTheHeadPassesOverTheHips(float belowReference)
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var ik = new FullBodyIk(truth.Map);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var rest = new SkeletonPose(truth.Clip.Skeleton);
            int head = truth[HumanoidBone.Head], chest = truth[HumanoidBone.Chest];
            RigidPose hips = rest.World[truth[HumanoidBone.Hips]];
            Vector3 w0 = rest.World[head].Position - hips.Position;
            Vector3 up = Vector3.Normalize(w0), side = Vector3.Normalize(Vector3.Cross(up, Vector3.UnitZ));
            Vector3 previous = default;
            float largest = 0f;
            for (int i = -100; i <= 100; i++)
            {
                Vector3 headTarget = hips.Position + w0 - up * belowReference + side * (i * 1e-4f);
                var targets = new BodyTargets
                {
                    Hips = hips, HipsActive = true, Head = new RigidPose(headTarget, rest.World[head].Rotation), HeadActive = true,
                    SpineBend = Rotations.FromTo(w0, headTarget - hips.Position),
                };
                ik.Solve(in targets, pose);
                // (a stiff back leaves the head up to about the chord noise short of a nearer target)
                if (belowReference > 0f) // (above the reach, the head stops short of its target)
                    Assert.That(Vector3.Distance(pose.World[head].Position, headTarget), Is.LessThan(FullBodyIk.DefaultChordNoiseMetres + 5e-4f), $"head at step {i}");
                if (i > -100) largest = Math.Max(largest, Vector3.Distance(pose.World[chest].Position, previous));
                previous = pose.World[chest].Position;
            }
            Assert.That(largest * 1000f, Is.LessThan(1f), "the chest's largest step (mm) for 0.1 mm steps of the head");
        }

        /// <summary>
        /// A slouched back: the head 1 and 2 cm nearer the first spine joint than in the calibration T-pose, swept over the hips
        /// from 3 cm in front of the calibration's line to 3 cm behind it in 0.1 mm steps (an arc about the first spine joint),
        /// on each shared skeleton with the default stiffness. The back must stay curled forward (the chest behind the line from
        /// the first spine joint to the head) and the chest move at most 1 mm a step. Found in review: the back flexes about the
        /// hip line, forward or backward as the solve's start leads it (the chord is even in φ about a straight back), and the
        /// start was 0.001 rad forward of the calibration's back: once the head was 2–3 mm behind the hips the bend's share
        /// arched the back by more than that, and the back flipped from curled to arched, the chest 14–98 mm in one 0.1 mm step
        /// (standing still that slouched, 1 mm of device noise flipped it back and forth: the chest 70–140 mm a frame at p95).
        /// </summary>
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        [TestCase("rigify_6channel_24fps_first240.bvh")]
        public void ASlouchedBackStaysCurledAsTheHeadPassesOverTheHips(string clipName)
        {
            var truth = new Truth(clipName);
            var calibration = new SkeletonPose(truth.Clip.Skeleton);
            TPoser.Apply(truth.Map, calibration, RigidPose.Identity);
            RigidPose[] t = calibration.World;
            RigidPose hips = t[truth[HumanoidBone.Hips]], head = t[truth[HumanoidBone.Head]];
            Vector3 first = t[truth[HumanoidBone.Spine]].Position;
            int chest = truth.Map.Has(HumanoidBone.UpperChest) ? truth[HumanoidBone.UpperChest] : truth[HumanoidBone.Chest];
            Vector3 toHead = head.Position - first, up = Vector3.Normalize(toHead);
            Vector3 right = Vector3.Normalize(t[truth[HumanoidBone.RightUpperLeg]].Position - t[truth[HumanoidBone.LeftUpperLeg]].Position);
            Vector3 forward = Vector3.Normalize(Vector3.Cross(right, up));
            var ik = new FullBodyIk(truth.Map, calibration);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            foreach (float nearer in new[] { 0.01f, 0.02f })
            {
                float reach = toHead.Length() - nearer, largest = 0f;
                Vector3 previous = default;
                for (int i = -300; i <= 300; i++)
                {
                    float angle = i * 1e-4f / reach; // 0.1 mm of arc a step, +-3 cm
                    Vector3 headTarget = first + reach * (up * MathF.Cos(angle) + forward * MathF.Sin(angle));
                    var targets = new BodyTargets
                    {
                        Hips = hips, HipsActive = true, Head = new RigidPose(headTarget, head.Rotation), HeadActive = true,
                        SpineBend = Rotations.FromTo(head.Position - hips.Position, headTarget - hips.Position),
                    };
                    ik.Solve(in targets, pose);
                    Vector3 c = pose.World[chest].Position, line = Vector3.Normalize(headTarget - first), off = c - first;
                    off -= line * Vector3.Dot(off, line);
                    Assert.That(Vector3.Dot(off, forward), Is.LessThan(0f), $"{clipName}, {nearer * 100} cm nearer, head {i * 0.1f} mm ahead: the chest behind the line (curled)");
                    if (i > -300) largest = Math.Max(largest, Vector3.Distance(c, previous));
                    previous = c;
                }
                TestContext.WriteLine($"{clipName}, {nearer * 100} cm nearer: the chest's largest step {largest * 1000f:F2} mm");
                Assert.That(largest * 1000f, Is.LessThan(1f), $"{clipName}, {nearer * 100} cm nearer: the chest's largest step (mm) for 0.1 mm steps of the head");
            }
        }

        /// <summary>
        /// A reference pose (the calibration T-pose the spine is bent from) with a joint that is not a pose (a rotation that is
        /// not finite or not of unit length, a position that is not finite: <see cref="RigidPose.IsValid"/>) is refused when
        /// the solver is built, naming the joint. Found in review: it was taken as it was, and every frame came out with NaN
        /// bones (14 of MocapBank's 24 joints for a zero or NaN rotation of its hips or chest: a zero hips rotation made the
        /// hip line the back flexes about NaN; 5, the arm's, for such a clavicle); a rotation of length 2 stretched every bone
        /// below it fourfold.
        /// </summary>
        [Test]
        public void AReferencePoseThatIsNotAPoseIsRefused()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            foreach (HumanoidBone bone in new[] { HumanoidBone.Hips, HumanoidBone.Chest, HumanoidBone.LeftShoulder })
            foreach (RigidPose bad in new[]
            {
                new RigidPose(Vector3.Zero, default), new RigidPose(Vector3.Zero, new Quaternion(float.NaN, 0f, 0f, 1f)),
                new RigidPose(new Vector3(float.PositiveInfinity, 0f, 0f), Quaternion.Identity), new RigidPose(Vector3.Zero, new Quaternion(0f, 0f, 0f, 2f)),
            })
            {
                var reference = new SkeletonPose(truth.Clip.Skeleton);
                RigidPose rest = reference.Local[truth[bone]];
                reference.Local[truth[bone]] = new RigidPose(rest.Position + bad.Position, bad.Rotation);
                var e = Assert.Throws<ArgumentException>(() => new FullBodyIk(truth.Map, reference), $"{bone}: {bad}");
                StringAssert.Contains(truth.Clip.Skeleton.GetName(truth[bone]), e.Message, "the joint is named");
            }
        }

        private static void SolveAll(FullBodyIk ik, BodyTargets[] frames, SkeletonPose pose, int passes)
        {
            for (int pass = 0; pass < passes; pass++)
                for (int f = 0; f < frames.Length; f++) ik.Solve(in frames[f], pose);
        }

        [Test]
        public void SolveAllocatesNothing()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var ik = new FullBodyIk(truth.Map);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var frames = new BodyTargets[truth.Clip.FrameCount];
            for (int f = 0; f < frames.Length; f++) truth.Targets(f, ref frames[f]);
            for (int f = 0; f < frames.Length; f++) ik.Solve(in frames[f], pose);
            // Warm up long enough for .NET's tiered compilation to settle: it starts counting calls only after
            // 100 ms without new compilations, and the thread whose call reaches the count queues the optimised
            // recompilation, a one-off 24-byte allocation that is the runtime's, not the solver's.
            var warm = System.Diagnostics.Stopwatch.StartNew();
            do { SolveAll(ik, frames, pose, 2); System.Threading.Thread.Sleep(5); } while (warm.ElapsedMilliseconds < 600);
            // Measured in windows inside a loop, each window five passes over the clip. (A single window in
            // straight-line code right before the assertion reads 24 bytes more even though every one of its Solve
            // calls measured alone reads 0: the runtime's, not the solver's.)
            var bytes = new long[4];
            for (int k = 0; k < bytes.Length; k++)
            {
                long t0 = GC.GetAllocatedBytesForCurrentThread();
                SolveAll(ik, frames, pose, 5);
                bytes[k] = GC.GetAllocatedBytesForCurrentThread() - t0;
            }
            Assert.That(bytes, Is.EqualTo(new long[bytes.Length]), "bytes allocated per window of 5 x 455 solves");
        }

        // Frame 0 of mocapbank at its true targets, solved as a single frame: the clavicle at its reference, so the shoulder is
        // where it starts.
        private static (FullBodyIk ik, SkeletonPose pose, BodyTargets targets, Truth truth) FirstFrameSolved()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var ik = new FullBodyIk(truth.Map);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var targets = new BodyTargets();
            truth.Targets(0, ref targets);
            ik.Solve(in targets, pose);
            return (ik, pose, targets, truth);
        }

        // The left arm's length, shoulder to elbow to wrist, in the pose (m).
        private static float LeftArmLength(SkeletonPose pose, Truth truth) =>
            Vector3.Distance(pose.World[truth[HumanoidBone.LeftUpperArm]].Position, pose.World[truth[HumanoidBone.LeftLowerArm]].Position)
            + Vector3.Distance(pose.World[truth[HumanoidBone.LeftLowerArm]].Position, pose.World[truth[HumanoidBone.LeftHand]].Position);

        // Frame 0 of mocapbank with the left hand's goal straight below its (unshrugged) shoulder, `beyond` metres farther
        // than the arm reaches; the other parts at their true targets.
        private static (FullBodyIk ik, SkeletonPose pose, BodyTargets targets, Truth truth) HangingArm(float beyond)
        {
            var (ik, pose, targets, truth) = FirstFrameSolved();
            Vector3 shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position;
            float arm = LeftArmLength(pose, truth);
            targets.LeftHand = new LimbTarget(new RigidPose(shoulder - Vector3.UnitY * (arm + beyond), targets.LeftHand.Goal.Rotation),
                shoulder - Vector3.UnitY * (arm * 0.5f) - Vector3.UnitZ * 0.1f);
            return (ik, pose, targets, truth);
        }

        private static float ClavicleTurnDegrees(SkeletonPose pose, Truth truth)
        {
            int clavicle = truth[HumanoidBone.LeftShoulder];
            return Rotations.AngleDegrees(truth.Clip.Skeleton.GetRestLocal(clavicle).Rotation, pose.Local[clavicle].Rotation);
        }

        /// <summary>
        /// A hand 2 cm beyond its arm's reach, straight below the shoulder, is reached by turning the clavicle down by the
        /// least angle that does it (the arm's full reach then ends on the goal), in a single frame, well within the 20° a
        /// shoulder shrugs; 40 cm beyond, the clavicle turns its 20° and the hand is reported out of reach by what is left.
        /// </summary>
        [Test]
        public void AClavicleShrugsJustEnoughToReachTheHand()
        {
            var (ik, pose, targets, truth) = HangingArm(0.02f);
            IkReport r = ik.Solve(in targets, pose);
            Assert.That(r.LeftHand.Reached, Is.True, $"reached ({r.LeftHand.DistanceLeft * 1000:F2} mm left)");
            float turn = ClavicleTurnDegrees(pose, truth);
            Vector3 shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position, pivot = pose.World[truth[HumanoidBone.LeftShoulder]].Position;
            float clavicle = Vector3.Distance(shoulder, pivot);
            TestContext.WriteLine($"2 cm beyond: clavicle turned {turn:F2} deg ({clavicle * 1000:F0} mm long)");
            // Lowering the shoulder by 2 cm on a clavicle of length c lying about level takes about asin(0.02 / c).
            Assert.That(turn, Is.GreaterThan(0.5f * (float)(Math.Asin(0.02 / clavicle) * 180 / Math.PI)).And.LessThan(20f), "the least turn, not the largest");
            float reach = Vector3.Distance(shoulder, targets.LeftHand.Goal.Position);
            float arm = LeftArmLength(pose, truth);
            Assert.That(reach, Is.EqualTo(arm).Within(0.001f), "the goal at the arm's full reach from the shrugged shoulder (m)");

            (ik, pose, targets, truth) = HangingArm(0.40f);
            r = ik.Solve(in targets, pose);
            Assert.That(r.LeftHand.Reached, Is.False, "40 cm beyond");
            Assert.That(ClavicleTurnDegrees(pose, truth), Is.EqualTo(20f).Within(0.05f), "the shrug at its limit");
            Assert.That(r.LeftHand.DistanceLeft, Is.GreaterThan(0.3f), "and the rest reported");
        }

        /// <summary>
        /// A shrug that reached the hand is held: with the hand then 10 cm within reach, the clavicle eases back to its
        /// reference with the time constant <see cref="FullBodyIk.DefaultShrugReleaseSeconds"/> (after 3 s, e^-1 of the
        /// shrug is left), the same at 30 and 120 Hz, and over the time a hand is lost. A single-frame solve holds nothing
        /// and starts from nothing held, a shrug that could not reach is not held, and 0 s holds none.
        /// </summary>
        [Test]
        public void AShrugThatReachedIsHeldAndReleasedOverSeconds()
        {
            foreach (int rate in new[] { 30, 120 })
            {
                var (ik, pose, targets, truth) = HangingArm(0.02f);
                float dt = 1f / rate;
                ik.Solve(in targets, pose, dt);
                float shrug = ClavicleTurnDegrees(pose, truth);
                BodyTargets within = targets;
                Vector3 shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position;
                within.LeftHand.Goal = new RigidPose(Vector3.Lerp(targets.LeftHand.Goal.Position, shoulder, 0.25f), targets.LeftHand.Goal.Rotation);
                for (int i = 0; i < 3 * rate; i++) ik.Solve(in within, pose, dt);
                float left = ClavicleTurnDegrees(pose, truth);
                TestContext.WriteLine($"{rate} Hz: shrug {shrug:F2} deg, after 3 s {left:F2} deg ({left / shrug:F3} of it)");
                Assert.That(left / shrug, Is.EqualTo((float)Math.Exp(-1)).Within(0.01f), $"{rate} Hz: e^-1 of the shrug left after 3 s");
            }

            var (ik1, pose1, targets1, truth1) = HangingArm(0.02f);
            ik1.Solve(in targets1, pose1); // single frame
            BodyTargets reachable = targets1;
            reachable.LeftHand.Goal = new RigidPose(targets1.LeftHand.Goal.Position + Vector3.UnitY * 0.1f, targets1.LeftHand.Goal.Rotation);
            ik1.Solve(in reachable, pose1, 1f / 90);
            Assert.That(ClavicleTurnDegrees(pose1, truth1), Is.LessThan(1e-3f), "a single-frame solve holds nothing");
            ik1.Solve(in targets1, pose1, 1f / 90); // held now
            ik1.Solve(in reachable, pose1);
            Assert.That(ClavicleTurnDegrees(pose1, truth1), Is.LessThan(1e-3f), "nor starts from what other frames held");

            // A hand lost for 3 s: its held shrug is released over that time too, not kept for its return.
            var (ikLost, poseLost, targetsLost, truthLost) = HangingArm(0.02f);
            ikLost.Solve(in targetsLost, poseLost, 1f / 90);
            float held = ClavicleTurnDegrees(poseLost, truthLost);
            BodyTargets lost = targetsLost;
            lost.LeftHand.IsActive = false;
            for (int i = 0; i < 270; i++) ikLost.Solve(in lost, poseLost, 1f / 90);
            Assert.That(ClavicleTurnDegrees(poseLost, truthLost), Is.EqualTo(held).Within(1e-3f), "the lost hand's arm keeps its pose");
            BodyTargets back = targetsLost;
            back.LeftHand.Goal = new RigidPose(Vector3.Lerp(targetsLost.LeftHand.Goal.Position, poseLost.World[truthLost[HumanoidBone.LeftUpperArm]].Position, 0.25f), targetsLost.LeftHand.Goal.Rotation);
            ikLost.Solve(in back, poseLost, 1f / 90);
            Assert.That(ClavicleTurnDegrees(poseLost, truthLost) / held, Is.EqualTo((float)Math.Exp(-271.0 / 270)).Within(0.01f), "released over the 3 s it was lost");

            var (ik2, pose2, targets2, truth2) = HangingArm(0.40f);
            ik2.Solve(in targets2, pose2, 1f / 90);
            reachable = targets2;
            reachable.LeftHand.Goal = new RigidPose(targets2.LeftHand.Goal.Position + Vector3.UnitY * 0.5f, targets2.LeftHand.Goal.Rotation);
            ik2.Solve(in reachable, pose2, 1f / 90);
            Assert.That(ClavicleTurnDegrees(pose2, truth2), Is.LessThan(1e-3f), "a shrug that could not reach is not held");

            var (ik3, pose3, targets3, truth3) = HangingArm(0.02f);
            ik3.ShrugReleaseSeconds = 0f;
            ik3.Solve(in targets3, pose3, 1f / 90);
            reachable = targets3;
            reachable.LeftHand.Goal = new RigidPose(targets3.LeftHand.Goal.Position + Vector3.UnitY * 0.1f, targets3.LeftHand.Goal.Rotation);
            ik3.Solve(in reachable, pose3, 1f / 90);
            Assert.That(ClavicleTurnDegrees(pose3, truth3), Is.LessThan(1e-3f), "0 s holds none");

            Assert.Throws<ArgumentOutOfRangeException>(() => ik3.ShrugReleaseSeconds = -1f);
            Assert.Throws<ArgumentOutOfRangeException>(() => ik3.ShrugReleaseSeconds = float.NaN);
            Assert.Throws<ArgumentOutOfRangeException>(() => new PipelineSettings().ShrugReleaseSeconds = float.PositiveInfinity);
        }

        /// <summary>
        /// The solver's tuning setters refuse a negative, NaN or infinite value with the setting's name as ParamName and in
        /// the message (found in review: ParamName "value", as PipelineSettings' had), and keep the value they had.
        /// </summary>
        [TestCase(nameof(FullBodyIk.ChordNoiseMetres)), TestCase(nameof(FullBodyIk.ChordCutoffHz)), TestCase(nameof(FullBodyIk.StraightLegCutoffHz)),
         TestCase(nameof(FullBodyIk.StraightArmCutoffHz)), TestCase(nameof(FullBodyIk.ShrugReleaseSeconds))]
        public void ATuningValueRefusedNamesItsSetting(string name)
        {
            FullBodyIk ik = HangingArm(0.02f).ik;
            System.Reflection.PropertyInfo p = typeof(FullBodyIk).GetProperty(name);
            object before = p.GetValue(ik);
            foreach (float bad in new[] { -1f, float.NaN, float.PositiveInfinity })
            {
                var e = Assert.Throws<System.Reflection.TargetInvocationException>(() => p.SetValue(ik, bad), $"{name} = {bad}");
                Assert.That(((ArgumentOutOfRangeException)e.InnerException).ParamName, Is.EqualTo(name));
                StringAssert.Contains("FullBodyIk." + name, e.InnerException.Message);
            }
            Assert.That(p.GetValue(ik), Is.EqualTo(before), "kept");
        }

        /// <summary>
        /// What is held is a continuous function of the goal: a hand just within the shrug's 20° is held whole, one a little
        /// beyond in part, one far beyond (10° past the range) not at all, with no jump in between (before: held whole up to
        /// 20° and not at all past it, so a goal micrometres either side of that line held 20° or nothing for seconds). The hand
        /// hangs below the shoulder 0 to 12 cm beyond its arm, one step a millimetre; the held shrug is read on a frame whose
        /// hand is well within reach (at half the goal's distance: nearer than the straight arm's steadying, which turns the
        /// clavicle for a frame within 5 % of full reach; at three quarters, 12 cm beyond read that turn, 3°, as held).
        /// </summary>
        [Test]
        public void TheHeldShrugFadesOutBeyondTheShouldersRangeWithoutAJump()
        {
            float previous = 0f, largestStep = 0f, largest = 0f, last = 0f;
            for (int mm = 0; mm <= 120; mm++)
            {
                var (ik, pose, targets, truth) = HangingArm(mm * 0.001f);
                ik.Solve(in targets, pose, 1f / 90);
                BodyTargets within = targets;
                within.LeftHand.Goal = new RigidPose(Vector3.Lerp(targets.LeftHand.Goal.Position, pose.World[truth[HumanoidBone.LeftUpperArm]].Position, 0.5f), targets.LeftHand.Goal.Rotation);
                ik.Solve(in within, pose, 1e-6f);
                float held = ClavicleTurnDegrees(pose, truth);
                if (mm > 0) largestStep = Math.Max(largestStep, Math.Abs(held - previous));
                largest = Math.Max(largest, held);
                previous = last = held;
            }
            TestContext.WriteLine($"largest held {largest:F2} deg, largest change over 1 mm of goal {largestStep:F2} deg, held 12 cm beyond {last:F3} deg");
            Assert.That(largest, Is.GreaterThan(19.5f), "a shrug of (nearly) the whole range is held");
            Assert.That(largestStep, Is.LessThan(1.5f), "no jump in what is held");
            Assert.That(last, Is.LessThan(1e-3f), "a goal far beyond the shoulder's range holds nothing");
        }

        // Frame 0 of mocapbank with the left hand's goal `degreesOff` off the line from the clavicle's pivot through the
        // (unshrugged) shoulder, `beyond` metres farther from the pivot than clavicle and arm reach together (negative: nearer).
        private static (FullBodyIk ik, SkeletonPose pose, BodyTargets targets, Truth truth) GoalAlongTheClavicle(float degreesOff, float beyond)
        {
            var (ik, pose, targets, truth) = FirstFrameSolved();
            Vector3 pivot = pose.World[truth[HumanoidBone.LeftShoulder]].Position, shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position;
            float arm = LeftArmLength(pose, truth);
            Vector3 along = Vector3.Normalize(shoulder - pivot);
            Vector3 off = Vector3.Transform(along, Rotations.AngleAxis(degreesOff, Vector3.Cross(along, Vector3.UnitY)));
            Vector3 goal = pivot + off * (Vector3.Distance(shoulder, pivot) + arm + beyond);
            targets.LeftHand = new LimbTarget(new RigidPose(goal, targets.LeftHand.Goal.Rotation), goal - Vector3.UnitY * arm);
            return (ik, pose, targets, truth);
        }

        /// <summary>
        /// A goal beyond any reach (farther from the clavicle's pivot than clavicle and arm together) says nothing about the
        /// shoulder even when the turn toward it lies within the shrug's 20°: the hold weighs how far beyond it lies as the
        /// shoulder's arc that distance would be, so it fades out there as it does past the 20° (found in review: a glitch 2 m
        /// out along the clavicle's line was held whole for seconds). 10° off the clavicle's line, the goal moved out from
        /// 2 cm within the farthest reach to 10 cm beyond it, one step a millimetre: held whole up to it and a little past,
        /// nothing a few centimetres past it, no jump in between. (Within the farthest reach the least turn that reaches rises
        /// steeply as the goal nears it: 4.7° to 10° over its last millimetre, the law of cosines' square root; that is the
        /// shoulder's geometry, not the hold.)
        /// </summary>
        [Test]
        public void AGoalBeyondAnyReachIsNotHeld()
        {
            float previous = 0f, largestStep = 0f, atTheFarthestReach = 0f, last = 0f;
            for (int mm = -20; mm <= 100; mm++)
            {
                var (ik, pose, targets, truth) = GoalAlongTheClavicle(10f, mm * 0.001f);
                ik.Solve(in targets, pose, 1f / 90);
                BodyTargets within = targets;
                within.LeftHand.Goal = new RigidPose(Vector3.Lerp(pose.World[truth[HumanoidBone.LeftUpperArm]].Position, targets.LeftHand.Goal.Position, 0.5f), targets.LeftHand.Goal.Rotation);
                ik.Solve(in within, pose, 1e-6f);
                float held = ClavicleTurnDegrees(pose, truth);
                if (mm > 0) largestStep = Math.Max(largestStep, Math.Abs(held - previous));
                if (mm == 0) atTheFarthestReach = held;
                previous = last = held;
            }
            var (ik2, pose2, targets2, truth2) = GoalAlongTheClavicle(15f, 2f);
            ik2.Solve(in targets2, pose2, 1f / 90);
            float glitch = ClavicleTurnDegrees(pose2, truth2);
            BodyTargets near = targets2;
            near.LeftHand.Goal = new RigidPose(Vector3.Lerp(pose2.World[truth2[HumanoidBone.LeftUpperArm]].Position, targets2.LeftHand.Goal.Position, 0.1f), targets2.LeftHand.Goal.Rotation);
            ik2.Solve(in near, pose2, 1e-6f);
            float glitchHeld = ClavicleTurnDegrees(pose2, truth2);
            TestContext.WriteLine($"10 deg off the line: held {atTheFarthestReach:F2} deg at the farthest reach, {last:F3} deg 10 cm beyond, largest change over 1 mm {largestStep:F2} deg; " +
                $"2 m beyond, 15 deg off: turned {glitch:F2} deg that frame, held {glitchHeld:F3} deg");
            Assert.That(atTheFarthestReach, Is.EqualTo(10f).Within(0.5f), "at the farthest reach the whole turn onto the line is held");
            Assert.That(largestStep, Is.LessThan(1f), "no jump in what is held");
            Assert.That(last, Is.LessThan(1e-3f), "10 cm beyond any reach holds nothing");
            Assert.That(glitch, Is.GreaterThan(10f), "the frame of the glitch still turns the clavicle toward it");
            Assert.That(glitchHeld, Is.LessThan(1e-3f), "a glitch 2 m out is not held");
        }

        /// <summary>
        /// A nod swings the shoulders no more when they hang from the neck: on MocapBank with its clavicles moved under its neck
        /// (as 3ds Max Biped hangs them), the head target turned 30° forward about its own position turns the neck as on the
        /// original (<see cref="FullBodyIk.NeckFollowsHead"/>; the spine below bends again to carry it) and each clavicle as
        /// on the original, with the chest, within 0.05° (before, it turned with the neck as well), its shoulder within what
        /// its root rides on the neck. (The two rigs' rest poses differ by float rounding, and the back's flexion is solved to
        /// the float resolution of its cost, not further: the two clavicles 0.004° apart when its solve started 0.001 rad
        /// forward, 0.013° since it starts 0.01 rad forward, 0.01–0.07° with the solve run to 400 iterations.)
        /// </summary>
        [Test]
        public void ANodDoesNotSwingShouldersThatHangFromTheNeck()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            var (ownClavicle, ownNeck, ownShoulder) = Nod(new Truth(clip));
            var (clavicle, neck, shoulder) = Nod(new Truth(Topology.Reparented(clip, ("LeftCollar", "Neck"), ("RightCollar", "Neck"))));
            TestContext.WriteLine($"nod 30 deg, clavicles on the chest: neck turned {ownNeck:F2} deg, clavicle {ownClavicle:F3} deg, shoulder moved {ownShoulder:F1} mm; " +
                $"under the neck: {neck:F2} deg, {clavicle:F3} deg, {shoulder:F1} mm");
            Assert.That(neck, Is.EqualTo(ownNeck).Within(0.01f).And.GreaterThan(3f), "the neck follows the head as it does on the original");
            Assert.That(clavicle, Is.EqualTo(ownClavicle).Within(0.05f), "the clavicle turns as on the original (with the chest), not with the neck");
            Assert.That(shoulder, Is.EqualTo(ownShoulder).Within(15f), "the shoulder moves only as far as its root rides on the neck");
        }

        /// <summary>
        /// Nor when the hand of that shoulder is lost as the head nods: its arm keeps its pose, and its clavicle keeps its
        /// place with the chest as on the original (found in review: it kept its rotation on the neck and swung with it).
        /// </summary>
        [Test]
        public void ANodDoesNotSwingTheShoulderOfALostHand()
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            var (ownClavicle, _, ownShoulder) = Nod(new Truth(clip), leftHandLost: true);
            var (clavicle, neck, shoulder) = Nod(new Truth(Topology.Reparented(clip, ("LeftCollar", "Neck"), ("RightCollar", "Neck"))), leftHandLost: true);
            TestContext.WriteLine($"nod 30 deg, left hand lost: clavicle {ownClavicle:F3} deg on the chest, {clavicle:F3} deg under the neck (neck {neck:F2} deg); shoulder {ownShoulder:F1} / {shoulder:F1} mm");
            Assert.That(neck, Is.GreaterThan(3f), "the neck follows the head");
            Assert.That(clavicle, Is.EqualTo(ownClavicle).Within(0.05f), "the lost hand's clavicle turns as on the original, not with the neck");
            Assert.That(shoulder, Is.EqualTo(ownShoulder).Within(15f), "its shoulder moves only as far as its root rides on the neck");
        }

        // The turn of the neck and the left clavicle (°) and how far the left shoulder moves (mm) when the head target of
        // MocapBank's first frame turns 30° forward about its own position (the left hand lost on that frame if asked).
        private static (float clavicle, float neck, float shoulder) Nod(Truth truth, bool leftHandLost = false)
        {
            var ik = new FullBodyIk(truth.Map);
            var pose = new SkeletonPose(truth.Clip.Skeleton);
            var targets = new BodyTargets();
            truth.Targets(0, ref targets);
            ik.Solve(in targets, pose);
            Quaternion clavicle = pose.World[truth[HumanoidBone.LeftShoulder]].Rotation, neck = pose.World[truth[HumanoidBone.Neck]].Rotation;
            Vector3 shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position;
            BodyTargets nod = targets;
            Vector3 hipLine = pose.World[truth[HumanoidBone.RightUpperLeg]].Position - pose.World[truth[HumanoidBone.LeftUpperLeg]].Position;
            nod.Head = new RigidPose(targets.Head.Position, Rotations.AngleAxis(30f, hipLine) * targets.Head.Rotation);
            nod.LeftHand.IsActive = !leftHandLost;
            ik.Solve(in nod, pose);
            return (Rotations.AngleDegrees(clavicle, pose.World[truth[HumanoidBone.LeftShoulder]].Rotation),
                Rotations.AngleDegrees(neck, pose.World[truth[HumanoidBone.Neck]].Rotation),
                Vector3.Distance(shoulder, pose.World[truth[HumanoidBone.LeftUpperArm]].Position) * 1000f);
        }

        /// <summary>
        /// The 20° a shoulder shrugs bounds the whole shrug, held part included: a hand reaching 1 mm further down each
        /// frame (90 Hz) to 20 cm beyond its arm never turns the clavicle past 20° from the calibration pose, as a single
        /// frame at 20 cm does not (found in review: the limit once applied to each frame's extra turn, 39.9° here).
        /// </summary>
        [Test]
        public void TheHeldShrugStaysWithinTheShouldersRange()
        {
            var (ik, pose, targets, truth) = HangingArm(0f);
            Vector3 goal0 = targets.LeftHand.Goal.Position;
            float largest = 0f;
            for (int i = 0; i <= 200; i++)
            {
                BodyTargets t = targets;
                t.LeftHand.Goal = new RigidPose(goal0 - Vector3.UnitY * (i * 0.001f), targets.LeftHand.Goal.Rotation);
                ik.Solve(in t, pose, 1f / 90);
                largest = Math.Max(largest, ClavicleTurnDegrees(pose, truth));
            }
            TestContext.WriteLine($"largest clavicle turn over the reach: {largest:F2} deg");
            Assert.That(largest, Is.LessThanOrEqualTo(20.01f));
            Assert.That(largest, Is.GreaterThan(19.9f), "and the shrug does reach its limit");
        }

        /// <summary>
        /// A frame in which no time passed (a repeated timestamp, or a recorded session replayed while the game is paused) keeps the held shrug:
        /// the shoulder does not move. Found in review: it once started such a frame from the calibration pose (the shoulder
        /// jumped 30 mm and back).
        /// </summary>
        [Test]
        public void AFrameWithoutElapsedTimeKeepsTheHeldShrug()
        {
            var (ik, pose, targets, truth) = HangingArm(0.03f);
            ik.Solve(in targets, pose, 1f / 90);
            BodyTargets within = targets;
            within.LeftHand.Goal = new RigidPose(targets.LeftHand.Goal.Position + Vector3.UnitY * 0.08f, targets.LeftHand.Goal.Rotation);
            ik.Solve(in within, pose, 1f / 90);
            float held = ClavicleTurnDegrees(pose, truth);
            Vector3 shoulder = pose.World[truth[HumanoidBone.LeftUpperArm]].Position;
            foreach (float dt in new[] { 0f, -0.01f, float.NaN })
            {
                ik.Solve(in within, pose, dt);
                Assert.That(ClavicleTurnDegrees(pose, truth), Is.EqualTo(held).Within(1e-3f), $"dt {dt}: the shrug kept, not released");
                Approx.Near(shoulder, pose.World[truth[HumanoidBone.LeftUpperArm]].Position, 1e-5f, $"dt {dt}: the shoulder stays");
            }
            Assert.That(held, Is.GreaterThan(5f), "a shrug was held");
        }

        /// <summary>
        /// A wearer standing still in the calibration pose, the pelvis tracker and the HMD each with 1 mm of noise per
        /// coordinate (900 frames, seeded; the spine bend computed from the noisy positions as the mapper does). The back is
        /// straight there, where the hips-to-head distance changes with the square of the flexion: chasing the noise to the
        /// last 0.1 mm flexed the back forward and back by centimetres from frame to frame (2026-12-02, before the back's
        /// stiffness: the chest p95 / max 20.8 / 31.1 mm from where the noise-free targets put it on MocapBank, 20.8 / 29.9 mm
        /// on Mixamo). Now 3.0 / 7.4 and 3.3 / 18.8 mm (2.8 / 9.0 and 2.9 / 18.8 while the flexion started 0.001 rad forward,
        /// <see cref="ASlouchedBackStaysCurledAsTheHeadPassesOverTheHips"/>): within the devices' noise but on the frames where the distance falls
        /// by more than the chord noise (where the back starts to flex, the flexion still grows with the square root of the
        /// shortfall); the head 2.75 mm p95 from its noisy target (2.56 before: a target beyond a straight back's reach).
        /// With <see cref="FullBodyIk.ChordNoiseMetres"/> 0 the back flexes until the head is on its target again.
        /// </summary>
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        public void TheDevicesNoiseDoesNotFlexAStraightBack(string clipName)
        {
            var truth = new Truth(clipName);
            var calibration = new SkeletonPose(truth.Clip.Skeleton);
            TPoser.Apply(truth.Map, calibration, RigidPose.Identity);
            RigidPose[] t = calibration.World;
            RigidPose hips = t[truth[HumanoidBone.Hips]], head = t[truth[HumanoidBone.Head]];
            BodyTargets Targets(Vector3 hipsNoise, Vector3 headNoise)
            {
                var targets = new BodyTargets
                {
                    Hips = new RigidPose(hips.Position + hipsNoise, hips.Rotation), HipsActive = true,
                    Head = new RigidPose(head.Position + headNoise, head.Rotation), HeadActive = true,
                    LeftFoot = new LimbTarget(t[truth[HumanoidBone.LeftFoot]], t[truth[HumanoidBone.LeftLowerLeg]].Position),
                    RightFoot = new LimbTarget(t[truth[HumanoidBone.RightFoot]], t[truth[HumanoidBone.RightLowerLeg]].Position),
                    LeftHand = new LimbTarget(t[truth[HumanoidBone.LeftHand]], t[truth[HumanoidBone.LeftLowerArm]].Position),
                    RightHand = new LimbTarget(t[truth[HumanoidBone.RightHand]], t[truth[HumanoidBone.RightLowerArm]].Position),
                };
                targets.SpineBend = Rotations.FromTo(head.Position - hips.Position, targets.Head.Position - targets.Hips.Position);
                return targets;
            }
            int chest = truth.Map.Has(HumanoidBone.UpperChest) ? truth[HumanoidBone.UpperChest] : truth[HumanoidBone.Chest];

            foreach (float chordNoise in new[] { FullBodyIk.DefaultChordNoiseMetres, 0f })
            {
                var ik = new FullBodyIk(truth.Map, calibration) { ChordNoiseMetres = chordNoise };
                var pose = new SkeletonPose(truth.Clip.Skeleton);
                BodyTargets still = Targets(Vector3.Zero, Vector3.Zero);
                ik.Solve(in still, pose);
                Vector3 chestStill = pose.World[chest].Position;
                Assert.That(Vector3.Distance(pose.World[truth[HumanoidBone.Head]].Position, head.Position), Is.LessThan(1e-4f), "noise-free: the head on its target");

                var random = new Random(7);
                float Gaussian() => (float)(Math.Sqrt(-2.0 * Math.Log(1.0 - random.NextDouble())) * Math.Cos(2.0 * Math.PI * random.NextDouble()));
                Vector3 Noise() => 0.001f * new Vector3(Gaussian(), Gaussian(), Gaussian());
                const int frames = 900;
                var chestOff = new float[frames];
                var headLeft = new float[frames];
                for (int f = 0; f < frames; f++)
                {
                    BodyTargets noisy = Targets(Noise(), Noise());
                    IkReport r = ik.Solve(in noisy, pose);
                    chestOff[f] = Vector3.Distance(pose.World[chest].Position, chestStill) * 1000f;
                    headLeft[f] = r.HeadDistanceLeft * 1000f;
                }
                Array.Sort(chestOff);
                Array.Sort(headLeft);
                float chestP95 = chestOff[(int)(0.95 * frames)], headP95 = headLeft[(int)(0.95 * frames)];
                TestContext.WriteLine($"{clipName}, chord noise {chordNoise * 1000f} mm: chest off p95 / max {chestP95:F1} / {chestOff[frames - 1]:F1} mm, " +
                                      $"head from its target median / p95 / max {headLeft[frames / 2]:F2} / {headP95:F2} / {headLeft[frames - 1]:F2} mm");
                if (chordNoise > 0f)
                {
                    // The hips' noise alone moves the chest by 2.8 mm at p95 (a 1 mm-per-coordinate displacement).
                    Assert.That(chestP95, Is.LessThan(6f), "the chest within the devices' noise (p95, mm)");
                    Assert.That(headP95, Is.LessThan(chordNoise * 1000f + 2f), "the head left at most about the chord noise short (p95, mm)");
                }
                else
                {
                    // The noise puts the head beyond a straight back's reach in about half the frames, on its target in the others.
                    Assert.That(headLeft[frames / 2], Is.LessThan(0.1f), "no chord noise: the head on its target (median, mm)");
                    Assert.That(headP95, Is.LessThan(3.5f), "no chord noise: the head short only of a target beyond reach (p95, mm)");
                }
            }
        }

        // The T-pose's targets for a leg test: the hips and feet where the T-pose has them, plus noise; the knees' hints ahead.
        private static BodyTargets LegTargets(Truth truth, RigidPose[] t, Vector3 hipsShift, Vector3 hipsNoise, Vector3 leftNoise, Vector3 rightNoise)
        {
            RigidPose hips = t[truth[HumanoidBone.Hips]], head = t[truth[HumanoidBone.Head]];
            RigidPose left = t[truth[HumanoidBone.LeftFoot]], right = t[truth[HumanoidBone.RightFoot]];
            Vector3 ahead = new Vector3(0f, 0f, 0.3f);
            return new BodyTargets
            {
                Hips = new RigidPose(hips.Position + hipsShift + hipsNoise, hips.Rotation), HipsActive = true,
                Head = new RigidPose(head.Position + hipsShift, head.Rotation), HeadActive = true,
                SpineBend = Quaternion.Identity,
                LeftFoot = new LimbTarget(new RigidPose(left.Position + leftNoise, left.Rotation), t[truth[HumanoidBone.LeftLowerLeg]].Position + ahead),
                RightFoot = new LimbTarget(new RigidPose(right.Position + rightNoise, right.Rotation), t[truth[HumanoidBone.RightLowerLeg]].Position + ahead),
                LeftHand = new LimbTarget(t[truth[HumanoidBone.LeftHand]], t[truth[HumanoidBone.LeftLowerArm]].Position),
                RightHand = new LimbTarget(t[truth[HumanoidBone.RightHand]], t[truth[HumanoidBone.RightLowerArm]].Position),
            };
        }

        /// <summary>
        /// A leg held straight does not shiver with the devices' noise. Near full reach the knee's distance from the
        /// hip-to-ankle line grows with the square root of the slack, so 1 mm of noise per coordinate on the hips and feet
        /// (1.4 mm in the hip-to-ankle distance) moved a straight knee by centimetres a frame (found in review, 2026-12-03:
        /// with <see cref="FullBodyIk.StraightLegCutoffHz"/> 0, as before, the knee's frame-to-frame move p95 / max
        /// 28.9 / 40.3 mm on MocapBank, 28.3 / 39.4 on Mixamo); with the filter and its soft reach 6.4 / 13.1 and 6.6 / 13.4
        /// mm, the foot within 2.87 mm (p95) of where the noise-free targets put it (2.83 mm without the filter: the noise).
        /// </summary>
        [TestCase("mocapbank_30fps.bvh")]
        [TestCase("mixamo_fingers_30fps.bvh")]
        public void AStraightLegDoesNotShiverWithTheDevicesNoise(string clipName)
        {
            var truth = new Truth(clipName);
            var calibration = new SkeletonPose(truth.Clip.Skeleton);
            TPoser.Apply(truth.Map, calibration, RigidPose.Identity);
            RigidPose[] t = calibration.World;
            int knee = truth[HumanoidBone.LeftLowerLeg], foot = truth[HumanoidBone.LeftFoot];
            Vector3 ankle = t[foot].Position;
            const int frames = 900;
            const float dt = 1f / 90f;
            foreach (float cutoff in new[] { FullBodyIk.DefaultStraightLegCutoffHz, 0f })
            {
                var ik = new FullBodyIk(truth.Map, calibration) { StraightLegCutoffHz = cutoff };
                var pose = new SkeletonPose(truth.Clip.Skeleton);
                var random = new Random(11);
                float Gaussian() => (float)(Math.Sqrt(-2.0 * Math.Log(1.0 - random.NextDouble())) * Math.Cos(2.0 * Math.PI * random.NextDouble()));
                Vector3 Noise() => 0.001f * new Vector3(Gaussian(), Gaussian(), Gaussian());
                var kneeMoves = new float[frames - 1];
                var footOff = new float[frames];
                Vector3 lastKnee = default;
                for (int f = 0; f < frames; f++)
                {
                    BodyTargets noisy = LegTargets(truth, t, Vector3.Zero, Noise(), Noise(), Noise());
                    ik.Solve(in noisy, pose, dt);
                    Vector3 k = pose.World[knee].Position;
                    if (f > 0) kneeMoves[f - 1] = Vector3.Distance(k, lastKnee) * 1000f;
                    lastKnee = k;
                    footOff[f] = Vector3.Distance(pose.World[foot].Position, ankle) * 1000f;
                }
                Array.Sort(kneeMoves);
                Array.Sort(footOff);
                float kneeP95 = kneeMoves[(int)(0.95 * kneeMoves.Length)], kneeMax = kneeMoves[kneeMoves.Length - 1];
                float footP95 = footOff[(int)(0.95 * frames)];
                TestContext.WriteLine($"{clipName}, cutoff {cutoff} Hz: knee's move a frame p95 / max {kneeP95:F1} / {kneeMax:F1} mm; foot from the noise-free ankle p95 {footP95:F2} mm");
                if (cutoff > 0f)
                {
                    Assert.That(kneeP95, Is.LessThan(9f), "a straight knee steady (its move a frame, p95, mm)");
                    Assert.That(kneeMax, Is.LessThan(20f), "a straight knee steady (its move a frame, max, mm)");
                    Assert.That(footP95, Is.LessThan(3.5f), "the foot within the devices' noise of its place (p95, mm)");
                }
                else Assert.That(kneeP95, Is.GreaterThan(20f), "without the filter the noise moves a straight knee (p95, mm): what the filter is for");
            }
        }

        /// <summary>
        /// The straight leg's filter follows time, not frames: the hips lowered 4 cm from a straight-legged stand and raised
        /// again over two seconds (noise-free) put the knee in the same place at the same time at 45 and at 180 frames a
        /// second (0.78 mm apart at most), and the foot lags its target by at most 3.0 mm at either rate (the filter's lag on the
        /// way down and up, 0.5 mm of it the soft reach).
        /// </summary>
        [Test]
        public void TheStraightLegsFilterFollowsTimeNotFrames()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var calibration = new SkeletonPose(truth.Clip.Skeleton);
            TPoser.Apply(truth.Map, calibration, RigidPose.Identity);
            RigidPose[] t = calibration.World;
            int knee = truth[HumanoidBone.LeftLowerLeg], foot = truth[HumanoidBone.LeftFoot];
            Vector3 ankle = t[foot].Position;
            // The hips' drop at time s: down and up again, smoothly (0.04 m at 1 s).
            Vector3 Drop(double s) => new Vector3(0f, -0.02f * (float)(1.0 - Math.Cos(Math.PI * Math.Min(s, 2.0))), 0f);
            Vector3[] KneeAt(int rate, out float footLag)
            {
                var ik = new FullBodyIk(truth.Map, calibration);
                var pose = new SkeletonPose(truth.Clip.Skeleton);
                int frames = 2 * rate + 1;
                var knees = new Vector3[frames];
                footLag = 0f;
                for (int f = 0; f < frames; f++)
                {
                    BodyTargets targets = LegTargets(truth, t, Drop((double)f / rate), Vector3.Zero, Vector3.Zero, Vector3.Zero);
                    ik.Solve(in targets, pose, 1f / rate);
                    knees[f] = pose.World[knee].Position;
                    footLag = Math.Max(footLag, Vector3.Distance(pose.World[foot].Position, ankle) * 1000f);
                }
                return knees;
            }
            Vector3[] slow = KneeAt(45, out float slowLag), fast = KneeAt(180, out float fastLag);
            float apart = 0f;
            for (int f = 0; f < slow.Length; f++) apart = Math.Max(apart, Vector3.Distance(slow[f], fast[4 * f]) * 1000f);
            TestContext.WriteLine($"knee apart at 45 and 180 Hz at most {apart:F2} mm; the foot's lag at most {slowLag:F2} / {fastLag:F2} mm");
            Assert.That(apart, Is.LessThan(1.5f), "the knee at the same time at either rate (mm)");
            Assert.That(Math.Max(slowLag, fastLag), Is.LessThan(4f), "the foot's lag behind its target (mm)");
        }

        /// <summary>
        /// A foot goal that is not finite (a target made by hand, not by the pipeline, whose sample gate refuses such devices)
        /// leaves the straight leg's filter as it was: no joint is ever NaN, and the frames after it are solved as if it had
        /// not come (the same pose as a run without it, within float rounding).
        /// </summary>
        [Test]
        public void ANonFiniteFootGoalLeavesTheStraightLegsFilterAsItWas()
        {
            var truth = new Truth("mocapbank_30fps.bvh");
            var calibration = new SkeletonPose(truth.Clip.Skeleton);
            TPoser.Apply(truth.Map, calibration, RigidPose.Identity);
            RigidPose[] t = calibration.World;
            int knee = truth[HumanoidBone.LeftLowerLeg];
            var clean = new FullBodyIk(truth.Map, calibration);
            var broken = new FullBodyIk(truth.Map, calibration);
            SkeletonPose cleanPose = new SkeletonPose(truth.Clip.Skeleton), brokenPose = new SkeletonPose(truth.Clip.Skeleton);
            for (int f = 0; f < 60; f++)
            {
                // The hips bob by 3 mm, so the legs stay within the filter's reach of straight.
                var bob = new Vector3(0f, 0.003f * MathF.Sin(f * 0.3f), 0f);
                BodyTargets targets = LegTargets(truth, t, bob, Vector3.Zero, Vector3.Zero, Vector3.Zero);
                clean.Solve(in targets, cleanPose, 1f / 90f);
                if (f == 20 || f == 21)
                {
                    BodyTargets bad = targets;
                    bad.LeftFoot.Goal = new RigidPose(new Vector3(float.NaN, 0f, float.PositiveInfinity), bad.LeftFoot.Goal.Rotation);
                    broken.Solve(in bad, brokenPose, 1f / 90f);
                    continue; // the clean run's frame is solved above; the broken one had the bad goal instead
                }
                broken.Solve(in targets, brokenPose, 1f / 90f);
                for (int j = 0; j < brokenPose.World.Length; j++)
                    Assert.That(Vectors.IsFinite(brokenPose.World[j].Position) && Rotations.IsFinite(brokenPose.World[j].Rotation), Is.True, $"frame {f}, joint {j}");
                if (f > 21)
                    Assert.That(Vector3.Distance(brokenPose.World[knee].Position, cleanPose.World[knee].Position), Is.LessThan(0.0015f),
                        $"frame {f}: the knee where the clean run has it (m); the filter missed only two frames' samples");
            }
        }
}
}
