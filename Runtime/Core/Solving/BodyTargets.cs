using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Everything the body IK needs for one frame, in world space (Unity's frame), as computed from the
    /// devices and a <c>CalibrationProfile</c> by the body solver (the paper's "Avatar movement" section):
    /// the root, the head, the spine bend and the four limb goals. A plain struct: filling it allocates nothing.
    /// </summary>
    public struct BodyTargets
    {
        /// <summary>World pose of the Hips joint (the avatar's root), from the pelvis tracker.</summary>
        public RigidPose Hips;

        /// <summary>False when the pelvis tracker is not tracked this frame: the root keeps its last pose.</summary>
        public bool HipsActive;

        /// <summary>World pose of the Head joint: the position the spine bends toward, the rotation from the HMD.</summary>
        public RigidPose Head;

        /// <summary>False when the HMD is not tracked this frame.</summary>
        public bool HeadActive;

        /// <summary>
        /// World-space rotation from the calibrated root-to-head vector <c>w0</c> (turned with the root) to the
        /// current one <c>wt</c>: the paper's angle α between them, with its axis. Identity when upright.
        /// </summary>
        public Quaternion SpineBend;

        /// <summary>Left ankle goal and knee hint.</summary>
        public LimbTarget LeftFoot;

        /// <summary>Right ankle goal and knee hint.</summary>
        public LimbTarget RightFoot;

        /// <summary>Left wrist goal (palm on the controller grip) and elbow hint.</summary>
        public LimbTarget LeftHand;

        /// <summary>Right wrist goal (palm on the controller grip) and elbow hint.</summary>
        public LimbTarget RightHand;
    }
}
