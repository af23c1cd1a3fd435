using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The mannequin the samples build from a skeleton: its joints stand where the canonical T-pose puts them, every bone
    /// segment is drawn from joint to joint, the humanoid bones are named for Unity's avatar builder, and none of it
    /// depends on how the skeleton's rest pose or local axes are expressed.
    /// </summary>
    public class MannequinBlueprintTests
    {
        private static readonly string[] Clips = { "mocapbank_30fps.bvh", "mixamo_fingers_30fps.bvh", "rigify_6channel_24fps_first240.bvh" };

        private static BvhClip Load(string file) => BvhReader.ReadFile(TestData.Mocap(file), new BvhReadOptions { ToMetres = true });

        // World poses of the blueprint's joints, composed from their locals (as Unity's transforms would).
        private static RigidPose[] World(MannequinBlueprint b)
        {
            var world = new RigidPose[b.Joints.Count];
            for (int i = 0; i < world.Length; i++)
            {
                MannequinJoint j = b.Joints[i];
                Assert.That(j.Parent, Is.LessThan(i), $"{j.Name}: parents come first");
                world[i] = j.Parent < 0 ? j.Local : world[j.Parent] * j.Local;
            }
            return world;
        }

        private static (Vector3 a, Vector3 b) Ends(MannequinPart part, RigidPose[] world)
        {
            RigidPose joint = world[part.Joint];
            Vector3 axis = Vector3.Transform(Vector3.UnitY, part.Rotation) * (part.Length * 0.5f);
            return (joint.TransformPoint(part.Centre - axis), joint.TransformPoint(part.Centre + axis));
        }

        [TestCaseSource(nameof(Clips))]
        public void TheJointsStandInTheTPoseAndEverySegmentIsDrawnBetweenItsJoints(string file)
        {
            BvhClip clip = Load(file);
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            MannequinBlueprint blueprint = MannequinBlueprint.Create(map);
            var tpose = new SkeletonPose(clip.Skeleton);
            TPoser.Apply(map, tpose, RigidPose.Identity);
            RigidPose[] world = World(blueprint);

            var names = new HashSet<string>();
            foreach (MannequinJoint j in blueprint.Joints) Assert.That(names.Add(j.Name), Is.True, $"{j.Name} is unique");
            // Every joint, end sites too: the binding takes them for the fingertips, toes' tips and crown.
            Assert.That(blueprint.Joints.Count, Is.EqualTo(clip.Skeleton.JointCount), "every joint of the skeleton, end sites too");
            Assert.That(names, Does.Not.Contain(blueprint.RootName));
            for (int i = 0; i < world.Length; i++)
                Approx.Near(tpose.World[blueprint.Joints[i].SkeletonJoint], world[i], 1e-4f, 0.05f, blueprint.Joints[i].Name);
            foreach (KeyValuePair<HumanoidBone, string> bone in blueprint.HumanBones)
                Assert.That(names, Does.Contain(bone.Value), $"{bone.Key} is a joint of the mannequin");
            Assert.That(blueprint.HumanBones.Count, Is.EqualTo(map.Count));

            // Each capsule runs from its joint to a child joint (or end site) of the T-pose: both caps on joints.
            int capsules = 0;
            foreach (MannequinPart part in blueprint.Parts)
            {
                Assert.That(part.Radius, Is.GreaterThan(0f).And.LessThan(0.2f));
                if (part.Shape != MannequinShape.Capsule) continue;
                capsules++;
                var (a, b) = Ends(part, world);
                Approx.Near(world[part.Joint].Position, a, 1e-4f, "capsule starts at its joint");
                float nearest = float.MaxValue;
                int skeletonJoint = blueprint.Joints[part.Joint].SkeletonJoint;
                for (int c = 0; c < clip.Skeleton.JointCount; c++)
                    if (clip.Skeleton.GetParent(c) == skeletonJoint) nearest = Math.Min(nearest, Vector3.Distance(tpose.World[c].Position, b));
                Assert.That(nearest, Is.LessThan(1e-4f), "capsule ends at a child");
            }
            int segments = 0;
            for (int c = 0; c < clip.Skeleton.JointCount; c++)
            {
                int p = clip.Skeleton.GetParent(c);
                if (p < 0 || p == map[HumanoidBone.Head] || clip.Skeleton.GetRestLocal(c).Position.Length() < MannequinBlueprint.ShortestDrawnSegment) continue;
                bool bodyBelow = false;
                for (int d = c; d < clip.Skeleton.JointCount; d++)
                    if (clip.Skeleton.IsAncestorOrSelf(c, d) && map.BoneOf(d) != HumanoidBone.LastBone) bodyBelow = true;
                if (bodyBelow || map.BoneOf(p) != HumanoidBone.LastBone) segments++;
            }
            Assert.That(capsules, Is.EqualTo(segments), "one capsule per segment of the body (the head's are one sphere, helper branches are not drawn)");
            Assert.That(blueprint.Stature, Is.InRange(1.2f, 2.1f), "a grown-up's stature from the hip height");
        }

        [TestCaseSource(nameof(Clips))]
        public void TheMannequinDoesNotDependOnTheRestPoseOrTheLocalAxes(string file)
        {
            BvhClip clip = Load(file);
            MannequinBlueprint reference = MannequinBlueprint.Create(HumanoidNaming.Detect(clip.Skeleton));
            RigidPose[] referenceWorld = World(reference);
            foreach (BvhClip other in new[] { BvhRebaser.AlongX(clip), BvhRebaser.RandomAxes(clip, 4), BvhRebaser.RandomAxes(clip, 5) })
            {
                MannequinBlueprint b = MannequinBlueprint.Create(HumanoidNaming.Detect(other.Skeleton));
                RigidPose[] w = World(b);
                Assert.That(b.Parts.Count, Is.EqualTo(reference.Parts.Count));
                Assert.That(b.Stature, Is.EqualTo(reference.Stature).Within(1e-4f));
                for (int i = 0; i < b.Parts.Count; i++)
                {
                    MannequinPart p0 = reference.Parts[i], p1 = b.Parts[i];
                    Assert.That(p1.Shape, Is.EqualTo(p0.Shape));
                    if (p0.Shape == MannequinShape.Sphere)
                    {
                        // A sphere has no axis: its centre is what must not move.
                        Approx.Near(referenceWorld[p0.Joint].TransformPoint(p0.Centre), w[p1.Joint].TransformPoint(p1.Centre), 1e-4f, $"sphere {i}");
                        continue;
                    }
                    var (a0, b0) = Ends(p0, referenceWorld);
                    var (a1, b1) = Ends(p1, w);
                    Approx.Near(a0, a1, 1e-4f, $"part {i} start");
                    Approx.Near(b0, b1, 1e-4f, $"part {i} end, on {b.Joints[p1.Joint].Name}");
                    Assert.That(b.Parts[i].Radius, Is.EqualTo(reference.Parts[i].Radius).Within(1e-5f));
                }
            }
        }

        /// <summary>
        /// A twist joint halfway along each upper arm, forearm, thigh and shin (every other joint's world pose kept) draws
        /// each limb as two capsules as thick as the one without it (found in review: a fifth of each half's length, so
        /// the upper arm was 25.6 mm thick instead of 51.2 mm).
        /// </summary>
        [Test]
        public void TwistJointsDoNotThinTheLimbs()
        {
            BvhClip clip = Load("mocapbank_30fps.bvh");
            HumanoidMap plainMap = HumanoidNaming.Detect(clip.Skeleton);
            BvhClip twisted = Topology.WithTwistJoints(clip);
            HumanoidMap twistedMap = HumanoidNaming.Detect(twisted.Skeleton);
            MannequinBlueprint plain = MannequinBlueprint.Create(plainMap), withTwists = MannequinBlueprint.Create(twistedMap);
            foreach (var (bone, next, twist) in Topology.TwistedBones)
            {
                float expected = RadiusFrom(plain, plainMap.Skeleton.GetName(plainMap[bone]));
                float first = RadiusFrom(withTwists, twistedMap.Skeleton.GetName(twistedMap[bone]));
                float second = RadiusFrom(withTwists, twist);
                Assert.That(first, Is.EqualTo(expected).Within(1e-4f), $"{bone} to its twist joint");
                Assert.That(second, Is.EqualTo(expected).Within(1e-4f), $"{twist} to {next}");
            }
        }

        // The radius of the capsule that hangs from the named joint (its first).
        private static float RadiusFrom(MannequinBlueprint b, string joint)
        {
            for (int i = 0; i < b.Parts.Count; i++)
                if (b.Parts[i].Shape == MannequinShape.Capsule && b.Joints[b.Parts[i].Joint].Name == joint) return b.Parts[i].Radius;
            throw new AssertionException($"no capsule hangs from {joint}");
        }

        [Test]
        public void PartsScaleWithTheBody()
        {
            BvhClip clip = Load("mocapbank_30fps.bvh");
            MannequinBlueprint adult = MannequinBlueprint.Create(HumanoidNaming.Detect(clip.Skeleton));
            MannequinBlueprint small = MannequinBlueprint.Create(HumanoidNaming.Detect(clip.Skeleton.Scaled(0.5f)));
            Assert.That(small.Stature, Is.EqualTo(adult.Stature * 0.5f).Within(1e-4f));
            for (int i = 0; i < adult.Parts.Count; i++)
                Assert.That(small.Parts[i].Radius, Is.EqualTo(adult.Parts[i].Radius * 0.5f).Within(1e-5f));
        }

        [Test]
        public void PrimitiveScaleGivesUnitysMeshesTheirSize()
        {
            var capsule = new MannequinPart(0, MannequinShape.Capsule, Vector3.Zero, Quaternion.Identity, 0.4f, 0.05f);
            Assert.That(capsule.PrimitiveScale, Is.EqualTo(new Vector3(0.1f, 0.2f, 0.1f)));
            var sphere = new MannequinPart(0, MannequinShape.Sphere, Vector3.Zero, Quaternion.Identity, 0.2f, 0.1f);
            Assert.That(sphere.PrimitiveScale, Is.EqualTo(new Vector3(0.2f)));
        }

        [Test]
        public void ASkeletonWithoutTheHumanoidBonesOrARootNamedLikeAJointIsRefused()
        {
            BvhClip clip = Load("mocapbank_30fps.bvh");
            HumanoidMap map = HumanoidNaming.Detect(clip.Skeleton);
            var partial = new List<KeyValuePair<HumanoidBone, string>>();
            foreach (KeyValuePair<HumanoidBone, string> p in map.Pairs()) if (p.Key != HumanoidBone.LeftFoot) partial.Add(p);
            var e = Assert.Throws<ArgumentException>(() => MannequinBlueprint.Create(new HumanoidMap(clip.Skeleton, partial)));
            Assert.That(e.Message, Does.Contain("LeftFoot"));
            e = Assert.Throws<ArgumentException>(() => MannequinBlueprint.Create(map, clip.Skeleton.GetName(0)));
            Assert.That(e.Message, Does.Contain(clip.Skeleton.GetName(0)));
        }
    }
}
