using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Which transforms of an engine's hierarchy become the joints of the core <see cref="Skeleton"/> that the pipeline
    /// solves, and how a solved pose goes back to them. The engine side lists its hierarchy (<see cref="HierarchyNode"/>,
    /// depth-first from the avatar's root) and, for a humanoid Animator, which node plays each humanoid bone; this type
    /// keeps the root, every node on the path from the root to each humanoid bone (so the core's local rotations are the
    /// transforms' own local rotations), and the direct children of the last finger and toe bones as end points (the
    /// finger model's tips and the T-pose's floor contact). Without a bone map (<see cref="TryFromNames"/>) it keeps every
    /// node and finds the bones from their names (<see cref="HumanoidNaming"/>).
    /// </summary>
    /// <remarks>
    /// <para>Units: the skeleton is expressed in the root's own frame, before the root's scale: a joint's rest position is
    /// its local position times the scales of the nodes between the root and its parent, and its rest rotation is its local
    /// rotation. The root joint rests at the identity: the pipeline places it. Every kept node must have a uniform, positive
    /// scale (a non-uniform scale shears children in engines, which no rigid pose can express).</para>
    /// <para>Writing back: the scaled avatar the pipeline solves is this skeleton times the calibration's avatar scale, so the
    /// engine root gets its bound local scale times <see cref="RootScaleFactor"/>, and a joint the solver translates (the
    /// hips) gets <see cref="ToLocalPosition"/> of its solved local position.</para>
    /// </remarks>
    public sealed class HumanoidHierarchy
    {
        private static readonly HumanoidBone[] TipParents =
        {
            HumanoidBone.LeftThumbDistal, HumanoidBone.LeftIndexDistal, HumanoidBone.LeftMiddleDistal, HumanoidBone.LeftRingDistal, HumanoidBone.LeftLittleDistal,
            HumanoidBone.RightThumbDistal, HumanoidBone.RightIndexDistal, HumanoidBone.RightMiddleDistal, HumanoidBone.RightRingDistal, HumanoidBone.RightLittleDistal,
        };

        private readonly int[] _nodeOfJoint;
        private readonly float[] _parentScale;

        private HumanoidHierarchy(Skeleton skeleton, HumanoidMap map, int[] nodeOfJoint, float[] parentScale, float rootWorldScale)
        {
            Skeleton = skeleton;
            Map = map;
            _nodeOfJoint = nodeOfJoint;
            _parentScale = parentScale;
            RootWorldScale = rootWorldScale;
        }

        /// <summary>The joints kept, in hierarchy order (joint 0 is the root node).</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Which joint plays each humanoid bone.</summary>
        public HumanoidMap Map { get; }

        /// <summary>The number of joints.</summary>
        public int JointCount => _nodeOfJoint.Length;

        /// <summary>The root node's world scale when the hierarchy was read (uniform).</summary>
        public float RootWorldScale { get; }

        /// <summary>The index (in the node list the hierarchy was made from) of joint <paramref name="joint"/>'s transform.</summary>
        public int NodeOf(int joint) => _nodeOfJoint[joint];

        /// <summary>
        /// The scale of <paramref name="joint"/>'s parent relative to the root's own units (1 for the root's children and for
        /// the root itself): a length in the parent's local units times this is a length in the skeleton's units.
        /// </summary>
        public float ParentScale(int joint) => _parentScale[joint];

        /// <summary>
        /// Reads a humanoid hierarchy whose bones are known (a Unity humanoid Animator's bone transforms):
        /// <paramref name="boneNodes"/>[b] is the node playing <see cref="HumanoidBone"/> b, or -1 (one entry per bone,
        /// <see cref="HumanoidBones.Count"/> of them). <paramref name="rootWorldScale"/> is the root's uniform world scale.
        /// Returns false with the reason when the hierarchy cannot be bound: a bone outside the root, a transform playing two
        /// bones, a required bone missing, a non-uniform or non-positive scale, or a list that is not depth-first.
        /// </summary>
        public static bool TryFromBones(IReadOnlyList<HierarchyNode> nodes, IReadOnlyList<int> boneNodes, float rootWorldScale,
            out HumanoidHierarchy hierarchy, out string error)
        {
            hierarchy = null;
            if (nodes == null) throw new ArgumentNullException(nameof(nodes));
            if (boneNodes == null) throw new ArgumentNullException(nameof(boneNodes));
            if (boneNodes.Count != HumanoidBones.Count) throw new ArgumentException($"Expected one entry per humanoid bone ({HumanoidBones.Count}), got {boneNodes.Count}.", nameof(boneNodes));
            if ((error = CheckOrder(nodes)) != null || (error = CheckScale(rootWorldScale, "the root's world scale")) != null) return false;

            int n = nodes.Count;
            var keep = new bool[n];
            var endSite = new bool[n];
            var boneOfNode = new int[n];
            for (int i = 0; i < n; i++) boneOfNode[i] = -1;
            keep[0] = true;
            for (int b = 0; b < boneNodes.Count; b++)
            {
                int node = boneNodes[b];
                if (node < 0) continue;
                if (node >= n) { error = $"{(HumanoidBone)b} is node {node}, but the hierarchy has {n} nodes"; return false; }
                if (boneOfNode[node] >= 0)
                {
                    error = $"'{nodes[node].Name}' plays both {(HumanoidBone)boneOfNode[node]} and {(HumanoidBone)b}";
                    return false;
                }
                boneOfNode[node] = b;
                for (int k = node; k >= 0 && !keep[k]; k = nodes[k].Parent) keep[k] = true;
            }
            // The end points after the last finger and toe bones, and the head's crown: the finger model's tips, the T-pose's
            // floor contact, what stands the head up (found in review: without Mixamo's HeadTop_End the bound avatar kept its
            // bind pose's head, and its eyes 3 cm lower scaled it 1.8 % too tall: the hands 26 mm off their controllers).
            foreach (HumanoidBone bone in TipParents) KeepChildrenAsEndSites(nodes, boneNodes[(int)bone], keep, endSite);
            // (Which of the head's children is its crown, if any, is the T-pose's to tell: TPoser reads their names.)
            KeepChildrenAsEndSites(nodes, boneNodes[(int)HumanoidBone.Head], keep, endSite);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int toes = boneNodes[(int)HumanoidBones.OnSide(HumanoidBone.LeftToes, side)];
                int foot = boneNodes[(int)HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)];
                KeepChildrenAsEndSites(nodes, toes >= 0 ? toes : foot, keep, endSite);
            }

            if (!Build(nodes, keep, endSite, rootWorldScale, out Skeleton skeleton, out int[] nodeOfJoint, out int[] jointOfNode, out float[] parentScale, out error))
                return false;
            var pairs = new List<KeyValuePair<HumanoidBone, string>>();
            for (int b = 0; b < boneNodes.Count; b++)
                if (boneNodes[b] >= 0) pairs.Add(new KeyValuePair<HumanoidBone, string>((HumanoidBone)b, skeleton.GetName(jointOfNode[boneNodes[b]])));
            var map = new HumanoidMap(skeleton, pairs);
            if ((error = Missing(map)) != null) return false;
            hierarchy = new HumanoidHierarchy(skeleton, map, nodeOfJoint, parentScale, rootWorldScale);
            return true;
        }

        /// <summary>
        /// Reads a hierarchy whose bones are found from the transforms' names (an avatar without a humanoid Animator): every
        /// node is a joint, childless nodes are end points, and <see cref="HumanoidNaming.Detect"/> finds the bones.
        /// Returns false with the reason when a required bone is not found or a scale is not uniform.
        /// </summary>
        public static bool TryFromNames(IReadOnlyList<HierarchyNode> nodes, float rootWorldScale, out HumanoidHierarchy hierarchy, out string error)
        {
            hierarchy = null;
            if (nodes == null) throw new ArgumentNullException(nameof(nodes));
            if ((error = CheckOrder(nodes)) != null || (error = CheckScale(rootWorldScale, "the root's world scale")) != null) return false;
            int n = nodes.Count;
            var keep = new bool[n];
            var endSite = new bool[n];
            for (int i = 0; i < n; i++) { keep[i] = true; endSite[i] = i > 0; }
            for (int i = 1; i < n; i++) endSite[nodes[i].Parent] = false;
            if (!Build(nodes, keep, endSite, rootWorldScale, out Skeleton skeleton, out int[] nodeOfJoint, out _, out float[] parentScale, out error))
                return false;
            HumanoidMap map = HumanoidNaming.Detect(skeleton);
            if ((error = Missing(map)) != null) return false;
            hierarchy = new HumanoidHierarchy(skeleton, map, nodeOfJoint, parentScale, rootWorldScale);
            return true;
        }

        /// <summary>
        /// The engine-side position (relative to its parent, in the parent's local units) of a joint of the scaled avatar whose
        /// solved local position is <paramref name="solvedLocalPosition"/>, when the avatar is scaled by <paramref name="avatarScale"/>.
        /// </summary>
        public Vector3 ToLocalPosition(int joint, Vector3 solvedLocalPosition, float avatarScale) =>
            solvedLocalPosition / (avatarScale * _parentScale[joint]);

        /// <summary>
        /// What the root's bound local scale is multiplied by so that the engine avatar has the scaled avatar's size in a
        /// tracking space of scale <paramref name="trackingScale"/> (world units per metre): the avatar scale times the
        /// tracking scale over the root's world scale when bound (the root's parent is assumed not to change scale).
        /// </summary>
        public float RootScaleFactor(float avatarScale, float trackingScale) => avatarScale * trackingScale / RootWorldScale;

        /// <summary>Every joint below <paramref name="bone"/> (not the bone itself), in hierarchy order; empty when the rig lacks it.</summary>
        public int[] JointsBelow(HumanoidBone bone)
        {
            int joint = Map[bone];
            if (joint < 0) return Array.Empty<int>();
            var below = new List<int>();
            for (int j = joint + 1; j < Skeleton.JointCount; j++)
                if (Skeleton.IsAncestorOrSelf(joint, j)) below.Add(j);
            return below.ToArray();
        }

        private static void KeepChildrenAsEndSites(IReadOnlyList<HierarchyNode> nodes, int parent, bool[] keep, bool[] endSite)
        {
            if (parent < 0 || parent >= nodes.Count) return;
            for (int c = parent + 1; c < nodes.Count; c++)
                if (nodes[c].Parent == parent && !keep[c] && !nodes[c].HasRenderer) { keep[c] = true; endSite[c] = true; }
        }

        private static string CheckOrder(IReadOnlyList<HierarchyNode> nodes)
        {
            if (nodes.Count == 0) return "the hierarchy is empty";
            if (nodes[0].Parent != -1) return "the first node must be the root (parent -1)";
            for (int i = 1; i < nodes.Count; i++)
                if (nodes[i].Parent < 0 || nodes[i].Parent >= i)
                    return $"node {i} ('{nodes[i].Name}') has parent {nodes[i].Parent}: the list must be depth-first, parents before children, one root";
            return null;
        }

        private static string CheckScale(float scale, string what) =>
            scale > 0f && !float.IsInfinity(scale) ? null : $"{what} is {scale}: it must be positive";

        // Uniform within 0.1 % and positive: an engine shears the children of a non-uniformly scaled transform.
        private static string CheckScale(HierarchyNode node)
        {
            Vector3 s = node.LocalScale;
            float max = Math.Max(s.X, Math.Max(s.Y, s.Z)), min = Math.Min(s.X, Math.Min(s.Y, s.Z));
            if (!(min > 0f) || float.IsInfinity(max) || max - min > 1e-3f * max)
                return $"'{node.Name}' has the scale ({s.X}, {s.Y}, {s.Z}): the avatar's bones need uniform, positive scales";
            return null;
        }

        private static bool Build(IReadOnlyList<HierarchyNode> nodes, bool[] keep, bool[] endSite, float rootWorldScale,
            out Skeleton skeleton, out int[] nodeOfJoint, out int[] jointOfNode, out float[] parentScale, out string error)
        {
            skeleton = null;
            nodeOfJoint = null;
            parentScale = null;
            int n = nodes.Count;
            jointOfNode = new int[n];
            var cumulative = new float[n]; // each node's scale relative to the root's own units
            var kept = new List<int>();
            for (int i = 0; i < n; i++)
            {
                jointOfNode[i] = -1;
                cumulative[i] = i == 0 ? 1f : cumulative[nodes[i].Parent] * nodes[i].LocalScale.X;
                if (!keep[i]) continue;
                if (!endSite[i] && (error = CheckScale(nodes[i])) != null) return false;
                jointOfNode[i] = kept.Count;
                kept.Add(i);
            }
            var used = new HashSet<string>(StringComparer.Ordinal);
            var names = new string[kept.Count];
            var parents = new int[kept.Count];
            var rest = new RigidPose[kept.Count];
            var ends = new bool[kept.Count];
            parentScale = new float[kept.Count];
            for (int j = 0; j < kept.Count; j++)
            {
                HierarchyNode node = nodes[kept[j]];
                string name = string.IsNullOrEmpty(node.Name) ? "node" : node.Name;
                if (!used.Add(name)) used.Add(name = name + "#" + kept[j]); // the core needs unique names; the engine side maps by index
                names[j] = name;
                parents[j] = j == 0 ? -1 : jointOfNode[node.Parent];
                parentScale[j] = j == 0 ? 1f : cumulative[node.Parent];
                if (!Vectors.IsFinite(node.LocalPosition) || !Rotations.IsFinite(node.LocalRotation) || node.LocalRotation.LengthSquared() < 1e-6f)
                {
                    error = $"'{node.Name}' has a non-finite local pose";
                    return false;
                }
                rest[j] = j == 0 ? RigidPose.Identity : new RigidPose(node.LocalPosition * parentScale[j], Quaternion.Normalize(node.LocalRotation));
                ends[j] = endSite[kept[j]];
            }
            skeleton = new Skeleton(names, parents, rest, ends);
            nodeOfJoint = kept.ToArray();
            error = null;
            return true;
        }

        private static string Missing(HumanoidMap map)
        {
            IReadOnlyList<HumanoidBone> missing = map.MissingRequired();
            return missing.Count == 0 ? null : "the avatar lacks required humanoid bones: " + string.Join(", ", missing);
        }
    }
}
