namespace AvatarGo.Core
{
    /// <summary>What the body IK achieved in a frame, per limb; an unreached hand is where the virtual controller should be drawn.</summary>
    public struct IkReport
    {
        /// <summary>The left leg.</summary>
        public LimbResult LeftFoot;

        /// <summary>The right leg.</summary>
        public LimbResult RightFoot;

        /// <summary>The left arm.</summary>
        public LimbResult LeftHand;

        /// <summary>The right arm.</summary>
        public LimbResult RightHand;

        /// <summary>Distance in metres between the head joint and its target after the spine bend.</summary>
        public float HeadDistanceLeft;
    }
}
