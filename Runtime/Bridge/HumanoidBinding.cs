using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// An avatar's transforms bound to the core: a <see cref="Skeleton"/> and <see cref="HumanoidMap"/> built from the
    /// transform hierarchy itself (<see cref="HumanoidHierarchy"/>: the root, every transform from it to each humanoid bone,
    /// and the finger and toe tips), so that the core's local rotations are the transforms' own and its rest pose is the
    /// transforms' current local pose; and the way back, a solved pose written to those transforms. Bound from a humanoid
    /// <see cref="Animator"/> (its bone transforms) or, for rigs without one, from the transforms' names.
    /// </summary>
    /// <remarks>
    /// The root is the Animator's own transform (or the given root). Writing a pose places the root in the world through the
    /// tracking space and scales it by the calibration's avatar scale; the root's parent must not change its scale
    /// afterwards. Bind while the avatar is in its bind pose (T-pose or A-pose: either works, the core finds the T-pose).
    /// </remarks>
    public sealed class HumanoidBinding
    {
        private readonly Transform[] _joints;
        private readonly Vector3 _rootBindScale;
        private readonly RigidPose[] _bindLocal;

        private HumanoidBinding(HumanoidHierarchy hierarchy, List<Transform> nodes, Transform root)
        {
            Hierarchy = hierarchy;
            Root = root;
            _rootBindScale = root.localScale;
            _joints = new Transform[hierarchy.JointCount];
            _bindLocal = new RigidPose[hierarchy.JointCount];
            for (int j = 0; j < _joints.Length; j++)
            {
                _joints[j] = nodes[hierarchy.NodeOf(j)];
                _bindLocal[j] = _joints[j].GetLocalPose();
            }
        }

        /// <summary>Which transforms are joints, and how poses go back to them.</summary>
        public HumanoidHierarchy Hierarchy { get; }

        /// <summary>The skeleton and its humanoid bones: the avatar the pipeline is made for.</summary>
        public HumanoidMap Map => Hierarchy.Map;

        /// <summary>The avatar's root transform (joint 0).</summary>
        public Transform Root { get; }

        /// <summary>The transform of joint <paramref name="joint"/>.</summary>
        public Transform Joint(int joint) => _joints[joint];

        /// <summary>The local pose (engine units) joint <paramref name="joint"/>'s transform had when bound.</summary>
        public RigidPose BindLocalPose(int joint) => _bindLocal[joint];

        /// <summary>The transform of <paramref name="bone"/>, or null when the rig lacks it.</summary>
        public Transform this[HumanoidBone bone]
        {
            get
            {
                int j = Map[bone];
                return j >= 0 ? _joints[j] : null;
            }
        }

        /// <summary>
        /// Binds a humanoid Animator's avatar. Fails (false, with the reason) when the Animator has no valid humanoid Avatar
        /// (checked before any bone is asked for: <c>GetBoneTransform</c> throws for such avatars from Unity 2022.1), when a bone
        /// is not below the Animator, or when the hierarchy cannot be bound (a non-uniform scale, a bone missing).
        /// </summary>
        public static bool TryBind(Animator animator, out HumanoidBinding binding, out string error)
        {
            binding = null;
            if (animator == null)
            {
                error = "no Animator is assigned";
                return false;
            }
            Avatar avatar = animator.avatar;
            if (avatar == null || !avatar.isValid || !avatar.isHuman)
            {
                error = avatar == null ? $"the Animator of '{animator.name}' has no Avatar; a humanoid Avatar is needed (set Animation Type: Humanoid in the model's import settings)"
                    : $"the Avatar '{avatar.name}' of '{animator.name}' is {(avatar.isValid ? "not humanoid" : "not valid")}; a valid humanoid Avatar is needed";
                return false;
            }
            var nodes = new List<HierarchyNode>();
            List<Transform> transforms = Flatten(animator.transform, nodes);
            var index = new Dictionary<Transform, int>(transforms.Count);
            for (int i = 0; i < transforms.Count; i++) index[transforms[i]] = i;
            var bones = new int[HumanoidBones.Count];
            for (int b = 0; b < bones.Length; b++)
            {
                Transform t = animator.GetBoneTransform((HumanBodyBones)b);
                if (t == null)
                {
                    bones[b] = -1;
                    continue;
                }
                if (!index.TryGetValue(t, out int node))
                {
                    error = $"the Avatar maps {(HumanoidBone)b} to '{t.name}', which is not below the Animator's GameObject '{animator.name}'";
                    return false;
                }
                bones[b] = node;
            }
            if (!HumanoidHierarchy.TryFromBones(nodes, bones, UniformScale(animator.transform.lossyScale), out HumanoidHierarchy hierarchy, out error))
            {
                error = $"'{animator.name}' cannot be bound: {error}";
                return false;
            }
            binding = new HumanoidBinding(hierarchy, transforms, animator.transform);
            return true;
        }

        /// <summary>
        /// Binds a rig without a humanoid Animator: every transform below <paramref name="root"/> is a joint and the humanoid
        /// bones are found from their names (Mixamo, Unity-style, Unreal, Rigify, CMU: see <see cref="HumanoidNaming"/>).
        /// </summary>
        public static bool TryBindByNames(Transform root, out HumanoidBinding binding, out string error)
        {
            binding = null;
            if (root == null)
            {
                error = "no avatar root is assigned";
                return false;
            }
            var nodes = new List<HierarchyNode>();
            List<Transform> transforms = Flatten(root, nodes);
            if (!HumanoidHierarchy.TryFromNames(nodes, UniformScale(root.lossyScale), out HumanoidHierarchy hierarchy, out error))
            {
                error = $"'{root.name}' cannot be bound by its bones' names: {error}";
                return false;
            }
            binding = new HumanoidBinding(hierarchy, transforms, root);
            return true;
        }

        /// <summary>
        /// The same joints on a copy of the bound hierarchy (an <c>Instantiate</c>d avatar has the same transforms in the
        /// same order), for the calibration's mirrored copy; null when the copy's hierarchy differs.
        /// </summary>
        public HumanoidBinding OnCopy(Transform copyRoot)
        {
            if (copyRoot == null) return null;
            var nodes = new List<HierarchyNode>();
            List<Transform> transforms = Flatten(copyRoot, nodes);
            for (int j = 0; j < _joints.Length; j++)
                if (Hierarchy.NodeOf(j) >= transforms.Count || transforms[Hierarchy.NodeOf(j)].name != _joints[j].name) return null;
            return new HumanoidBinding(Hierarchy, transforms, copyRoot);
        }

        /// <summary>
        /// Places the root: its world pose is the tracking-space pose <paramref name="root"/> mapped through
        /// <paramref name="space"/>, its scale the bound scale times the avatar scale (and the tracking space's scale).
        /// </summary>
        public void ApplyRoot(RigidPose root, TrackingSpace space, float avatarScale)
        {
            Root.SetWorldPose(space.ToWorld(root));
            float f = Hierarchy.RootScaleFactor(avatarScale, space.Scale);
            Root.localScale = new Vector3(_rootBindScale.x * f, _rootBindScale.y * f, _rootBindScale.z * f);
        }

        /// <summary>
        /// Writes a whole solved pose of the scaled avatar (tracking space) to the transforms: the root placed and scaled, every
        /// other joint's local rotation and local position. Allocation-free.
        /// </summary>
        public void ApplyPose(SkeletonPose pose, TrackingSpace space, float avatarScale)
        {
            ApplyRoot(pose.World[0], space, avatarScale);
            RigidPose[] local = pose.Local;
            for (int j = 1; j < _joints.Length; j++)
            {
                Transform t = _joints[j];
                t.localRotation = local[j].Rotation.ToUnity();
                t.localPosition = Hierarchy.ToLocalPosition(j, local[j].Position, avatarScale).ToUnity();
            }
        }

        /// <summary>Writes the local rotations of the listed joints (the fingers) from a solved pose. Allocation-free.</summary>
        public void ApplyLocalRotations(SkeletonPose pose, int[] joints)
        {
            RigidPose[] local = pose.Local;
            for (int i = 0; i < joints.Length; i++) _joints[joints[i]].localRotation = local[joints[i]].Rotation.ToUnity();
        }

        /// <summary>
        /// Copies every joint's local pose from another binding of the same hierarchy (the mirrored copy takes what the avatar
        /// shows). Allocation-free.
        /// </summary>
        public void CopyLocalPoses(HumanoidBinding source)
        {
            for (int j = 1; j < _joints.Length; j++)
            {
                Transform from = source._joints[j], to = _joints[j];
                to.localRotation = from.localRotation;
                to.localPosition = from.localPosition;
            }
        }

        /// <summary>Puts every transform back to its pose when bound (the root's scale too).</summary>
        public void RestoreBindPose()
        {
            Root.localScale = _rootBindScale;
            for (int j = 1; j < _joints.Length; j++)
                if (_joints[j] != null) _joints[j].SetLocalPose(_bindLocal[j]);
        }

        /// <summary>True while the root and every bone transform still exist.</summary>
        public bool IsIntact
        {
            get
            {
                for (int j = 0; j < _joints.Length; j++)
                    if (_joints[j] == null) return false;
                return true;
            }
        }

        /// <summary>
        /// The hierarchy below <paramref name="root"/> as the core reads it, depth-first (children in sibling order), with the
        /// matching transforms. Allocates.
        /// </summary>
        public static List<Transform> Flatten(Transform root, List<HierarchyNode> nodes)
        {
            var transforms = new List<Transform>();
            nodes.Clear();
            Add(root, -1, transforms, nodes);
            return transforms;
        }

        private static void Add(Transform t, int parent, List<Transform> transforms, List<HierarchyNode> nodes)
        {
            int index = transforms.Count;
            transforms.Add(t);
            // A transform that draws (the mannequin's capsules, a prop on a finger) is never taken for a bone's end point.
            nodes.Add(new HierarchyNode(t.name, parent, t.localPosition.ToCore(), t.localRotation.ToCore(), t.localScale.ToCore(), t.GetComponent<Renderer>() != null));
            for (int c = 0; c < t.childCount; c++) Add(t.GetChild(c), index, transforms, nodes);
        }

        // A uniform scale's value (the core checks the joints' scales are uniform; the root's world scale is taken as its x).
        private static float UniformScale(Vector3 scale) => scale.x;
    }
}
