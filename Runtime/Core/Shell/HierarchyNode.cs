using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// One transform of an engine's hierarchy as the binding reads it: its name, its parent (an index into the same list,
    /// -1 for the root) and its local position, rotation and scale. A hierarchy is a list of these in depth-first order,
    /// the root first, so that every parent comes before its children.
    /// </summary>
    public readonly struct HierarchyNode
    {
        /// <summary>The transform's name.</summary>
        public readonly string Name;

        /// <summary>The index of the parent node, or -1 for the root.</summary>
        public readonly int Parent;

        /// <summary>The position relative to the parent, in the parent's (scaled) units.</summary>
        public readonly Vector3 LocalPosition;

        /// <summary>The rotation relative to the parent.</summary>
        public readonly Quaternion LocalRotation;

        /// <summary>The scale relative to the parent (the binding needs it uniform and positive).</summary>
        public readonly Vector3 LocalScale;

        /// <summary>
        /// The transform draws something (a Unity Renderer): a mesh or primitive attached to a bone, such as the mannequin's
        /// capsules or a ring on a finger. A humanoid binding (<see cref="HumanoidHierarchy.TryFromBones"/>) never takes such a
        /// node for a bone's end point (a fingertip, the toes' tip, the crown); binding by names takes every node, as a rig
        /// whose bones carry their own meshes needs.
        /// </summary>
        public readonly bool HasRenderer;

        /// <summary>Creates a node of a transform that draws nothing.</summary>
        public HierarchyNode(string name, int parent, Vector3 localPosition, Quaternion localRotation, Vector3 localScale)
            : this(name, parent, localPosition, localRotation, localScale, false)
        {
        }

        /// <summary>Creates a node; <paramref name="hasRenderer"/>: see <see cref="HasRenderer"/>.</summary>
        public HierarchyNode(string name, int parent, Vector3 localPosition, Quaternion localRotation, Vector3 localScale, bool hasRenderer)
        {
            Name = name;
            Parent = parent;
            LocalPosition = localPosition;
            LocalRotation = localRotation;
            LocalScale = localScale;
            HasRenderer = hasRenderer;
        }
    }
}
