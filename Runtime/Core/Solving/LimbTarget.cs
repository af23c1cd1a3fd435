using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The goal of one limb for a frame: where its end joint (ankle or wrist) should be and how it should be
    /// oriented, and a hint position that the middle joint (knee or elbow) should bend toward.
    /// </summary>
    public struct LimbTarget
    {
        /// <summary>World pose the end joint (ankle, wrist) should take.</summary>
        public RigidPose Goal;

        /// <summary>World position the middle joint (knee, elbow) should bend toward.</summary>
        public Vector3 Hint;

        /// <summary>False when the device driving this limb is not tracked this frame: the limb keeps its last pose.</summary>
        public bool IsActive;

        /// <summary>Creates an active limb target.</summary>
        public LimbTarget(RigidPose goal, Vector3 hint)
        {
            Goal = goal;
            Hint = hint;
            IsActive = true;
        }
    }
}
