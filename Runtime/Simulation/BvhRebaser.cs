using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Re-expresses a BVH clip in another rest convention without changing its motion: every joint gets new local axes
    /// (a constant rotation of its old ones), its children's OFFSETs and every frame's rotations are rewritten to match,
    /// and so every joint's world position in every frame stays where it was (to float precision: well under 0.01 mm).
    /// BVH's rest pose is always the OFFSETs with no rotation, so new local axes also mean a new rest pose: with
    /// <see cref="AlongX"/> every bone lies along its joint's +X axis and the rest is a straight line, not a T-pose;
    /// with <see cref="RandomAxes"/> every joint's local frame is a random rotation and the rest is crumpled. Nothing
    /// in the pipeline may depend on which (issue 10): tests compare a clip's results in all of them.
    /// </summary>
    /// <remarks>
    /// Joints with position channels in the source keep all three (their translation, now in the parent's new axes,
    /// generally moves along every axis); rotation channels keep the source's order. End Sites have no axes of their
    /// own: theirs are their parent's. Lengths stay in the file's units.
    /// </remarks>
    public static class BvhRebaser
    {
        /// <summary>
        /// Every joint's local +X axis (BVH's, right-handed, as the file shows it) along its bone, turned by
        /// <paramref name="twistDegrees"/> about it: the bone to the child that leads the largest part of the skeleton
        /// (the spine from the hips, an arm from the chest), ignoring children at the joint itself. A joint with no
        /// child away from it keeps its axes, turned by the twist about X.
        /// </summary>
        public static BvhClip AlongX(BvhClip clip, float twistDegrees = 0f)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (!Vectors.IsFinite(twistDegrees)) throw new ArgumentOutOfRangeException(nameof(twistDegrees), twistDegrees, "The twist must be finite.");
            Skeleton s = clip.Skeleton;
            int[] subtree = SubtreeSizes(s);
            // BVH's +X is Unity's -X (the reader mirrors X); the frames below are in Unity's frame.
            Vector3 bvhX = -Vector3.UnitX;
            Quaternion twist = Quaternion.CreateFromAxisAngle(bvhX, twistDegrees * Rotations.Deg2Rad);
            var axes = new Quaternion[s.JointCount];
            for (int j = 0; j < s.JointCount; j++)
            {
                int lead = -1;
                for (int c = j + 1; c < s.JointCount; c++)
                    if (s.GetParent(c) == j && s.GetRestLocal(c).Position.LengthSquared() > 1e-12f && (lead < 0 || subtree[c] > subtree[lead])) lead = c;
                Quaternion along = lead < 0 ? Quaternion.Identity : Rotations.FromTo(bvhX, s.GetRestLocal(lead).Position);
                axes[j] = Quaternion.Normalize(along * twist);
            }
            return Rebase(clip, axes);
        }

        /// <summary>Every joint's local frame a rotation drawn uniformly at random (<paramref name="seed"/> makes it repeatable).</summary>
        public static BvhClip RandomAxes(BvhClip clip, int seed)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            var rng = new Random(seed);
            var axes = new Quaternion[clip.Skeleton.JointCount];
            for (int j = 0; j < axes.Length; j++) axes[j] = DeviceMountings.UniformRotation(rng);
            return Rebase(clip, axes);
        }

        /// <summary>
        /// The general case: <paramref name="newAxes"/>[j] is joint j's new local frame expressed in its old one (Unity's
        /// frame); End Sites' entries are ignored (they take their parent's).
        /// </summary>
        public static BvhClip Rebase(BvhClip clip, IReadOnlyList<Quaternion> newAxes)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (newAxes == null) throw new ArgumentNullException(nameof(newAxes));
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            if (newAxes.Count != n) throw new ArgumentException($"Expected axes for {n} joints, got {newAxes.Count}.", nameof(newAxes));
            var axes = new Quaternion[n];
            for (int j = 0; j < n; j++)
            {
                int parent = s.GetParent(j);
                axes[j] = s.IsEndSite(j) && parent >= 0 ? axes[parent] : Rotations.NormalizeOr(newAxes[j], Quaternion.Identity);
            }

            // A child's translation is re-expressed in its parent's new axes; a joint's rotation becomes
            // (parent's new axes)^-1 · rotation · (its new axes), so that every world pose is the old one times its axes.
            var rest = new RigidPose[n];
            for (int j = 0; j < n; j++)
                rest[j] = new RigidPose(Snap(ToNewParent(s, axes, j, s.GetRestLocal(j).Position)), Quaternion.Identity);
            var local = new RigidPose[n];
            var frames = new List<RigidPose[]>(clip.FrameCount);
            for (int f = 0; f < clip.FrameCount; f++)
            {
                clip.GetLocalPoses(f, local);
                var rebased = new RigidPose[n];
                for (int j = 0; j < n; j++)
                {
                    int parent = s.GetParent(j);
                    Quaternion parentAxes = parent < 0 ? Quaternion.Identity : axes[parent];
                    Quaternion rotation = s.IsEndSite(j) ? Quaternion.Identity : Quaternion.Normalize(Quaternion.Conjugate(parentAxes) * local[j].Rotation * axes[j]);
                    rebased[j] = new RigidPose(ToNewParent(s, axes, j, local[j].Position), rotation);
                }
                frames.Add(rebased);
            }

            var channels = new BvhChannel[n][];
            for (int j = 0; j < n; j++) channels[j] = s.IsEndSite(j) ? Array.Empty<BvhChannel>() : ChannelsLike(clip.GetChannels(j), s.GetParent(j) < 0);
            Skeleton rebasedSkeleton = s.WithRestLocal(rest);
            return BvhClip.FromPoses(rebasedSkeleton, frames, clip.FrameTime, clip.Scale, channels);
        }

        private static Vector3 ToNewParent(Skeleton s, Quaternion[] axes, int joint, Vector3 translation)
        {
            int parent = s.GetParent(joint);
            return parent < 0 ? translation : Vector3.Transform(translation, Quaternion.Conjugate(axes[parent]));
        }

        // Components under a millionth of the offset's length are float residue (a bone turned onto an axis): zero.
        private static Vector3 Snap(Vector3 v)
        {
            float tiny = 1e-6f * v.Length();
            return new Vector3(Math.Abs(v.X) < tiny ? 0f : v.X, Math.Abs(v.Y) < tiny ? 0f : v.Y, Math.Abs(v.Z) < tiny ? 0f : v.Z);
        }

        // The source's rotation order, and all three position channels where it had any (or at a root).
        private static BvhChannel[] ChannelsLike(IReadOnlyList<BvhChannel> source, bool root)
        {
            var rotations = new List<BvhChannel>(3);
            bool positions = root;
            foreach (BvhChannel c in source)
            {
                if (c <= BvhChannel.Zposition) positions = true;
                else rotations.Add(c);
            }
            if (rotations.Count != 3) rotations = new List<BvhChannel> { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            var result = new List<BvhChannel>(6);
            if (positions) result.AddRange(new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition });
            result.AddRange(rotations);
            return result.ToArray();
        }

        private static int[] SubtreeSizes(Skeleton s)
        {
            var size = new int[s.JointCount];
            for (int j = s.JointCount - 1; j >= 0; j--)
            {
                size[j]++;
                int parent = s.GetParent(j);
                if (parent >= 0) size[parent] += size[j];
            }
            return size;
        }
    }
}
