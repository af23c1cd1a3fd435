using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>How the fingers held the controllers over a session, on the solved body (both hands pooled), in millimetres.</summary>
    public sealed class FingerReport
    {
        internal FingerReport()
        {
            for (int f = 0; f < TipGapMm.Length; f++) TipGapMm[f] = new ErrorSeries();
        }

        /// <summary>Frames in which at least one hand's fingers were solved.</summary>
        public int Frames { get; internal set; }

        /// <summary>The deepest any finger point (joints and tips) went into a controller's surface, in mm (0: none).</summary>
        public double MaxPenetrationMm { get; internal set; }

        /// <summary>Per finger (<see cref="Finger"/> order, thumb first), the distance from the fingertip's skin to the controller's surface, in mm, over every solved hand-frame.</summary>
        public ErrorSeries[] TipGapMm { get; } = new ErrorSeries[5];

        /// <summary>Hand-frames in which the fingers opened because the palm was too far from the controller.</summary>
        public int OpenHandFrames { get; internal set; }

        /// <summary>The gaps of one finger.</summary>
        public ErrorSeries Gap(Finger finger) => TipGapMm[(int)finger];
    }
}
