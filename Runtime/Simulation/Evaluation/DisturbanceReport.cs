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
        /// The largest frame-to-frame displacement of any end effector beyond the wearer's own (|Δ avatar − Δ wearer|), in mm:
        /// how far the avatar snapped where the wearer did not move.
        /// </summary>
        public double LargestExcessJumpMm { get; internal set; }

        /// <summary><see cref="LargestExcessJumpMm"/> within <see cref="RecoverySeconds"/> after the effector's device came back, in mm.</summary>
        public double LargestRecoveryJumpMm { get; internal set; }

        /// <summary>Position error of the end effectors whose device is lost or teleported, in mm.</summary>
        public ErrorSeries WhileDisturbedMm { get; } = new ErrorSeries();

        /// <summary>Position error of the end effectors in the <see cref="RecoverySeconds"/> after their device came back, in mm.</summary>
        public ErrorSeries AfterRecoveryMm { get; } = new ErrorSeries();

        /// <summary>Position error of the end effectors whose device is tracked and not recovering, in mm.</summary>
        public ErrorSeries UndisturbedMm { get; } = new ErrorSeries();
    }
}
