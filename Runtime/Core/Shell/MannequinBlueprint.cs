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
    /// <para>Joints are listed parents first, so a builder can create them in order. End sites are not joints of the
    /// mannequin (a Unity humanoid does not need them) unless they play a humanoid bone; the segment to an end site is
    /// still drawn, from its parent. Branches of helper joints that lead to no humanoid bone (Rigify's pelvis.L and
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

        // The skeleton's joints minus its end sites, parents first; the root of the skeleton takes its world T-pose as its
        // local pose under the mannequin's root (which stands at the origin).
        private static MannequinJoint[] JointsOf(HumanoidMap map, SkeletonPose pose, out int[] jointOf)
        {
            Skeleton skeleton = map.Skeleton;
            jointOf = new int[skeleton.JointCount];
            var joints = new List<MannequinJoint>(skeleton.JointCount);
            // Skeleton joints are stored parents first (a parent's index is below its child's), so one pass keeps the order.
            for (int j = 0; j < skeleton.JointCount; j++)
            {
                jointOf[j] = -1;
                if (skeleton.IsEndSite(j) && map.BoneOf(j) == HumanoidBone.LastBone) continue; // a hand may be an end site (Rigify)
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
                float radius = RadiusOf(map, parent, j, length, stature);
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

    /// <summary>One joint of a <see cref="MannequinBlueprint"/>: a transform of the mannequin.</summary>
    public readonly struct MannequinJoint
    {
        /// <summary>Creates a joint.</summary>
        public MannequinJoint(string name, int parent, int skeletonJoint, RigidPose local)
        {
            Name = name;
            Parent = parent;
            SkeletonJoint = skeletonJoint;
            Local = local;
        }

        /// <summary>The joint's name, as in the skeleton (unique).</summary>
        public string Name { get; }

        /// <summary>The parent's index in <see cref="MannequinBlueprint.Joints"/>, or -1 for the mannequin's root object.</summary>
        public int Parent { get; }

        /// <summary>The joint's index in the skeleton the blueprint was made from.</summary>
        public int SkeletonJoint { get; }

        /// <summary>The joint's T-pose in its parent's frame: the transform's local position and rotation (scale 1).</summary>
        public RigidPose Local { get; }
    }

    /// <summary>The primitive shapes of a mannequin.</summary>
    public enum MannequinShape
    {
        /// <summary>A capsule along its local +Y axis, <see cref="MannequinPart.Length"/> long from cap to cap.</summary>
        Capsule,
        /// <summary>A sphere of <see cref="MannequinPart.Radius"/>.</summary>
        Sphere,
    }

    /// <summary>One primitive of a <see cref="MannequinBlueprint"/>, in the frame of the joint that carries it.</summary>
    public readonly struct MannequinPart
    {
        /// <summary>Creates a part.</summary>
        public MannequinPart(int joint, MannequinShape shape, Vector3 centre, Quaternion rotation, float length, float radius)
        {
            Joint = joint;
            Shape = shape;
            Centre = centre;
            Rotation = rotation;
            Length = length;
            Radius = radius;
        }

        /// <summary>The index in <see cref="MannequinBlueprint.Joints"/> of the joint the part moves with.</summary>
        public int Joint { get; }

        /// <summary>The part's shape.</summary>
        public MannequinShape Shape { get; }

        /// <summary>The part's centre in the joint's frame.</summary>
        public Vector3 Centre { get; }

        /// <summary>The part's rotation in the joint's frame (a capsule's axis is this rotation's +Y).</summary>
        public Quaternion Rotation { get; }

        /// <summary>The length along the axis in metres (a segment's length; a sphere's diameter).</summary>
        public float Length { get; }

        /// <summary>The radius in metres.</summary>
        public float Radius { get; }

        /// <summary>
        /// The local scale that gives Unity's built-in primitive this size: the capsule mesh is 2 tall with radius 0.5
        /// along +Y, the sphere mesh has radius 0.5.
        /// </summary>
        public Vector3 PrimitiveScale => Shape == MannequinShape.Sphere
            ? new Vector3(2f * Radius)
            : new Vector3(2f * Radius, 0.5f * Length, 2f * Radius);
    }
}
