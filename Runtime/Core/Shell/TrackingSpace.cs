using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Where the XR runtime's tracking space lies in the scene: the world pose of its origin (an XR Origin's camera-offset
    /// object, typically) and its uniform scale. The pipeline works in tracking space, so the avatar follows the rig when the
    /// application moves it (locomotion, teleports); drivers map the solved pose to world space with this.
    /// </summary>
    public readonly struct TrackingSpace
    {
        /// <summary>The origin's world pose.</summary>
        public readonly RigidPose Origin;

        /// <summary>The uniform scale of the tracking space in the scene (1: a metre is a metre).</summary>
        public readonly float Scale;

        /// <summary>Creates a tracking space.</summary>
        /// <exception cref="ArgumentOutOfRangeException">The scale is not positive and finite.</exception>
        public TrackingSpace(RigidPose origin, float scale = 1f)
        {
            if (!(scale > 0f) || float.IsInfinity(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "The scale must be positive.");
            Origin = origin;
            Scale = scale;
        }

        /// <summary>The tracking space that is the world (identity origin, scale 1).</summary>
        public static TrackingSpace World => new TrackingSpace(RigidPose.Identity);

        /// <summary>A tracking-space pose in world space.</summary>
        public RigidPose ToWorld(RigidPose tracking) =>
            new RigidPose(Origin.TransformPoint(tracking.Position * Scale), Quaternion.Normalize(Origin.Rotation * tracking.Rotation));

        /// <summary>A tracking-space point in world space.</summary>
        public Vector3 ToWorld(Vector3 tracking) => Origin.TransformPoint(tracking * Scale);

        /// <summary>A world pose in tracking space.</summary>
        public RigidPose ToTracking(RigidPose world) =>
            new RigidPose(Origin.InverseTransformPoint(world.Position) / Scale, Quaternion.Normalize(Quaternion.Conjugate(Origin.Rotation) * world.Rotation));
    }
}
