using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Everything needed to build a stand-in avatar from a skeleton with nothing but primitives: the joints as a
    /// transform hierarchy in the canonical T-pose (<see cref="TPoser"/>), one capsule per bone segment and a sphere for
    /// the head, and the humanoid bone names that make it a Unity humanoid (<c>AvatarBuilder.BuildHumanAvatar</c> takes
    /// <see cref="Joints"/> as its skeleton and <see cref="HumanBones"/> as its human bones). The samples build their
    /// mannequin from this; every decision about what goes where is taken here.
    /// </summary>
    /// <remarks>
    /// <para>Joints are listed parents first, so a builder can create them in order. End sites are joints of the mannequin
    /// too, empty transforms: a Unity humanoid does not need them, but the binding takes them for the fingertips, the toes'
    /// tip and the crown (found in review: without them it took the capsules drawn on the last segments, halfway along,
    /// for the tips). The segment to an end site is drawn from its parent. Branches of helper joints that lead to no humanoid bone (Rigify's pelvis.L and
    /// pelvis.R, a face rig) stay transforms but are not drawn: their rest rotations are all that places them, and the
    /// mannequin must not depend on how a file expresses its rest pose.</para>
    /// <para>Sizes scale with the body: <see cref="Stature"/> is estimated from the hip height in the T-pose (hips at 0.53
    /// of the stature, Drillis and Contini), so a child-sized or centimetre-unit skeleton gets proportionate parts.</para>
    /// </remarks>
    public sealed class MannequinBlueprint
    {
        /// <summary>The hip height as a fraction of the stature (Drillis and Contini's body-segment proportions).</summary>
        public const float HipHeightOfStature = 0.53f;

        /// <summary>Segments shorter than this (in metres) are not drawn: zero-length helper joints.</summary>
        public const float ShortestDrawnSegment = 0.001f;

        private readonly MannequinJoint[] _joints;
        private readonly MannequinPart[] _parts;
        private readonly KeyValuePair<HumanoidBone, string>[] _humanBones;

        private MannequinBlueprint(string rootName, float stature, MannequinJoint[] joints, MannequinPart[] parts, KeyValuePair<HumanoidBone, string>[] humanBones)
        {
            RootName = rootName;
            Stature = stature;
            _joints = joints;
            _parts = parts;
            _humanBones = humanBones;
        }

        /// <summary>The name of the mannequin's root object (the hips' parent, the first entry of a humanoid's skeleton).</summary>
        public string RootName { get; }

        /// <summary>The estimated standing height in metres (see remarks), from which the parts' radii are taken.</summary>
        public float Stature { get; }

        /// <summary>The joints, parents before children, each with its local T-pose in its parent (the root for the first).</summary>
        public IReadOnlyList<MannequinJoint> Joints => _joints;

        /// <summary>The primitives to draw, each attached to a joint of <see cref="Joints"/>.</summary>
        public IReadOnlyList<MannequinPart> Parts => _parts;

        /// <summary>Every humanoid bone the skeleton has, with the name of the joint that plays it.</summary>
        public IReadOnlyList<KeyValuePair<HumanoidBone, string>> HumanBones => _humanBones;

        /// <summary>
        /// The blueprint of <paramref name="map"/>'s skeleton, standing at the origin in the canonical T-pose, facing +Z.
        /// </summary>
        /// <param name="map">The skeleton and its humanoid bones; it must have every required bone.</param>
        /// <param name="rootName">The root object's name; it must not be the name of a joint.</param>
        /// <exception cref="ArgumentException">A required humanoid bone is missing, or the root name is a joint's.</exception>
        public static MannequinBlueprint Create(HumanoidMap map, string rootName = "Mannequin")
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (string.IsNullOrEmpty(rootName)) throw new ArgumentException("The root needs a name.", nameof(rootName));
            Skeleton skeleton = map.Skeleton;
            if (skeleton.IndexOf(rootName) >= 0) throw new ArgumentException($"The root name '{rootName}' is already a joint's name.", nameof(rootName));
            var pose = new SkeletonPose(skeleton);
            TPoser.Apply(map, pose, RigidPose.Identity);

            float stature = Math.Max(pose.World[map[HumanoidBone.Hips]].Position.Y, ShortestDrawnSegment) / HipHeightOfStature;
            MannequinJoint[] joints = JointsOf(map, pose, out int[] jointOf);
            MannequinPart[] parts = PartsOf(map, pose, jointOf, stature);
            var humanBones = new List<KeyValuePair<HumanoidBone, string>>();
            foreach (KeyValuePair<HumanoidBone, string> pair in map.Pairs()) humanBones.Add(pair);
            return new MannequinBlueprint(rootName, stature, joints, parts, humanBones.ToArray());
        }

        // The skeleton's joints, end sites too (empty transforms: the binding's fingertips, toes' tips and crown), parents
        // first; the root of the skeleton takes its world T-pose as its local pose under the mannequin's root (which stands at
        // the origin).
        private static MannequinJoint[] JointsOf(HumanoidMap map, SkeletonPose pose, out int[] jointOf)
        {
            Skeleton skeleton = map.Skeleton;
            jointOf = new int[skeleton.JointCount];
            var joints = new List<MannequinJoint>(skeleton.JointCount);
            // Skeleton joints are stored parents first (a parent's index is below its child's), so one pass keeps the order.
            for (int j = 0; j < skeleton.JointCount; j++)
            {
                jointOf[j] = -1;
                int parent = skeleton.GetParent(j);
                int parentJoint = parent >= 0 ? jointOf[parent] : -1;
                RigidPose local = parent >= 0 ? pose.Local[j] : pose.World[j];
                jointOf[j] = joints.Count;
                joints.Add(new MannequinJoint(skeleton.GetName(j), parentJoint, j, local));
            }
            return joints.ToArray();
        }

        private static MannequinPart[] PartsOf(HumanoidMap map, SkeletonPose pose, int[] jointOf, float stature)
        {
            Skeleton skeleton = map.Skeleton;
            var parts = new List<MannequinPart>(skeleton.JointCount);
            int head = map[HumanoidBone.Head];
            bool[] leadsToBody = LeadsToHumanoidBone(map);
            for (int j = 0; j < skeleton.JointCount; j++)
            {
                int parent = skeleton.GetParent(j);
                if (parent < 0 || parent == head) continue; // the head is one sphere, below
                if (!leadsToBody[j] && map.BoneOf(parent) == HumanoidBone.LastBone) continue; // a helper branch (see remarks)
                Vector3 offset = pose.Local[j].Position; // the child in its parent's frame
                float length = offset.Length();
                if (length < ShortestDrawnSegment) continue;
                float radius = RadiusOf(map, parent, j, BoneLength(map, pose, parent, j, length), stature);
                parts.Add(new MannequinPart(jointOf[parent], MannequinShape.Capsule, offset * 0.5f,
                    Rotations.FromTo(Vector3.UnitY, offset / length), length, radius));
            }
            // The head: a sphere above the head joint (up is +Y in the T-pose), so a head without an end site is drawn too.
            float headRadius = 0.06f * stature;
            RigidPose headWorld = pose.World[head];
            Vector3 centre = headWorld.InverseTransformPoint(headWorld.Position + new Vector3(0f, headRadius, 0f));
            parts.Add(new MannequinPart(jointOf[head], MannequinShape.Sphere, centre, Quaternion.Identity, 2f * headRadius, headRadius));
            return parts.ToArray();
        }

        // True for a joint that is a humanoid bone or has one below it. Only segments to such joints, or from a humanoid
        // bone to its tip, are drawn: a branch of helper joints (Rigify's pelvis.L, a face rig) hangs on rotations that no
        // landmark fixes, so drawing it would make the mannequin depend on how the file expresses its rest pose.
        private static bool[] LeadsToHumanoidBone(HumanoidMap map)
        {
            Skeleton skeleton = map.Skeleton;
            var leads = new bool[skeleton.JointCount];
            for (int j = skeleton.JointCount - 1; j >= 0; j--) // children come after their parents
            {
                if (map.BoneOf(j) != HumanoidBone.LastBone) leads[j] = true;
                int parent = skeleton.GetParent(j);
                if (leads[j] && parent >= 0) leads[parent] = true;
            }
            return leads;
        }

        // The length of the humanoid bone a segment is part of: from the humanoid joint at or above its start to the first
        // one at or below its end along an unbranched chain, so that a twist joint halfway along an arm does not halve the
        // arm's thickness (found in review: 25.6 mm against 51.2 mm on MocapBank's upper arm with twist joints).
        private static float BoneLength(HumanoidMap map, SkeletonPose pose, int parent, int child, float segment)
        {
            Skeleton skeleton = map.Skeleton;
            int start = parent;
            while (map.BoneOf(start) == HumanoidBone.LastBone && skeleton.GetParent(start) >= 0) start = skeleton.GetParent(start);
            int end = child;
            while (map.BoneOf(end) == HumanoidBone.LastBone)
            {
                int only = -1, count = 0;
                for (int k = end + 1; k < skeleton.JointCount; k++)
                    if (skeleton.GetParent(k) == end) { only = k; count++; }
                if (count != 1) break;
                end = only;
            }
            if (map.BoneOf(start) == HumanoidBone.LastBone || map.BoneOf(end) == HumanoidBone.LastBone) return segment;
            return Math.Max(segment, Vector3.Distance(pose.World[start].Position, pose.World[end].Position));
        }

        // Torso segments (between the hips, spine, chest and neck) are thick; limbs and fingers get a fifth of their
        // length, kept between 0.4 % and 3.5 % of the stature (fingers stay visible, thighs stay limbs).
        private static float RadiusOf(HumanoidMap map, int parent, int child, float length, float stature)
        {
            HumanoidBone from = map.BoneOf(parent), to = map.BoneOf(child);
            if (IsTorso(from) && (IsTorso(to) || to == HumanoidBone.Neck || to == HumanoidBone.Head)) return 0.06f * stature;
            if (from == HumanoidBone.Neck) return 0.025f * stature;
            return Math.Clamp(0.2f * length, 0.004f * stature, 0.035f * stature);
        }

        private static bool IsTorso(HumanoidBone bone) =>
            bone == HumanoidBone.Hips || bone == HumanoidBone.Spine || bone == HumanoidBone.Chest || bone == HumanoidBone.UpperChest;
    }
}
