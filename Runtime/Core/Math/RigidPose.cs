using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A rigid transform: a position and a rotation, in Unity's frame (metres, left-handed,
    /// +Y up, +Z forward). Composition follows Unity: <c>parent * local</c> is the world pose
    /// of a child whose pose relative to <c>parent</c> is <c>local</c>.
    /// </summary>
    [Serializable]
    public readonly struct RigidPose : IEquatable<RigidPose>
    {
        /// <summary>The position, in metres.</summary>
        public readonly Vector3 Position;

        /// <summary>The rotation, a unit quaternion (x, y, z, w).</summary>
        public readonly Quaternion Rotation;

        /// <summary>Creates a pose from a position and a rotation.</summary>
        public RigidPose(Vector3 position, Quaternion rotation)
        {
            Position = position;
            Rotation = rotation;
        }

        /// <summary>The pose at the origin with no rotation.</summary>
        public static RigidPose Identity => new RigidPose(Vector3.Zero, Quaternion.Identity);

        /// <summary>A pose with only a translation.</summary>
        public static RigidPose FromPosition(Vector3 position) => new RigidPose(position, Quaternion.Identity);

        /// <summary>A pose with only a rotation.</summary>
        public static RigidPose FromRotation(Quaternion rotation) => new RigidPose(Vector3.Zero, rotation);

        /// <summary>
        /// True when the position and rotation are finite and the rotation is a unit quaternion
        /// (within 1e-3): the test every pose from outside (a device, a file) must pass.
        /// </summary>
        public bool IsValid => Vectors.IsFinite(Position) && Rotations.IsUnit(Rotation);

        /// <summary>The inverse transform: <c>p.Inverse() * p == Identity</c>.</summary>
        public RigidPose Inverse()
        {
            Quaternion inv = Quaternion.Conjugate(Rotation);
            return new RigidPose(Vector3.Transform(-Position, inv), inv);
        }

        /// <summary>Composes two poses: <paramref name="local"/> expressed in <paramref name="parent"/>'s frame, returned in the frame <paramref name="parent"/> lives in.</summary>
        public static RigidPose operator *(RigidPose parent, RigidPose local)
        {
            return new RigidPose(
                parent.Position + Vector3.Transform(local.Position, parent.Rotation),
                Quaternion.Normalize(parent.Rotation * local.Rotation));
        }

        /// <summary>Maps a point from this pose's local frame to the parent frame.</summary>
        public Vector3 TransformPoint(Vector3 localPoint) => Position + Vector3.Transform(localPoint, Rotation);

        /// <summary>Maps a point from the parent frame into this pose's local frame.</summary>
        public Vector3 InverseTransformPoint(Vector3 point) =>
            Vector3.Transform(point - Position, Quaternion.Conjugate(Rotation));

        /// <summary>Rotates a direction from this pose's local frame to the parent frame.</summary>
        public Vector3 TransformDirection(Vector3 localDirection) => Vector3.Transform(localDirection, Rotation);

        /// <summary>Rotates a direction from the parent frame into this pose's local frame.</summary>
        public Vector3 InverseTransformDirection(Vector3 direction) =>
            Vector3.Transform(direction, Quaternion.Conjugate(Rotation));

        /// <summary>This pose expressed in the frame of <paramref name="reference"/>: <c>reference.Inverse() * this</c>.</summary>
        public RigidPose RelativeTo(RigidPose reference) => reference.Inverse() * this;

        /// <summary>The same pose with another position.</summary>
        public RigidPose WithPosition(Vector3 position) => new RigidPose(position, Rotation);

        /// <summary>The same pose with another rotation.</summary>
        public RigidPose WithRotation(Quaternion rotation) => new RigidPose(Position, rotation);

        /// <summary>Interpolates position linearly and rotation spherically (shortest path).</summary>
        public static RigidPose Lerp(RigidPose a, RigidPose b, float t) =>
            new RigidPose(Vector3.Lerp(a.Position, b.Position, t), Quaternion.Slerp(a.Rotation, b.Rotation, t));

        /// <summary>The same pose uniformly scaled about the origin (positions only).</summary>
        public RigidPose Scaled(float scale) => new RigidPose(Position * scale, Rotation);

        /// <inheritdoc/>
        public bool Equals(RigidPose other) => Position.Equals(other.Position) && Rotation.Equals(other.Rotation);

        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is RigidPose other && Equals(other);

        /// <inheritdoc/>
        public override int GetHashCode() => Position.GetHashCode() * 397 ^ Rotation.GetHashCode();

        /// <inheritdoc/>
        public override string ToString() => $"RigidPose(position {Position}, rotation {Rotation})";
    }
}
