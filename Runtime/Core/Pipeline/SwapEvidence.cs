using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>One frame's limbs as <see cref="RoleSwapDetector"/> weighs them: the wrist targets as the devices are assigned and as they would be swapped, with the shoulders and the arm's length; the ankle targets.</summary>
    public struct SwapEvidence
    {
        /// <summary>The left wrist target from the device playing the left hand.</summary>
        public Vector3 LeftHand;
        /// <summary>The right wrist target from the device playing the right hand.</summary>
        public Vector3 RightHand;
        /// <summary>The left wrist target were the right hand's device the left's.</summary>
        public Vector3 LeftHandIfSwapped;
        /// <summary>The right wrist target were the left hand's device the right's.</summary>
        public Vector3 RightHandIfSwapped;
        /// <summary>The left shoulder (upper arm joint).</summary>
        public Vector3 LeftShoulder;
        /// <summary>The right shoulder (upper arm joint).</summary>
        public Vector3 RightShoulder;
        /// <summary>Shoulder to elbow to wrist, in metres.</summary>
        public float ArmLength;
        /// <summary>Both controllers tracked this frame.</summary>
        public bool HandsTracked;
        /// <summary>The left ankle target from the device playing the left foot.</summary>
        public Vector3 LeftFoot;
        /// <summary>The right ankle target from the device playing the right foot.</summary>
        public Vector3 RightFoot;
        /// <summary>Both foot trackers tracked this frame.</summary>
        public bool FeetTracked;
    }
}
