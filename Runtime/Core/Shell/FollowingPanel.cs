using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Where the wearer's instructions float: <see cref="Distance"/> in front of the head (its heading only, so looking down
    /// does not bury the text in the floor), <see cref="Drop"/> below the eyes, facing the wearer, following the head
    /// lazily (time constant <see cref="FollowSeconds"/>, frame-rate independent). The pose's +Z points away from the
    /// wearer, the way world-space text reads. Engine-free.
    /// </summary>
    public sealed class FollowingPanel
    {
        private bool _placed;

        /// <summary>How far in front of the head (m, 1.2).</summary>
        public float Distance { get; set; } = 1.2f;

        /// <summary>How far below the eyes (m, 0.15).</summary>
        public float Drop { get; set; } = 0.15f;

        /// <summary>The time constant of the follow (s, 0.4); 0 follows at once.</summary>
        public float FollowSeconds { get; set; } = 0.4f;

        /// <summary>The panel's pose after the last <see cref="Update"/>.</summary>
        public RigidPose Pose { get; private set; } = RigidPose.Identity;

        /// <summary>
        /// Moves the panel toward its place in front of <paramref name="head"/> by <paramref name="dt"/> seconds; the first call
        /// (and the first after <see cref="Reset"/>) puts it there at once. A non-finite head pose leaves it where it is.
        /// </summary>
        public RigidPose Update(RigidPose head, float dt)
        {
            if (!head.IsValid) return Pose;
            Vector3 heading = Vectors.ProjectOnPlane(Vector3.Transform(Vector3.UnitZ, head.Rotation), Vector3.UnitY);
            heading = Vectors.NormalizeOr(heading, Vector3.UnitZ);
            var target = new RigidPose(head.Position + heading * Distance - new Vector3(0f, Drop, 0f), Rotations.LookRotation(heading, Vector3.UnitY));
            if (!_placed || !(FollowSeconds > 0f))
            {
                Pose = target;
                _placed = true;
                return Pose;
            }
            float t = dt > 0f ? 1f - MathF.Exp(-dt / FollowSeconds) : 0f;
            Pose = new RigidPose(Vector3.Lerp(Pose.Position, target.Position, t), Quaternion.Normalize(Quaternion.Slerp(Pose.Rotation, target.Rotation, t)));
            return Pose;
        }

        /// <summary>Makes the next <see cref="Update"/> put the panel in place at once.</summary>
        public void Reset() => _placed = false;
    }
}
