using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A reusable pose buffer for one <see cref="Skeleton"/>: local transforms that a solver writes and
    /// world transforms computed from them. Allocated once; every per-frame operation is allocation-free.
    /// </summary>
    public sealed class SkeletonPose
    {
        /// <summary>The skeleton this pose belongs to.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Local transforms, one per joint, relative to the parent (roots: relative to <see cref="Origin"/>).</summary>
        public RigidPose[] Local { get; }

        /// <summary>World transforms, valid after <see cref="UpdateWorld()"/>.</summary>
        public RigidPose[] World { get; }

        /// <summary>The frame the roots are expressed in (identity: world).</summary>
        public RigidPose Origin { get; set; } = RigidPose.Identity;

        /// <summary>Creates a pose buffer set to the skeleton's rest pose.</summary>
        public SkeletonPose(Skeleton skeleton)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            Local = new RigidPose[skeleton.JointCount];
            World = new RigidPose[skeleton.JointCount];
            ResetToRest();
        }

        /// <summary>Sets every local transform to the rest pose and updates the world transforms.</summary>
        public void ResetToRest()
        {
            Skeleton.GetRestLocal(Local);
            UpdateWorld();
        }

        /// <summary>Recomputes <see cref="World"/> from <see cref="Local"/> (forward kinematics).</summary>
        public void UpdateWorld() => Skeleton.ComputeWorld(Local, World, Origin);

        /// <summary>
        /// Recomputes the world transforms of the listed joints only, in the order given (parents first); their
        /// parents' world transforms must be up to date. For solvers that touch one chain. Allocation-free.
        /// </summary>
        public void UpdateWorld(ReadOnlySpan<int> joints)
        {
            for (int i = 0; i < joints.Length; i++)
            {
                int j = joints[i];
                int parent = Skeleton.GetParent(j);
                World[j] = (parent < 0 ? Origin : World[parent]) * Local[j];
            }
        }

        /// <summary>
        /// Sets the local rotation of <paramref name="joint"/> so that its world rotation becomes <paramref name="world"/>,
        /// from its parent's world rotation (which must be up to date). <see cref="World"/> is not updated.
        /// </summary>
        public void SetWorldRotation(int joint, Quaternion world)
        {
            int parent = Skeleton.GetParent(joint);
            Quaternion parentRotation = parent < 0 ? Origin.Rotation : World[parent].Rotation;
            Local[joint] = Local[joint].WithRotation(Quaternion.Normalize(Quaternion.Conjugate(parentRotation) * world));
        }

        /// <summary>Turns <paramref name="joint"/> by the world-space rotation <paramref name="delta"/> (applied after its current world rotation); see <see cref="SetWorldRotation"/>.</summary>
        public void RotateWorld(int joint, Quaternion delta) => SetWorldRotation(joint, Quaternion.Normalize(delta * World[joint].Rotation));

        /// <summary>
        /// Sets the local pose of <paramref name="joint"/> so that its world pose becomes <paramref name="world"/>, from its
        /// parent's world pose (which must be up to date). <see cref="World"/> is not updated.
        /// </summary>
        public void SetWorldPose(int joint, RigidPose world)
        {
            int parent = Skeleton.GetParent(joint);
            Local[joint] = world.RelativeTo(parent < 0 ? Origin : World[parent]);
        }

        /// <summary>Recomputes <see cref="Local"/> from <see cref="World"/>.</summary>
        public void UpdateLocal() => Skeleton.ComputeLocal(World, Local, Origin);

        /// <summary>Copies another pose of the same skeleton into this one.</summary>
        public void CopyFrom(SkeletonPose other)
        {
            if (other == null) throw new ArgumentNullException(nameof(other));
            if (other.Skeleton.JointCount != Skeleton.JointCount) throw new ArgumentException("The poses belong to different skeletons.", nameof(other));
            Array.Copy(other.Local, Local, Local.Length);
            Array.Copy(other.World, World, World.Length);
            Origin = other.Origin;
        }
    }
}
