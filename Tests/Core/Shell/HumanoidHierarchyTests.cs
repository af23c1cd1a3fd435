using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free half of the Unity humanoid binding (HumanoidBinding): which transforms become joints, their rest
    /// poses in the root's units whatever scales and rotations the FBX put above the hips, and how a solved pose goes back
    /// (local rotations, the hips' local position, the root's scale) so that every bone lands where the core put it.
    /// </summary>
    public class HumanoidHierarchyTests
    {
        private static HumanoidMap Mocap(string clip) =>
            HumanoidNaming.Detect(BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true }).Skeleton);

        private static readonly Quaternion BlenderArmature = Rotations.AngleAxis(-90f, Vector3.UnitX);

        [TestCase(1f)]
        [TestCase(0.01f)]
        [TestCase(100f)]
        public void TheSkeletonKeepsThePathsToTheBonesInTheRootsUnits(float armatureScale)
        {
            HumanoidMap mocap = Mocap("mixamo_fingers_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, BlenderArmature, armatureScale);
            Assert.That(HumanoidHierarchy.TryFromBones(engine.Read(), engine.BoneNodes, 1f, out HumanoidHierarchy h, out string error), Is.True, error);

            Assert.That(h.Skeleton.GetName(0), Is.EqualTo("Avatar"), "joint 0 is the Animator's own transform");
            Assert.That(h.Skeleton.IndexOf("Body"), Is.EqualTo(-1), "a mesh object beside the bones is not a joint");
            Assert.That(h.Skeleton.IndexOf("Armature"), Is.GreaterThan(0), "the node between the root and the hips is");
            Assert.That(h.Skeleton.GetRestLocal(0), Is.EqualTo(RigidPose.Identity), "the root rests at the identity: the pipeline places it");
            var fk = new RigidPose[h.JointCount];
            var rest = new RigidPose[h.JointCount];
            h.Skeleton.GetRestLocal(rest);
            h.Skeleton.ComputeWorld(rest, fk);
            for (int j = 0; j < h.JointCount; j++)
            {
                int node = h.NodeOf(j);
                Approx.Near(engine.WorldPosition(node), fk[j].Position, 1e-5f, h.Skeleton.GetName(j));
                Approx.Near(engine.WorldRotation(node), fk[j].Rotation, 0.01f, h.Skeleton.GetName(j));
                if (j > 0) Assert.That(h.Skeleton.GetRestLocal(j).Rotation, Is.EqualTo(Quaternion.Normalize(engine.LocalRotations[node])), "core local rotations are the transforms' own");
            }
            for (int b = 0; b < HumanoidBones.Count; b++)
                if (engine.BoneNodes[b] >= 0) Assert.That(h.NodeOf(h.Map[(HumanoidBone)b]), Is.EqualTo(engine.BoneNodes[b]), ((HumanoidBone)b).ToString());
        }

        [Test]
        public void TheFingerTipsAndToeEndsAreKeptAsEndPoints()
        {
            HumanoidMap mocap = Mocap("mixamo_fingers_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
            int[] bones = (int[])engine.BoneNodes.Clone();
            Assert.That(HumanoidHierarchy.TryFromBones(engine.Read(), bones, 1f, out HumanoidHierarchy h, out string error), Is.True, error);
            int distal = h.Map[HumanoidBone.LeftIndexDistal];
            int tips = 0;
            for (int j = 0; j < h.JointCount; j++)
                if (h.Skeleton.GetParent(j) == distal) { tips++; Assert.That(h.Skeleton.IsEndSite(j), Is.True); }
            Assert.That(tips, Is.EqualTo(1), "the index tip below the distal phalanx");
            Assert.That(h.JointsBelow(HumanoidBone.LeftHand), Has.Length.EqualTo(15 + 5), "three phalanges and a tip per finger");
            Assert.That(HandModel.CanModel(h.Map, BodySide.Left, out string reason), Is.True, reason);
        }

        /// <summary>
        /// The head's crown is kept too (Mixamo's HeadTop_End: without it the bound avatar's head kept its bind pose in the
        /// T-pose, its eyes 3 cm lower, and the avatar came out 1.8 % too tall), and a drawn object under the head or a last
        /// finger joint (a hat, a ring, the mannequin's primitives) is no end point: the bound avatar's T-pose is the wearer's.
        /// </summary>
        [Test]
        public void TheCrownIsKeptAndDrawnObjectsAreNoEndPoints()
        {
            HumanoidMap mocap = Mocap("mixamo_fingers_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
            var nodes = new List<HierarchyNode>(engine.Read());
            int head = engine.BoneNodes[(int)HumanoidBone.Head], distal = engine.BoneNodes[(int)HumanoidBone.LeftIndexDistal];
            // Appended after every node: still depth-first (their parents come before them).
            nodes.Add(new HierarchyNode("Hat", head, new Vector3(0f, 0.3f, 0f), Quaternion.Identity, Vector3.One, hasRenderer: true));
            nodes.Add(new HierarchyNode("Ring", distal, new Vector3(0.1f, 0f, 0f), Quaternion.Identity, Vector3.One, hasRenderer: true));
            Assert.That(HumanoidHierarchy.TryFromBones(nodes, engine.BoneNodes, 1f, out HumanoidHierarchy h, out string error), Is.True, error);
            Assert.That(h.Skeleton.IndexOf("mixamorig:HeadTop_End"), Is.GreaterThan(0), "the crown");
            Assert.That(h.Skeleton.IndexOf("Hat"), Is.EqualTo(-1));
            Assert.That(h.Skeleton.IndexOf("Ring"), Is.EqualTo(-1));
            float Eyes(HumanoidMap map)
            {
                var pose = new SkeletonPose(map.Skeleton);
                TPoser.Apply(map, pose, RigidPose.Identity);
                return TPoser.EyePosition(map, pose, Quaternion.Identity).Y;
            }
            Assert.That(Eyes(h.Map), Is.EqualTo(Eyes(mocap)).Within(1e-4f), "the T-pose's eye height (m)");
            var bound = new HandModel(h.Map, BodySide.Left);
            var own = new HandModel(mocap, BodySide.Left);
            for (int f = 0; f < 5; f++) Approx.Near(own.TipLocal[f], bound.TipLocal[f], 1e-5f, "finger " + f + "'s tip");
        }

        /// <summary>
        /// A child of an eyeless head that is not a crown (a ponytail's root with its chain, a hat's socket, a face rig's root) is
        /// not taken for the crown, bound by bones or by names: the T-pose's head is the same both ways (a second review: kept
        /// as an end site, its name was no longer read, and the head turned 67°; bound by names, a childless one was taken too).
        /// </summary>
        [TestCase("Ponytail", true), TestCase("HatSocket", false), TestCase("FaceRoot_End", false)]
        public void AChildOfTheHeadThatIsNoCrownIsNotTakenForIt(string name, bool chain)
        {
            HumanoidMap mocap = Mocap("mocapbank_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
            int head = engine.BoneNodes[(int)HumanoidBone.Head], top = -1;
            for (int n = 0; n < engine.Names.Count; n++)
                if (engine.Parents[n] == head) top = n;
            Assume.That(top, Is.GreaterThan(0), "MocapBank's head has its End Site");
            float length = engine.LocalPositions[top].Length();
            engine.Names[top] = name;
            engine.LocalPositions[top] = Vector3.Normalize(new Vector3(0f, 1f, -1f)) * length; // up and back
            if (chain) engine.Add(name + ".001", top, new Vector3(0f, -0.05f, -0.05f), Quaternion.Identity);
            HierarchyNode[] nodes = engine.Read();
            Assert.That(HumanoidHierarchy.TryFromBones(nodes, engine.BoneNodes, 1f, out HumanoidHierarchy bound, out string error), Is.True, error);
            Assert.That(HumanoidHierarchy.TryFromNames(nodes, 1f, out HumanoidHierarchy named, out error), Is.True, error);
            // The reference: the same hierarchy without that child (and its chain), whose head has no crown.
            var without = new List<HierarchyNode>();
            var index = new int[nodes.Length];
            for (int n = 0; n < nodes.Length; n++)
            {
                index[n] = -1;
                if (n == top || (nodes[n].Parent >= 0 && index[nodes[n].Parent] < 0 && n > top && IsBelow(nodes, n, top))) continue;
                HierarchyNode node = nodes[n];
                index[n] = without.Count;
                without.Add(new HierarchyNode(node.Name, node.Parent < 0 ? -1 : index[node.Parent], node.LocalPosition, node.LocalRotation, node.LocalScale));
            }
            var bones = new int[engine.BoneNodes.Length];
            for (int b = 0; b < bones.Length; b++) bones[b] = engine.BoneNodes[b] < 0 ? -1 : index[engine.BoneNodes[b]];
            Assert.That(HumanoidHierarchy.TryFromBones(without, bones, 1f, out HumanoidHierarchy crownless, out error), Is.True, error);
            Quaternion Head(HumanoidMap map)
            {
                var pose = new SkeletonPose(map.Skeleton);
                TPoser.Apply(map, pose, RigidPose.Identity);
                return pose.World[map[HumanoidBone.Head]].Rotation;
            }
            Quaternion reference = Head(crownless.Map);
            Assert.That(Rotations.AngleDegrees(Head(bound.Map), reference), Is.LessThan(0.1f), "bound by bones: the T-pose's head as without that child (degrees)");
            Assert.That(Rotations.AngleDegrees(Head(named.Map), reference), Is.LessThan(0.1f), "bound by names (degrees)");
        }

        private static bool IsBelow(IReadOnlyList<HierarchyNode> nodes, int node, int ancestor)
        {
            for (int k = nodes[node].Parent; k >= 0; k = nodes[k].Parent)
                if (k == ancestor) return true;
            return false;
        }

        [Test]
        public void NamesThatRepeatAreMadeUnique()
        {
            HumanoidMap mocap = Mocap("mocapbank_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
            engine.Names[engine.BoneNodes[(int)HumanoidBone.LeftHand]] = "Hand";
            engine.Names[engine.BoneNodes[(int)HumanoidBone.RightHand]] = "Hand";
            Assert.That(HumanoidHierarchy.TryFromBones(engine.Read(), engine.BoneNodes, 1f, out HumanoidHierarchy h, out string error), Is.True, error);
            Assert.That(h.Map.NameOf(HumanoidBone.LeftHand), Is.Not.EqualTo(h.Map.NameOf(HumanoidBone.RightHand)));
        }

        [Test]
        public void HierarchiesThatCannotBeBoundSayWhy()
        {
            HumanoidMap mocap = Mocap("mocapbank_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
            string Why(Action<EngineHierarchy, int[]> plant)
            {
                EngineHierarchy e = EngineHierarchy.FromSkeleton(mocap, Quaternion.Identity, 1f);
                int[] bones = (int[])e.BoneNodes.Clone();
                plant(e, bones);
                Assert.That(HumanoidHierarchy.TryFromBones(e.Read(), bones, 1f, out HumanoidHierarchy h, out string error), Is.False);
                Assert.That(h, Is.Null);
                return error;
            }
            Assert.That(Why((e, b) => e.LocalScales[2] = new Vector3(1f, 2f, 1f)), Does.Contain("'Armature' has the scale (1, 2, 1)"));
            Assert.That(Why((e, b) => e.LocalScales[b[(int)HumanoidBone.Spine]] = new Vector3(-1f)), Does.Contain("uniform, positive scales"));
            Assert.That(Why((e, b) => b[(int)HumanoidBone.RightHand] = b[(int)HumanoidBone.LeftHand]), Does.Contain("plays both LeftHand and RightHand"));
            Assert.That(Why((e, b) => b[(int)HumanoidBone.Head] = -1), Does.Contain("lacks required humanoid bones: Head"));
            Assert.That(Why((e, b) => e.Parents[3] = 7), Does.Contain("must be depth-first"));
            Assert.That(Why((e, b) => e.LocalRotations[3] = new Quaternion(float.NaN, 0, 0, 1)), Does.Contain("non-finite local pose"));
            Assert.That(HumanoidHierarchy.TryFromBones(engine.Read(), engine.BoneNodes, 0f, out _, out string scale), Is.False);
            Assert.That(scale, Does.Contain("must be positive"));
            Assert.Throws<ArgumentException>(() => HumanoidHierarchy.TryFromBones(engine.Read(), new int[3], 1f, out _, out _));
        }

        [Test]
        public void WithoutABoneMapTheNamesFindTheBones()
        {
            HumanoidMap mocap = Mocap("mixamo_fingers_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, BlenderArmature, 0.01f);
            Assert.That(HumanoidHierarchy.TryFromNames(engine.Read(), 1f, out HumanoidHierarchy h, out string error), Is.True, error);
            Assert.That(h.JointCount, Is.EqualTo(engine.Names.Count), "every transform is a joint");
            foreach (HumanoidBone b in HumanoidBones.Required)
                Assert.That(h.NodeOf(h.Map[b]), Is.EqualTo(engine.BoneNodes[(int)b]), b.ToString());
            var bare = new EngineHierarchy();
            bare.Add("Root", -1, Vector3.Zero, Quaternion.Identity);
            bare.Add("Cube", 0, Vector3.UnitY, Quaternion.Identity);
            Assert.That(HumanoidHierarchy.TryFromNames(bare.Read(), 1f, out _, out error), Is.False);
            Assert.That(error, Does.StartWith("the avatar lacks required humanoid bones: ").And.Contain("LeftUpperLeg"));
        }

        // The TransformDriver's twin: the pipeline's pose (walk-in T-pose, then the solve) written back as the binding does
        // it puts every bone of the engine hierarchy where the core's pose has it.
        [TestCase(1f)]
        [TestCase(0.01f)]
        public void ASolvedPoseWrittenBackPutsEveryBoneWhereTheCorePutsIt(float armatureScale)
        {
            HumanoidMap mocap = Mocap("mixamo_fingers_30fps.bvh");
            EngineHierarchy engine = EngineHierarchy.FromSkeleton(mocap, BlenderArmature, armatureScale);
            engine.LocalScales[0] = new Vector3(1.5f); // the avatar's root was scaled in the scene
            Assert.That(HumanoidHierarchy.TryFromBones(engine.Read(), engine.BoneNodes, 1.5f, out HumanoidHierarchy h, out string error), Is.True, error);
            var settings = new PipelineSettings();
            settings.LeftHand.Controller = settings.RightHand.Controller = ControllerProfile.Parse(System.IO.File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/vive-wand.json")));
            string session = Sessions.Simulate("mocapbank_30fps.bvh");
            var space = new TrackingSpace(new RigidPose(new Vector3(2f, 0.5f, -3f), Rotations.AngleAxis(30f, Vector3.UnitY)), 1.25f);
            Vector3 bindScale = engine.LocalScales[0];
            float worst = 0f;
            int frames = 0, walkIn = 0;
            using (SessionReader reader = Sessions.Read(session))
            {
                var pipeline = new SelfAvatarPipeline(reader.Header.Devices, h.Map, settings);
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame))
                {
                    pipeline.Update(frame);
                    SkeletonPose pose = pipeline.Pose;
                    if (pose == null) continue;
                    if (pipeline.State == CalibrationState.WalkIn) walkIn++;
                    float s = pipeline.Profile.AvatarScale;
                    RigidPose root = space.ToWorld(pose.World[0]);
                    engine.LocalPositions[0] = root.Position;
                    engine.LocalRotations[0] = root.Rotation;
                    engine.LocalScales[0] = bindScale * h.RootScaleFactor(s, space.Scale);
                    for (int j = 1; j < h.JointCount; j++)
                    {
                        engine.LocalRotations[h.NodeOf(j)] = pose.Local[j].Rotation;
                        engine.LocalPositions[h.NodeOf(j)] = h.ToLocalPosition(j, pose.Local[j].Position, s);
                    }
                    if (frames++ % 10 != 0) continue;
                    for (int j = 0; j < h.JointCount; j++)
                        worst = Math.Max(worst, Vector3.Distance(engine.WorldPosition(h.NodeOf(j)), space.ToWorld(pose.World[j].Position)));
                }
                Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated));
            }
            Assert.That(walkIn, Is.GreaterThan(10), "the walk-in's T-pose was written too");
            Assert.That(worst, Is.LessThan(1e-4f), "every bone, fingers included, where the core's pose has it (world units)");
        }
    }
}
