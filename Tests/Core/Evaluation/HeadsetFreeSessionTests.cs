using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The engine-free twin of the headset-free sample (Samples~/HeadsetFree): the session it writes from the bundled
    /// clip's text, played through the pipeline onto a mannequin of the same skeleton, calibrates from the session's own
    /// presses and follows the true joints as closely as `avatargo evaluate` says; a broken clip or an unwritable path
    /// fails with the usual typed errors and leaves an earlier session file as it was.
    /// </summary>
    public class HeadsetFreeSessionTests
    {
        private const string SampleMotion = "Samples~/HeadsetFree/Motion/mixamo_fingers_30fps.bvh.txt";

        private string _folder;

        [SetUp]
        public void MakeFolder() => Directory.CreateDirectory(_folder = Path.Combine(Path.GetTempPath(), "avatargo-sample-" + Guid.NewGuid().ToString("N")));

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_folder, true);

        [Test]
        public void TheSamplesSessionCalibratesAndFollowsTheWearer()
        {
            string clip = File.ReadAllText(TestData.InPackage(SampleMotion));
            string path = Path.Combine(_folder, "AvatarGo", "headset-free.agsession");
            HumanoidMap wearer = HeadsetFreeSession.Write(clip, "mixamo_fingers_30fps.bvh.txt", path, new SimulationOptions { Rate = 60 });

            // What the sample does with it: a mannequin of the wearer's skeleton is the avatar, the session plays through it.
            MannequinBlueprint mannequin = MannequinBlueprint.Create(wearer);
            Assert.That(mannequin.HumanBones.Count, Is.EqualTo(wearer.Count));
            var meter = new TruthErrorMeter();
            using (SessionReader reader = SessionReader.Open(path))
            {
                Assert.That(reader.Header.Rate, Is.EqualTo(60));
                Assert.That(reader.Header.TruthHumanoid.Skeleton.JointCount, Is.EqualTo(wearer.Skeleton.JointCount));
                var pipeline = new SelfAvatarPipeline(reader.Header.Devices, wearer);
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame))
                {
                    pipeline.Update(frame);
                    meter.Measure(pipeline.ScaledAvatar, pipeline.Pose, frame, pipeline.State);
                }
                Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), "the session's own trigger presses calibrate");
            }
            Assert.That(meter.Frames, Is.GreaterThan(150), "the motion after calibration (3.3 s at 60 Hz)");
            // The figures of pipeline.md for this clip with exact offsets (MPJPE about 11 mm, end effectors a few mm).
            Assert.That(meter.MeanMm, Is.LessThan(20), "MPJPE (mm)");
            Assert.That(meter.MeanEndEffectorMm, Is.LessThan(8), "end effectors (mm)");
        }

        /// <summary>
        /// The sample as Unity binds its mannequin: the blueprint's joints as transforms with one drawn primitive under each
        /// (what MannequinBuilder makes and HumanoidBinding.Flatten reads), the Animator IK driver's spine as bound. It follows
        /// the wearer as closely as the wearer's own skeleton does (found in review: the capsules under the last finger and toe
        /// joints were taken for their tips and the crown was dropped: MPJPE 22.1 against 9.9 mm, end effectors 16.6 mm).
        /// </summary>
        [Test]
        public void TheSampleFollowsTheWearerOnTheMannequinAsUnityBindsIt()
        {
            string clip = File.ReadAllText(TestData.InPackage(SampleMotion));
            string path = Path.Combine(_folder, "s.agsession");
            HumanoidMap wearer = HeadsetFreeSession.Write(clip, "mixamo_fingers_30fps.bvh.txt", path, new SimulationOptions { Seed = 1 });
            List<HierarchyNode> nodes = AsUnityBuildsIt(MannequinBlueprint.Create(wearer), out int[] bones);
            Assert.That(HumanoidHierarchy.TryFromBones(nodes, bones, 1f, out HumanoidHierarchy bound, out string error), Is.True, error);
            for (int j = 0; j < bound.Skeleton.JointCount; j++)
                Assert.That(nodes[bound.NodeOf(j)].HasRenderer, Is.False, $"{bound.Skeleton.GetName(j)} is a drawn primitive");
            (double mpjpe, double endEffectors) Run(HumanoidMap avatar, bool spineAsBound)
            {
                var meter = new TruthErrorMeter();
                var settings = new PipelineSettings();
                settings.Calibration.SpineJointsAsBound = spineAsBound;
                using SessionReader reader = SessionReader.Open(path);
                var pipeline = new SelfAvatarPipeline(reader.Header.Devices, avatar, settings);
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame))
                {
                    pipeline.Update(frame);
                    meter.Measure(pipeline.ScaledAvatar, pipeline.Pose, frame, pipeline.State);
                }
                return (meter.MeanMm, meter.MeanEndEffectorMm);
            }
            var own = Run(wearer, false);
            var unity = Run(bound.Map, true);
            TestContext.WriteLine($"MPJPE / end effectors (mm): the wearer's skeleton {own.mpjpe:F2} / {own.endEffectors:F2}, the mannequin as bound {unity.mpjpe:F2} / {unity.endEffectors:F2}");
            Assert.That(unity.mpjpe, Is.EqualTo(own.mpjpe).Within(0.5), "MPJPE (mm)");
            Assert.That(unity.endEffectors, Is.EqualTo(own.endEffectors).Within(0.5), "end effectors (mm)");
        }

        // The node list HumanoidBinding.Flatten reads from the objects MannequinBuilder.Build makes: the root, the
        // blueprint's joints in order (each parented as it is created), then each joint's primitives (drawn) after its children.
        private static List<HierarchyNode> AsUnityBuildsIt(MannequinBlueprint blueprint, out int[] boneNodes)
        {
            int n = blueprint.Joints.Count;
            var children = new List<int>[n + 1]; // 0: the root; joint i is i + 1
            var parts = new List<MannequinPart>[n + 1];
            for (int i = 0; i <= n; i++) { children[i] = new List<int>(); parts[i] = new List<MannequinPart>(); }
            for (int i = 0; i < n; i++) children[blueprint.Joints[i].Parent + 1].Add(i + 1);
            foreach (MannequinPart part in blueprint.Parts) parts[part.Joint + 1].Add(part);
            var nodes = new List<HierarchyNode>();
            var nodeOf = new int[n + 1];
            void Add(int t, int parent)
            {
                int index = nodes.Count;
                nodeOf[t] = index;
                nodes.Add(t == 0
                    ? new HierarchyNode(blueprint.RootName, -1, Vector3.Zero, Quaternion.Identity, Vector3.One)
                    : new HierarchyNode(blueprint.Joints[t - 1].Name, parent, blueprint.Joints[t - 1].Local.Position, blueprint.Joints[t - 1].Local.Rotation, Vector3.One));
                foreach (int c in children[t]) Add(c, index);
                foreach (MannequinPart m in parts[t]) nodes.Add(new HierarchyNode("Capsule", index, m.Centre, m.Rotation, m.PrimitiveScale, hasRenderer: true));
            }
            Add(0, -1);
            boneNodes = new int[HumanoidBones.Count];
            for (int b = 0; b < boneNodes.Length; b++) boneNodes[b] = -1;
            var byName = new Dictionary<string, int>();
            for (int i = 0; i < n; i++) byName[blueprint.Joints[i].Name] = nodeOf[i + 1];
            foreach (KeyValuePair<HumanoidBone, string> bone in blueprint.HumanBones) boneNodes[(int)bone.Key] = byName[bone.Value];
            return nodes;
        }

        [Test]
        public void TheSamplesMotionIsTheTestClipWithPlainWhitespace()
        {
            // The sample ships the Mixamo clip as a text asset with LF line ends and spaces (PVS checks .txt files).
            BvhClip shipped = BvhReader.ReadFile(TestData.InPackage(SampleMotion), new BvhReadOptions { ToMetres = true });
            BvhClip test = BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true });
            Assert.That(shipped.Skeleton.Names, Is.EqualTo(test.Skeleton.Names));
            Assert.That(shipped.FrameCount, Is.EqualTo(test.FrameCount));
            var a = new RigidPose[shipped.Skeleton.JointCount];
            var b = new RigidPose[test.Skeleton.JointCount];
            for (int f = 0; f < shipped.FrameCount; f += 37)
            {
                shipped.GetLocalPoses(f, a);
                test.GetLocalPoses(f, b);
                for (int j = 0; j < a.Length; j++) Approx.Near(b[j], a[j], 1e-6f, 1e-3f, $"frame {f} {shipped.Skeleton.GetName(j)}");
            }
        }

        [Test]
        public void ABrokenClipFailsWithItsLineAndKeepsTheEarlierSession()
        {
            string path = Path.Combine(_folder, "s.agsession");
            File.WriteAllText(path, "earlier");
            string clip = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            var e = Assert.Throws<FormatException>(() => HeadsetFreeSession.Write(clip.Replace("CHANNELS 6", "CHANNELS 6x"), "clip.bvh.txt", path));
            Assert.That(e.Message, Does.StartWith("clip.bvh.txt:"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("earlier"));
            Assert.That(Directory.GetFiles(_folder), Has.Length.EqualTo(1), "no temporary file left");
        }
    }
}
