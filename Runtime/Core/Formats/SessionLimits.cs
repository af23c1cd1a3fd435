namespace AvatarGo.Core
{
    /// <summary>
    /// The limits of the session format (Documentation~/session-format.md, "Limits"): what <see cref="SessionReader"/>
    /// accepts and <see cref="SessionWriter"/> writes. Each is far beyond a real session and keeps a hostile file from
    /// costing more than its size in time and memory, or from handing a later stage a number it cannot use.
    /// </summary>
    public static class SessionLimits
    {
        /// <summary>
        /// The most devices a session may list (1,024). SteamVR tracks at most 64; the calibrator keeps a 256-sample
        /// history per device (7 KB), so this bounds it to about 8 MB.
        /// </summary>
        public const int MaxDevices = 1024;

        /// <summary>The most joints of the ground-truth skeleton (65,536, as <see cref="BvhReader.MaxJoints"/>).</summary>
        public const int MaxTruthJoints = 1 << 16;

        /// <summary>The most events one frame may have (1,024).</summary>
        public const int MaxEventsPerFrame = 1024;

        /// <summary>The lowest nominal rate, in Hz.</summary>
        public const float MinRate = 1f;

        /// <summary>The highest nominal rate, in Hz (10 kHz; tracking runs at 30 to 1,000 Hz).</summary>
        public const float MaxRate = 10000f;

        /// <summary>
        /// The largest coordinate of a tracked pose, a ground-truth pose or a skeleton's rest pose, in metres: 10 km, where
        /// a float still resolves about a millimetre. Lost poses only need to be finite.
        /// </summary>
        public const float MaxPosition = 1e4f;

        /// <summary>The largest magnitude of a frame time, in seconds (1e10 s, about 300 years: room for any clock's epoch).</summary>
        public const double MaxTime = 1e10;

        /// <summary>The longest line, in characters (1 Mi).</summary>
        public const int MaxLineLength = 1 << 20;
    }
}
