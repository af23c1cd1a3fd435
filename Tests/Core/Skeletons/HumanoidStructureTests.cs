using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.RegularExpressions;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// <see cref="HumanoidStructure"/>: the humanoid bones found from the hierarchy and the motion, the names unread. Each
    /// shared clip with every joint renamed <c>j0</c>, <c>j1</c>, … must map the same joints as its names do (every bone
    /// the structure looks for: hips, spine, chest, neck, head, clavicles, limbs, toes), in its own rest and rebased, with
    /// twist joints, under a floor root, with the CMU conversion's joints at the hips, mirrored (sides named the other way:
    /// the structure reads sides from the body, not the names) and without clavicles; what is not a humanoid is refused
    /// with a reason.
    /// </summary>
    public class HumanoidStructureTests
    {
        private static readonly HumanoidBone[] Read =
        {
            HumanoidBone.Hips, HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.UpperChest, HumanoidBone.Neck, HumanoidBone.Head,
            HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot, HumanoidBone.LeftToes,
            HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot, HumanoidBone.RightToes,
            HumanoidBone.LeftShoulder, HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand,
            HumanoidBone.RightShoulder, HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, HumanoidBone.RightHand,
        };

        internal static readonly string[] Clips = { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps_first240.bvh" };

        private static BvhClip Clip(string file) => BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true });

        /// <summary><paramref name="clip"/> with every joint named by its index (<c>j0</c>, …): no name says anything.</summary>
        internal static BvhClip Numbered(BvhClip clip)
        {
            var text = new StringWriter();
            BvhWriter.Write(text, clip);
            int next = 0;
            string numbered = Regex.Replace(text.ToString(), @"^(\s*(?:ROOT|JOINT)\s+)(\S+)", m => m.Groups[1].Value + "j" + next++, RegexOptions.Multiline);
            return BvhReader.Read(new StringReader(numbered), "numbered", new BvhReadOptions { ToMetres = true });
        }

        /// <summary>Asserts that the structure of the numbered clip maps, bone by bone, the joints the names map in <paramref name="named"/>.</summary>
        private static void AssertSameBones(BvhClip named, string what)
        {
            HumanoidMap byNames = HumanoidNaming.Detect(named.Skeleton);
            Assert.That(byNames.IsComplete, Is.True, $"{what}: the names");
            BvhClip numbered = Numbered(named);
            Assert.That(HumanoidNaming.Detect(numbered.Skeleton).IsComplete, Is.False, $"{what}: numbered names say nothing");
            HumanoidMap byStructure = HumanoidStructure.Detect(numbered, out string failure);
            Assert.That(byStructure, Is.Not.Null, $"{what}: {failure}");
            foreach (HumanoidBone bone in Read)
                Assert.That(byStructure[bone], Is.EqualTo(byNames[bone]),
                    $"{what}: {bone} is {(byNames[bone] < 0 ? "none" : named.Skeleton.GetName(byNames[bone]))} by its name, " +
                    $"{(byStructure[bone] < 0 ? "none" : named.Skeleton.GetName(byStructure[bone]))} by the structure");
        }

        [TestCaseSource(nameof(Clips))]
        public void TheStructureFindsTheBonesTheNamesDo(string file) => AssertSameBones(Clip(file), file);

        [TestCaseSource(nameof(Clips))]
        public void TheStructureDoesNotDependOnTheRestConvention(string file)
        {
            foreach (var c in RestConventionTests.Conventions)
                AssertSameBones(RestConventionTests.Rebased(TestData.Mocap(file), c), $"{file} {c.rest} {c.twist}° seed {c.seed}");
        }

        [TestCaseSource(nameof(Clips))]
        public void TheStructureReadsOtherTopologies(string file)
        {
            BvhClip clip = Clip(file);
            AssertSameBones(Topology.WithTwistJoints(clip), $"{file} with twist joints");
            AssertSameBones(Topology.WithFloorRoot(clip), $"{file} under a floor root");
            AssertSameBones(Topology.Mirrored(clip), $"{file} mirrored");
        }

        /// <summary>The CMU conversion's hierarchy: a joint at the hips above each thigh and the spine, a second neck joint.</summary>
        [Test]
        public void TheStructureReadsTheCmuConversionsHierarchy()
        {
            BvhClip clip = Clip("mocapbank_30fps.bvh");
            BvhClip cmu = Topology.WithJointsAbove(clip, ("LeftHip", "LHipJoint", 0f), ("RightHip", "RHipJoint", 0f), ("Chest", "LowerBack", 0f), ("Head", "Neck1", 0.5f));
            AssertSameBones(cmu, "the CMU conversion's hierarchy");
        }

        [Test]
        public void TheStructureReadsARigWithoutClavicles()
        {
            BvhClip clip = Clip("mocapbank_30fps.bvh");
            Skeleton s = clip.Skeleton;
            BvhClip without = Topology.Without(clip, s.IndexOf("LeftCollar"), s.IndexOf("RightCollar"));
            AssertSameBones(without, "without clavicles");
        }

        /// <summary>The same motion named or numbered gives the same avatar: the numbered clip calibrates and its figures are the original's.</summary>
        [Test]
        public void ANumberedClipGivesTheSameAvatarAsItsNamedOriginal()
        {
            BvhClip named = Clip("mocapbank_30fps.bvh");
            BvhClip numbered = Numbered(named);
            HumanoidMap map = HumanoidStructure.Detect(numbered, out string failure);
            Assert.That(map, Is.Not.Null, failure);
            EvaluationReport own = Evaluate(named, HumanoidNaming.Detect(named.Skeleton)), other = Evaluate(numbered, map);
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.Frames, Is.EqualTo(own.Frames));
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.01), "MPJPE (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.01), "elbows and knees median (mm)");
        }

        private static EvaluationReport Evaluate(BvhClip clip, HumanoidMap map)
        {
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 2 }, map);
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            using var reader = new SessionReader(new StringReader(text.ToString()), "structure");
            return SessionEvaluator.Evaluate(reader, new PipelineSettings());
        }

        [Test]
        public void AChainIsNotAHumanoid()
        {
            // Ten joints in a line, bending: no joint where three long branches meet.
            var names = Enumerable.Range(0, 10).Select(i => "j" + i).ToArray();
            var parents = Enumerable.Range(-1, 10).ToArray();
            var rest = Enumerable.Range(0, 10).Select(i => new RigidPose(i == 0 ? Vector3.Zero : new Vector3(0.2f, 0f, 0f), Quaternion.Identity)).ToArray();
            var skeleton = new Skeleton(names, parents, rest);
            var frames = new List<Vector3[]>();
            for (int f = 0; f < 10; f++)
            {
                var p = new Vector3[10];
                for (int j = 1; j < 10; j++) p[j] = p[j - 1] + new Vector3(0.2f * System.MathF.Cos(0.1f * f * j), 0.2f * System.MathF.Sin(0.1f * f * j), 0f);
                frames.Add(p);
            }
            Assert.That(HumanoidStructure.Detect(skeleton, frames, out string failure), Is.Null);
            Assert.That(failure, Does.Contain("three long branches"));
        }

        [Test]
        public void AHumanoidThatNeverBendsItsLimbsIsRefusedWithTheReason()
        {
            // The MocapBank skeleton in one frame with its knees and elbows straight cannot show where they are.
            BvhClip clip = Numbered(Clip("mocapbank_30fps.bvh"));
            Skeleton s = clip.Skeleton;
            var local = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            s.GetRestLocal(local);
            for (int j = 0; j < s.JointCount; j++) local[j] = new RigidPose(local[j].Position, Quaternion.Identity);
            s.ComputeWorld(local, world);
            Vector3[] positions = world.Select(w => w.Position).ToArray();
            Assert.That(HumanoidStructure.Detect(s, new[] { positions }, out string failure), Is.Null);
            Assert.That(failure, Does.Contain("bend"), failure);
        }
    }
}
