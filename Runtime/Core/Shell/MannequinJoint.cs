namespace AvatarGo.Core
{
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
}
