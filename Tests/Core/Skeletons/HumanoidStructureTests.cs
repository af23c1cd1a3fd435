using System;
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

        /// <summary><paramref name="clip"/> written as BVH and read again (metres): its joints in depth-first order.</summary>
        private static BvhClip ReadBack(BvhClip clip)
        {
            var text = new StringWriter();
            BvhWriter.Write(text, clip);
            return BvhReader.Read(new StringReader(text.ToString()), "read back", new BvhReadOptions { ToMetres = true });
        }

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
            named = ReadBack(named); // in the order a file lists the joints, which Numbered keeps
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

        /// <summary>
        /// <paramref name="clip"/> with joints added (each under a named parent, at an offset in its parent's frame); each
        /// added joint that is not an End Site swings about its X axis, 0.02 rad a frame.
        /// </summary>
        private static BvhClip WithAdded(BvhClip clip, params (string name, string parent, Vector3 offset, bool endSite)[] added)
        {
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var names = new List<string>(s.Names);
            var parents = Enumerable.Range(0, n).Select(s.GetParent).ToList();
            var rest = Enumerable.Range(0, n).Select(s.GetRestLocal).ToList();
            var ends = Enumerable.Range(0, n).Select(s.IsEndSite).ToList();
            foreach (var a in added)
            {
                parents.Add(names.IndexOf(a.parent));
                names.Add(a.name);
                rest.Add(new RigidPose(a.offset, Quaternion.Identity));
                ends.Add(a.endSite);
            }
            var skeleton = new Skeleton(names, parents, rest, ends);
            var frames = new List<RigidPose[]>();
            for (int f = 0; f < clip.FrameCount; f++)
            {
                var local = new RigidPose[names.Count];
                clip.GetLocalPoses(f, local.AsSpan(0, n));
                for (int k = 0; k < added.Length; k++)
                    local[n + k] = new RigidPose(added[k].offset, added[k].endSite ? Quaternion.Identity : Quaternion.CreateFromAxisAngle(Vector3.UnitX, 0.02f * f));
                frames.Add(local);
            }
            return BvhClip.FromPoses(skeleton, frames, clip.FrameTime);
        }

        /// <summary>A ponytail hanging from the head (a VRoid or MMD model's hair chain) is not the head (found in review: its last joint was).</summary>
        [TestCaseSource(nameof(Clips))]
        public void AHairChainOnTheHeadIsNotTheHead(string file)
        {
            BvhClip clip = Clip(file);
            string head = HumanoidNaming.Detect(clip.Skeleton).NameOf(HumanoidBone.Head);
            var hair = new List<(string, string, Vector3, bool)>();
            for (int k = 0; k < 5; k++) hair.Add(($"pt{k}", k == 0 ? head : $"pt{k - 1}", new Vector3(0f, -0.06f, -0.02f), false));
            hair.Add(("pt_end", "pt4", new Vector3(0f, -0.06f, -0.02f), true));
            AssertSameBones(WithAdded(clip, hair.ToArray()), $"{file} with a ponytail");
        }

        /// <summary>
        /// Joints in one place: a sword gripped at the wrist (its own joint on the wrist, a metre long) and a joint inserted on
        /// the upper arm's: the first of them is the limb's joint (found in review: the sword became the hand, the inserted
        /// joint the upper arm).
        /// </summary>
        [Test]
        public void OfJointsInOnePlaceTheFirstIsTheLimbsJoint()
        {
            BvhClip clip = Clip("mocapbank_30fps.bvh");
            AssertSameBones(WithAdded(clip, ("sword", "RightWrist", Vector3.Zero, false), ("sword_tip", "sword", new Vector3(0f, 0f, 1f), true)), "a sword at the wrist");
            AssertSameBones(Topology.WithJointsAbove(clip, ("LeftElbow", "ez", 0f), ("RightElbow", "ez2", 0f)), "a joint on the upper arm's");
        }

        /// <summary>
        /// A clip whose knees never bend cannot show them; nor can an arm with nothing beyond its last joint tell the hand
        /// from the elbow. Both are refused, not read wrong (found in review: Mixamo's straight-legged clip read foot and toe
        /// as thigh and shin, and Rigify's arms without their End Sites were shifted by a joint, both with sides swapped).
        /// </summary>
        [Test]
        public void LimbsTheMotionCannotShowAreRefusedNotMisread()
        {
            BvhClip mixamo = Clip("mixamo_fingers_30fps.bvh");
            HumanoidMap names = HumanoidNaming.Detect(mixamo.Skeleton);
            Skeleton s = mixamo.Skeleton;
            var frames = new List<RigidPose[]>();
            for (int f = 0; f < mixamo.FrameCount; f++)
            {
                var local = new RigidPose[s.JointCount];
                mixamo.GetLocalPoses(f, local);
                foreach (HumanoidBone knee in new[] { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg })
                    local[names[knee]] = new RigidPose(local[names[knee]].Position, Quaternion.Identity);
                frames.Add(local);
            }
            BvhClip straight = Numbered(BvhClip.FromPoses(s, frames, mixamo.FrameTime));
            Assert.That(HumanoidStructure.Detect(straight, out string why), Is.Null, "knees held straight");
            StringAssert.Contains("no two long segments", why);

            BvhClip rigify = Clip("rigify_6channel_24fps_first240.bvh");
            int[] ends = Enumerable.Range(0, rigify.Skeleton.JointCount).Where(j => rigify.Skeleton.GetName(j).StartsWith("forearm") && rigify.Skeleton.IsEndSite(j)).ToArray();
            Assert.That(ends.Length, Is.EqualTo(2));
            BvhClip handless = Numbered(Topology.Without(rigify, ends));
            Assert.That(HumanoidStructure.Detect(handless, out why), Is.Null, "forearms with nothing beyond");
            StringAssert.Contains("nothing beyond it", why);
        }

        /// <summary>
        /// One glitched frame (Rigify's knee, which has position channels, 50 m off) changes nothing: lengths are medians and
        /// a joint must bend in two frames at least and one in fifty (found in review: the mean lengths refused the clip).
        /// </summary>
        [Test]
        public void OneGlitchedFrameChangesNothing()
        {
            BvhClip clip = Clip("rigify_6channel_24fps_first240.bvh");
            Skeleton s = clip.Skeleton;
            int knee = s.IndexOf("shin.L");
            var frames = new List<RigidPose[]>();
            for (int f = 0; f < clip.FrameCount; f++)
            {
                var local = new RigidPose[s.JointCount];
                clip.GetLocalPoses(f, local);
                if (f == 100) local[knee] = local[knee].WithPosition(local[knee].Position + new Vector3(50f, 0f, 0f)); // a sampled frame
                frames.Add(local);
            }
            AssertSameBones(BvhClip.FromPoses(s, frames, clip.FrameTime), "a knee 50 m off in one frame");
        }

        /// <summary>
        /// In a short clip (60 frames, all of them read) a twist joint bent 40° in one frame is still a twist joint (found in
        /// review: one bent frame in fewer than a hundred made it the elbow and shifted the arm by a joint).
        /// </summary>
        [Test]
        public void ATwistJointGlitchedInOneFrameOfAShortClipIsNotAJoint()
        {
            BvhClip clip = Topology.WithTwistJoints(Clip("mocapbank_30fps.bvh"));
            Skeleton s = clip.Skeleton;
            int twist = s.IndexOf("LeftForeArmTwist");
            var frames = new List<RigidPose[]>();
            for (int f = 0; f < 60; f++)
            {
                var local = new RigidPose[s.JointCount];
                clip.GetLocalPoses(f, local);
                if (f == 30) local[twist] = local[twist].WithRotation(Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 40f * MathF.PI / 180f) * local[twist].Rotation);
                frames.Add(local);
            }
            AssertSameBones(BvhClip.FromPoses(s, frames, clip.FrameTime), "a twist joint bent in one of 60 frames");
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
