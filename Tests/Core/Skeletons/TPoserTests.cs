using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The canonical T-pose from anatomy and landmarks (issue 10): the same joint positions whatever the rest pose and the
    /// bones' local axes, and the landmarks where the T-pose says (hip line level, feet flat toward the toes on the floor,
    /// arms out, palms down with the thumbs forward, spine up).
    /// </summary>
    public class TPoserTests
    {
        private static IEnumerable<TestCaseData> Clips()
        {
            foreach (string clip in new[] { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps_first240.bvh" })
                yield return new TestCaseData(clip).SetName($"TPose {clip}");
        }

        private static (HumanoidMap map, SkeletonPose pose) TPose(BvhClip clip, RigidPose placement)
        {
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            var pose = new SkeletonPose(clip.Skeleton);
            TPoser.Apply(map, pose, placement);
            return (map, pose);
        }

        [TestCaseSource(nameof(Clips))]
        public void EveryHumanoidJointIsWhereItIsWhateverTheRestAndTheLocalAxes(string file)
        {
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true });
            var placement = new RigidPose(new Vector3(0.3f, 0f, -1.2f), Rotations.AngleAxis(130f, Vector3.UnitY));
            var (map, reference) = TPose(clip, placement);
            var others = new[] { BvhRebaser.AlongX(clip), BvhRebaser.AlongX(clip, 37f), BvhRebaser.RandomAxes(clip, 1), BvhRebaser.RandomAxes(clip, 2), BvhRebaser.RandomAxes(clip, 3) };
            foreach (BvhClip other in others)
            {
                var (otherMap, pose) = TPose(other, placement);
                for (int b = 0; b < HumanoidBones.Count; b++)
                {
                    var bone = (HumanoidBone)b;
                    if (!map.Has(bone)) continue;
                    Approx.Near(reference.World[map[bone]].Position, pose.World[otherMap[bone]].Position, 1e-5f, $"{file} {bone}");
                }
                Assert.That(TPoser.EyePosition(otherMap, pose, placement.Rotation).Y, Is.EqualTo(TPoser.EyePosition(map, reference, placement.Rotation).Y).Within(1e-5f), "eye height (the scale)");
            }
        }

        [TestCaseSource(nameof(Clips))]
        public void TheLandmarksAreWhereTheTPoseSays(string file)
        {
            // A random rest convention, so nothing of the file's own rest can help.
            BvhClip clip = BvhRebaser.RandomAxes(BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true }), 11);
            var (map, pose) = TPose(clip, RigidPose.Identity);
            Vector3 At(HumanoidBone b) => pose.World[map[b]].Position;
            Vector3 hipLine = At(HumanoidBone.RightUpperLeg) - At(HumanoidBone.LeftUpperLeg);
            Assert.That(Vectors.AngleDegrees(hipLine, Vector3.UnitX), Is.LessThan(0.01f), "hip line level along +X");
            Assert.That(Vectors.AngleDegrees(At(HumanoidBone.Head) - At(HumanoidBone.Spine), Vector3.UnitY), Is.LessThan(0.01f), "spine straight up");
            float lowest = float.MaxValue;
            for (int j = 0; j < pose.World.Length; j++) lowest = System.Math.Min(lowest, pose.World[j].Position.Y);
            Assert.That(lowest, Is.EqualTo(0f).Within(1e-5f), "standing on the floor");
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Vector3 outward = side == BodySide.Left ? -Vector3.UnitX : Vector3.UnitX;
                HumanoidBone Bone(HumanoidBone left) => HumanoidBones.OnSide(left, side);
                Assert.That(Vectors.AngleDegrees(At(Bone(HumanoidBone.LeftUpperArm)) - At(Bone(HumanoidBone.LeftShoulder)), outward), Is.LessThan(0.01f), $"{side} clavicle out");
                Assert.That(Vectors.AngleDegrees(At(Bone(HumanoidBone.LeftHand)) - At(Bone(HumanoidBone.LeftUpperArm)), outward), Is.LessThan(0.01f), $"{side} arm out");
                Assert.That(Vectors.AngleDegrees(At(Bone(HumanoidBone.LeftFoot)) - At(Bone(HumanoidBone.LeftUpperLeg)), -Vector3.UnitY), Is.LessThan(0.01f), $"{side} leg down");
                // Feet toward the toes: straight ahead, the toes on the floor with the ankle at its anatomical height.
                Vector3 ankle = At(Bone(HumanoidBone.LeftFoot)), toe = pose.World[TPoser.ToeLandmark(map, side)].Position;
                Assert.That(Vectors.AngleDegrees(Vectors.ProjectOnPlane(toe - ankle, Vector3.UnitY), Vector3.UnitZ), Is.LessThan(0.01f), $"{side} toes forward");
                float leg = Vector3.Distance(At(Bone(HumanoidBone.LeftUpperLeg)), At(Bone(HumanoidBone.LeftLowerLeg))) + Vector3.Distance(At(Bone(HumanoidBone.LeftLowerLeg)), ankle);
                Assert.That(toe.Y, Is.LessThan(0.01f * leg), $"{side} toes on the floor (the longer leg's exactly)");
                Assert.That(ankle.Y - toe.Y, Is.EqualTo(TPoser.AnkleHeightOfLeg * leg).Within(5e-4f), $"{side} ankle its anatomical height above the toes");
                if (!HandModel.CanModel(map, side, out _)) continue;
                // Palms down, thumbs forward: from the finger bases alone.
                var hand = new HandModel(map, side, pose);
                RigidPose wrist = pose.World[map[Bone(HumanoidBone.LeftHand)]];
                Assert.That(Vectors.AngleDegrees(wrist.TransformDirection(hand.PalmNormalInHand), -Vector3.UnitY), Is.LessThan(0.01f), $"{side} palm down");
                Vector3 across = Vectors.ProjectOnPlane(wrist.TransformDirection(hand.AcrossInHand), wrist.TransformDirection(hand.AlongInHand));
                Assert.That(Vectors.AngleDegrees(across, Vector3.UnitZ), Is.LessThan(0.01f), $"{side} little-to-index forward");
                Assert.That(Vectors.AngleDegrees(wrist.TransformDirection(hand.AlongInHand), outward), Is.LessThan(0.01f), $"{side} hand out");
            }
        }

        [Test]
        public void AHandWithoutFingerBonesPointsAlongItsLongestChainNotItsThumb()
        {
            // The Kinects' hand: the wrist carries the hand centre (8 cm on, the hand tip 7 cm further) and the thumb (10 cm,
            // 40° aside). The farthest child alone is the thumb, 40° off the hand's direction.
            var aside = Vector3.Transform(Vector3.UnitX, Rotations.AngleAxis(40f, Vector3.UnitY)) * 0.10f;
            var skeleton = new Skeleton(
                new[] { "WRIST_LEFT", "HAND_LEFT", "HANDTIP_LEFT", "THUMB_LEFT" },
                new[] { -1, 0, 1, 0 },
                new[] { RigidPose.Identity, new RigidPose(new Vector3(0.08f, 0f, 0f), Quaternion.Identity), new RigidPose(new Vector3(0.07f, 0f, 0f), Quaternion.Identity), new RigidPose(aside, Quaternion.Identity) },
                new[] { false, false, true, true });
            var map = new HumanoidMap(skeleton, new[] { new KeyValuePair<HumanoidBone, string>(HumanoidBone.LeftHand, "WRIST_LEFT") });
            Assert.That(skeleton.GetName(TPoser.HandLandmark(map, BodySide.Left)), Is.EqualTo("HAND_LEFT"));
        }

        [Test]
        public void ASpineBoneMappedOffTheWayToTheHeadStillPoses()
        {
            // A map given by hand may put a spine bone where no spine is (here the Chest on the head's end joint): the T-pose
            // turns it toward the head as before and throws nothing (found in review: the child toward the head is none).
            BvhClip clip = BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton, new Dictionary<string, HumanoidBone> { ["mixamorig:HeadTop_End"] = HumanoidBone.Chest });
            Assert.That(map.NameOf(HumanoidBone.Chest), Is.EqualTo("mixamorig:HeadTop_End"));
            var pose = new SkeletonPose(clip.Skeleton);
            Assert.DoesNotThrow(() => TPoser.Apply(map, pose, RigidPose.Identity));
            foreach (RigidPose p in pose.World) Assert.That(Vectors.IsFinite(p.Position) && Rotations.IsFinite(p.Rotation), Is.True, "no NaN");
        }

        private static BvhClip Read(string file) => BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true });

        private static RigidPose[] FirstFrame(BvhClip clip)
        {
            var local = new RigidPose[clip.Skeleton.JointCount];
            clip.GetLocalPoses(0, local);
            return local;
        }

        // The T-pose with the twists no landmark fixes taken from the rest (null) or from other local poses.
        private static SkeletonPose TPose(HumanoidMap map, RigidPose[] reference)
        {
            var pose = new SkeletonPose(map.Skeleton);
            TPoser.Apply(map, pose, RigidPose.Identity, reference);
            return pose;
        }

        // The largest distance (mm) of a humanoid joint between the T-pose from the rest and from the clip's first frame.
        private static double ReferenceSpreadMm(BvhClip clip, HumanoidMap map)
        {
            SkeletonPose fromRest = TPose(map, null), fromFirst = TPose(map, FirstFrame(clip));
            double most = 0;
            for (int b = 0; b < HumanoidBones.Count; b++)
                if (map.Has((HumanoidBone)b))
                    most = System.Math.Max(most, 1000.0 * Vector3.Distance(fromRest.World[map[(HumanoidBone)b]].Position, fromFirst.World[map[(HumanoidBone)b]].Position));
            return most;
        }

        [Test]
        public void AJointAtTheSamePlaceAsItsSpineJointDoesNotLeaveTheSpineToTheReference()
        {
            // A joint on Chest2, between it and the neck (two joints at one place): taken as the way up, it gave no
            // direction, and Chest2 kept its reference rotation (the shoulders 54 mm apart between two references).
            BvhClip clip = Topology.WithJointsAbove(Read("mocapbank_30fps.bvh"), ("Neck", "NeckBase", 0f));
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            Assert.That(ReferenceSpreadMm(clip, map), Is.LessThan(1.0));
        }

        [Test]
        public void AHeadWithoutEyesStandsItsCrownUpWhateverTheReference()
        {
            // MocapBank's head has no eyes, only its End Site at the crown: the crown straight up from either reference (it
            // was carried from the reference with the neck: 9.6 degrees apart between the rest and the first frame).
            BvhClip clip = Read("mocapbank_30fps.bvh");
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            Assert.That(map.Has(HumanoidBone.LeftEye), Is.False);
            int head = map[HumanoidBone.Head], crown = -1;
            for (int j = 0; j < clip.Skeleton.JointCount; j++)
                if (clip.Skeleton.GetParent(j) == head) crown = j;
            foreach (RigidPose[] reference in new[] { null, FirstFrame(clip) })
            {
                SkeletonPose pose = TPose(map, reference);
                Vector3 up = pose.World[crown].Position - pose.World[head].Position;
                Assert.That(Vectors.AngleDegrees(up, Vector3.UnitY), Is.LessThan(0.01), reference == null ? "from the rest" : "from the first frame");
            }
        }

        [Test]
        public void EarsAndHairOnTheHeadAreNotItsCrown()
        {
            // The Mixamo head without its HeadTop_End: its eyes alone orient it. Ears beside it, or a hair root behind it,
            // taken for the crown (the longest child), turned the head by 9 and 68 degrees and lowered the eyes by up to
            // 13 cm, the avatar's scale off by 8.8 %.
            BvhClip original = Read("mixamo_fingers_30fps.bvh");
            int headTop = original.Skeleton.IndexOf("mixamorig:HeadTop_End");
            Assert.That(headTop, Is.GreaterThanOrEqualTo(0));
            int headTopEnd = original.Skeleton.IndexOf("mixamorig:HeadTop_End_End"); // HeadTop_End's End Site
            Assert.That(headTopEnd, Is.GreaterThanOrEqualTo(0));
            BvhClip eyesOnly = Topology.Without(original, headTop, headTopEnd);
            var variants = new Dictionary<string, BvhClip>
            {
                ["ears"] = Topology.WithLeaves(eyesOnly, ("mixamorig:Head", "mixamorig:LeftEar", new Vector3(0.075f, 0.05f, -0.01f)), ("mixamorig:Head", "mixamorig:RightEar", new Vector3(-0.075f, 0.05f, -0.01f))),
                ["hair behind"] = Topology.WithLeaves(eyesOnly, ("mixamorig:Head", "mixamorig:Hair1", new Vector3(0f, 0.04f, -0.11f))),
            };
            HumanoidMap plainMap = HumanoidNaming.Detect(eyesOnly.Skeleton);
            SkeletonPose plain = TPose(plainMap, null);
            foreach (var variant in variants)
            {
                HumanoidMap map = HumanoidNaming.Detect(variant.Value.Skeleton);
                SkeletonPose pose = TPose(map, null);
                Assert.That(Rotations.AngleDegrees(plain.World[plainMap[HumanoidBone.Head]].Rotation, pose.World[map[HumanoidBone.Head]].Rotation), Is.LessThan(0.01), variant.Key);
                Assert.That(TPoser.EyePosition(map, pose, Quaternion.Identity).Y, Is.EqualTo(TPoser.EyePosition(plainMap, plain, Quaternion.Identity).Y).Within(1e-5f), variant.Key + ": eye height");
            }
            // A crown above the eyes is still one: the original's HeadTop_End stands straight up.
            HumanoidMap originalMap = HumanoidNaming.Detect(original.Skeleton);
            SkeletonPose withTop = TPose(originalMap, null);
            Vector3 up = withTop.World[headTop].Position - withTop.World[originalMap[HumanoidBone.Head]].Position;
            Assert.That(Vectors.AngleDegrees(up, Vector3.UnitY), Is.LessThan(0.01), "HeadTop_End is the crown");
        }

        [Test]
        public void HipsWhoseSpineStartsOnTheHipLineStandUpByTheSpineNotTheReference()
        {
            // Rigify's spine joint sits on the middle of its hip line, so the hips' pitch came from the reference: a clip
            // whose first frame lies down calibrated its pelvis tracker turned 90 degrees (MPJPE 17.4 against 11.0 mm).
            BvhClip clip = Read("rigify_6channel_24fps_first240.bvh");
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            int hips = map[HumanoidBone.Hips];
            Vector3 mid = (clip.Skeleton.GetRestLocal(map[HumanoidBone.LeftUpperLeg]).Position + clip.Skeleton.GetRestLocal(map[HumanoidBone.RightUpperLeg]).Position) * 0.5f;
            Assert.That(Vector3.Distance(clip.Skeleton.GetRestLocal(map[HumanoidBone.Spine]).Position, mid), Is.LessThan(1e-4f), "the spine starts on the hip line");
            RigidPose[] upright = FirstFrame(clip), lying = FirstFrame(clip);
            lying[hips] = new RigidPose(lying[hips].Position, Rotations.AngleAxis(90f, Vector3.UnitX) * lying[hips].Rotation);
            SkeletonPose a = TPose(map, upright), b = TPose(map, lying);
            Assert.That(Rotations.AngleDegrees(a.World[hips].Rotation, b.World[hips].Rotation), Is.LessThan(0.01));
            Assert.That(ReferenceSpreadMm(clip, map), Is.LessThan(1.0), "every humanoid joint where it is from the rest and from the first frame");
        }

        [Test]
        public void ANoseIsNotACrown()
        {
            // A lone leaf at the face, 10 cm ahead of MocapBank's head joint and longer than half its neck, in place of its
            // End Site: stood up as a crown, it tipped the face 73 degrees up. It is named as part of the face: no crown, and
            // the head keeps its reference rotation.
            BvhClip original = Read("mocapbank_30fps.bvh");
            int head = original.Skeleton.IndexOf("Head"), end = -1;
            for (int j = 0; j < original.Skeleton.JointCount; j++)
                if (original.Skeleton.GetParent(j) == head) end = j;
            BvhClip clip = Topology.WithLeaves(Topology.Without(original, end), ("Head", "Nose", new Vector3(0f, 0.03f, 0.10f)));
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            SkeletonPose pose = TPose(map, null);
            int nose = clip.Skeleton.IndexOf("Nose");
            Vector3 ahead = pose.World[nose].Position - pose.World[map[HumanoidBone.Head]].Position;
            Assert.That(Vectors.AngleDegrees(ahead, Vector3.UnitY), Is.GreaterThan(45f), "the nose is not straight up");
        }

        [TestCase("")]
        [TestCase("Clip:")]
        [TestCase("Bear:")]
        [TestCase("Machine:")]
        public void TheCrownDoesNotDependOnTheRigsNamespace(string prefix)
        {
            // Namespaces that hold a face word ("lip", "ear", "chin") made the End Site at the crown no crown: the head kept
            // its rest rotation, the crown 21 degrees from up.
            string text = System.IO.File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh")).Replace("ROOT ", "ROOT " + prefix).Replace("JOINT ", "JOINT " + prefix);
            BvhClip clip = BvhReader.Read(new System.IO.StringReader(text), "prefixed.bvh", new BvhReadOptions { ToMetres = true });
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            int head = map[HumanoidBone.Head], crown = -1;
            for (int j = 0; j < clip.Skeleton.JointCount; j++)
                if (clip.Skeleton.GetParent(j) == head) crown = j;
            SkeletonPose pose = TPose(map, null);
            Assert.That(Vectors.AngleDegrees(pose.World[crown].Position - pose.World[head].Position, Vector3.UnitY), Is.LessThan(0.01));
        }
}
}
