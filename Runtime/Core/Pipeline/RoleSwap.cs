namespace AvatarGo.Core
{
    /// <summary>A pair of devices found swapped after calibration (<see cref="RoleSwapDetector"/>).</summary>
    public enum RoleSwap
    {
        /// <summary>None.</summary>
        None = 0,

        /// <summary>The controllers are in the other hands.</summary>
        Hands = 1,

        /// <summary>The foot trackers are on the other feet.</summary>
        Feet = 2,
    }
}
