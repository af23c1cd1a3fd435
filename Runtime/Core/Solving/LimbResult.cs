namespace AvatarGo.Core
{
    /// <summary>What one limb's IK achieved this frame.</summary>
    public readonly struct LimbResult
    {
        /// <summary>True when the end joint is within <see cref="TwoBoneIk.ReachedTolerance"/> of the goal.</summary>
        public readonly bool Reached;

        /// <summary>Distance in metres left between the end joint and the goal (0 when reached).</summary>
        public readonly float DistanceLeft;

        /// <summary>Creates a result.</summary>
        public LimbResult(bool reached, float distanceLeft)
        {
            Reached = reached;
            DistanceLeft = distanceLeft;
        }
    }
}
