namespace AvatarGo.Simulation
{
    /// <summary>
    /// How the avatar behaved while a <see cref="SessionDisturber"/> damaged the session: the end effectors' jumps and their
    /// errors while their device was lost or teleported, in the second after it came back, and the rest of the time.
    /// </summary>
    public sealed class DisturbanceReport
    {
        /// <summary>Seconds after a device comes back that count as its recovery (1 s).</summary>
        public const double RecoverySeconds = 1.0;

        /// <summary>Device-frames lost or teleported.</summary>
        public int DisturbedDeviceFrames { get; internal set; }

        /// <summary>The largest frame-to-frame displacement of any end effector of the avatar, in mm.</summary>
        public double LargestJumpMm { get; internal set; }

        /// <summary>
        /// The largest frame-to-frame displacement of any end effector beyond the wearer's own (|Δ avatar − Δ wearer|), in mm.
        /// While a device is lost this is the wearer's own motion that the avatar does not follow, not a snap.
        /// </summary>
        public double LargestExcessJumpMm { get; internal set; }

        /// <summary>
        /// The largest jump a device's return caused, in mm: on the first frame back, the end effector's whole displacement
        /// (the frame before, it was not following the wearer); in the rest of <see cref="RecoverySeconds"/>, its displacement
        /// beyond the wearer's own.
        /// </summary>
        public double LargestRecoveryJumpMm { get; internal set; }

        /// <summary>The end effector of <see cref="LargestRecoveryJumpMm"/>.</summary>
        public AvatarGo.Core.HumanoidBone LargestRecoveryJumpJoint { get; internal set; } = AvatarGo.Core.HumanoidBone.LastBone;

        /// <summary>The session time of <see cref="LargestRecoveryJumpMm"/>, in seconds.</summary>
        public double LargestRecoveryJumpTime { get; internal set; } = double.NaN;

        /// <summary>The end effector of <see cref="LargestExcessJumpMm"/>.</summary>
        public AvatarGo.Core.HumanoidBone LargestExcessJumpJoint { get; internal set; } = AvatarGo.Core.HumanoidBone.LastBone;

        /// <summary>The session time of <see cref="LargestExcessJumpMm"/>, in seconds.</summary>
        public double LargestExcessJumpTime { get; internal set; } = double.NaN;

        /// <summary>Position error of the end effectors whose device is lost or teleported, in mm.</summary>
        public ErrorSeries WhileDisturbedMm { get; } = new ErrorSeries();

        /// <summary>Position error of the end effectors in the <see cref="RecoverySeconds"/> after their device came back, in mm.</summary>
        public ErrorSeries AfterRecoveryMm { get; } = new ErrorSeries();

        /// <summary>Position error of the end effectors in frames where no body device is lost, teleported or recovering, in mm.</summary>
        public ErrorSeries UndisturbedMm { get; } = new ErrorSeries();
    }
}
