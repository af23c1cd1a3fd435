using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A vertical mirror for the walk-in: a plane in front of the avatar, facing it, and the reflection through it. A copy of
    /// the avatar whose root is <see cref="ReflectRoot"/> of the avatar's root, with the root's scale negated along its own
    /// x axis and every other local transform copied, is the avatar's exact mirror image (a reflection is a rotation times a
    /// flip of one axis). Engine-free.
    /// </summary>
    public readonly struct MirrorPlane
    {
        /// <summary>The calibrator's default distance of the mirror in front of the avatar (m).</summary>
        public const float DefaultDistance = 1.5f;

        /// <summary>The farthest a mirror is put in front of the avatar (m): farther, its image would be too small to use.</summary>
        public const float MaxDistance = 10f;

        /// <summary>
        /// A distance fit for <see cref="InFrontOf"/>: clamped to 0…<see cref="MaxDistance"/> (an infinite one to an end),
        /// <see cref="DefaultDistance"/> for NaN. A serialized field can hold anything; a non-finite distance would put the
        /// mirrored copy at infinity or NaN.
        /// </summary>
        public static float ValidDistance(float distance) =>
            float.IsNaN(distance) ? DefaultDistance : Math.Min(MaxDistance, Math.Max(0f, distance));

        /// <summary>A point on the plane.</summary>
        public readonly Vector3 Point;

        /// <summary>The plane's unit normal (pointing toward the side the reflected things are seen from).</summary>
        public readonly Vector3 Normal;

        /// <summary>Creates a plane through <paramref name="point"/> with normal <paramref name="normal"/> (normalised).</summary>
        /// <exception cref="ArgumentException">The normal has no length.</exception>
        public MirrorPlane(Vector3 point, Vector3 normal)
        {
            if (!(normal.LengthSquared() > 1e-12f)) throw new ArgumentException("The normal has no length.", nameof(normal));
            Point = point;
            Normal = Vector3.Normalize(normal);
        }

        /// <summary>
        /// The vertical mirror <paramref name="distance"/> in front of <paramref name="placement"/> (a floor pose facing +Z,
        /// like the calibration's placement), facing back at it.
        /// </summary>
        public static MirrorPlane InFrontOf(RigidPose placement, float distance)
        {
            Vector3 forward = Vectors.ProjectOnPlane(Vector3.Transform(Vector3.UnitZ, placement.Rotation), Vector3.UnitY);
            forward = Vectors.NormalizeOr(forward, Vector3.UnitZ);
            return new MirrorPlane(placement.Position + forward * distance, -forward);
        }

        /// <summary>The mirror image of a point.</summary>
        public Vector3 Reflect(Vector3 point) => point - 2f * Vector3.Dot(point - Point, Normal) * Normal;

        /// <summary>The mirror image of a direction.</summary>
        public Vector3 ReflectDirection(Vector3 direction) => direction - 2f * Vector3.Dot(direction, Normal) * Normal;

        /// <summary>
        /// The pose of the mirrored copy's root: at the reflected position, turned so that with its local x axis flipped
        /// (scale (−s, s, s)) it maps every local point where the reflection of the original maps it.
        /// </summary>
        public RigidPose ReflectRoot(RigidPose root)
        {
            Vector3 x = -ReflectDirection(Vector3.Transform(Vector3.UnitX, root.Rotation));
            Vector3 y = ReflectDirection(Vector3.Transform(Vector3.UnitY, root.Rotation));
            Vector3 z = ReflectDirection(Vector3.Transform(Vector3.UnitZ, root.Rotation));
            return new RigidPose(Reflect(root.Position), Rotations.FromBasis(x, y, z));
        }
    }
}
