using System;
using AvatarGo.Core;
using UnityEngine;
using CoreQuaternion = System.Numerics.Quaternion;
using CoreVector3 = System.Numerics.Vector3;

namespace AvatarGo
{
    /// <summary>
    /// Conversions between Unity's math and transforms and the core's (<see cref="System.Numerics"/>,
    /// <see cref="RigidPose"/>). Both sides use the same frame (metres, left-handed, +Y up, +Z forward) and the
    /// same quaternion layout (x, y, z, w), so every conversion copies components one to one: no axis is flipped
    /// and no sign changes.
    /// </summary>
    public static class UnityConversions
    {
        /// <summary>A Unity vector as a core vector.</summary>
        public static CoreVector3 ToCore(this Vector3 v) => new CoreVector3(v.x, v.y, v.z);

        /// <summary>A core vector as a Unity vector.</summary>
        public static Vector3 ToUnity(this CoreVector3 v) => new Vector3(v.X, v.Y, v.Z);

        /// <summary>A Unity quaternion as a core quaternion (same x, y, z, w).</summary>
        public static CoreQuaternion ToCore(this Quaternion q) => new CoreQuaternion(q.x, q.y, q.z, q.w);

        /// <summary>A core quaternion as a Unity quaternion (same x, y, z, w).</summary>
        public static Quaternion ToUnity(this CoreQuaternion q) => new Quaternion(q.X, q.Y, q.Z, q.W);

        /// <summary>The transform's pose in world space.</summary>
        /// <exception cref="ArgumentNullException"><paramref name="transform"/> is null or destroyed.</exception>
        public static RigidPose GetWorldPose(this Transform transform)
        {
            ThrowIfNull(transform);
            return new RigidPose(transform.position.ToCore(), transform.rotation.ToCore());
        }

        /// <summary>The transform's pose relative to its parent (world space when it has none).</summary>
        /// <exception cref="ArgumentNullException"><paramref name="transform"/> is null or destroyed.</exception>
        public static RigidPose GetLocalPose(this Transform transform)
        {
            ThrowIfNull(transform);
            return new RigidPose(transform.localPosition.ToCore(), transform.localRotation.ToCore());
        }

        /// <summary>
        /// Moves the transform to <paramref name="pose"/> in world space, position and rotation in one call
        /// (<c>Transform.SetPositionAndRotation</c>, which every Unity version since 2021.3.0 has).
        /// </summary>
        /// <exception cref="ArgumentNullException"><paramref name="transform"/> is null or destroyed.</exception>
        public static void SetWorldPose(this Transform transform, RigidPose pose)
        {
            ThrowIfNull(transform);
            transform.SetPositionAndRotation(pose.Position.ToUnity(), pose.Rotation.ToUnity());
        }

        /// <summary>
        /// Sets the transform's pose relative to its parent. Written as two property sets because
        /// <c>Transform.SetLocalPositionAndRotation</c> only exists from Unity 2021.3.11.
        /// </summary>
        /// <exception cref="ArgumentNullException"><paramref name="transform"/> is null or destroyed.</exception>
        public static void SetLocalPose(this Transform transform, RigidPose pose)
        {
            ThrowIfNull(transform);
            transform.localPosition = pose.Position.ToUnity();
            transform.localRotation = pose.Rotation.ToUnity();
        }

        // UnityEngine.Object's == is also true for a destroyed object, which would otherwise throw deep inside the engine.
        private static void ThrowIfNull(Transform transform)
        {
            if (transform == null) throw new ArgumentNullException(nameof(transform));
        }
    }
}
