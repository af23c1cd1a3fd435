using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The time that measurements between frames run on (speeds, holds and eases, averaging windows, the spacing of presses):
    /// it follows the frames' times while they run forward in regular steps, and counts a step longer than
    /// <see cref="MaxStepSeconds"/> either way (a clock that jumps ahead or restarts, one frame stamped with a time from long
    /// before) as the last regular step, and a repeated, slightly earlier or non-finite time as none (and
    /// <see cref="EarlyFramesBeforeRebase"/> earlier ones in a row as a clock that went back, followed from there). A recording's clock
    /// that jumps would otherwise hold a lost part until it came back, ease it in one frame, open the glitch filter by the
    /// jump's length, or ignore presses for as long as it had gone back.
    /// </summary>
    internal sealed class SteadyClock
    {
        /// <summary>The longest step between two frames taken as it is (a hitch, a paused replay): 0.25 s.</summary>
        public const double MaxStepSeconds = 0.25;

        private double _lastTime = double.NaN;
        private double _regularStep = 1.0 / 90.0;
        private int _earlyFrames;                   // frames in a row stamped before the latest time

        /// <summary>
        /// How many frames in a row may be stamped before the latest time (each counted as no time) before the clock is
        /// taken to have really gone back and is followed from there: 3.
        /// </summary>
        public const int EarlyFramesBeforeRebase = 3;

        /// <summary>The last regular step between frames (s): what one frame takes.</summary>
        public double RegularStep => _regularStep;

        /// <summary>The clock after the last <see cref="Advance"/> (NaN before the first).</summary>
        public double Now { get; private set; } = double.NaN;

        /// <summary>How far the last <see cref="Advance"/> moved it (s).</summary>
        public double LastStep { get; private set; }

        /// <summary>Moves the clock to the frame at <paramref name="time"/> (the frame's own time) and returns it.</summary>
        public double Advance(double time)
        {
            if (double.IsNaN(time) || double.IsInfinity(time))
            {
                LastStep = 0.0;
                if (double.IsNaN(Now)) Now = 0.0;
                return Now;
            }
            double raw = double.IsNaN(_lastTime) ? 0.0 : time - _lastTime;
            double step = Math.Abs(raw) > MaxStepSeconds ? _regularStep : Math.Max(raw, 0.0);
            if (raw > 0.0 && raw <= MaxStepSeconds) _regularStep = raw;
            // A frame stamped slightly early does not move the time the next one is measured from: measured from it, the
            // next step would include what this one went back (a wider glitch filter, a clock gaining that much for good).
            // Several in a row are a clock that went back for good: followed from there (it would stand still for as long).
            _earlyFrames = raw < 0.0 && raw >= -MaxStepSeconds ? _earlyFrames + 1 : 0;
            if (_earlyFrames == 0 || _earlyFrames >= EarlyFramesBeforeRebase)
            {
                _lastTime = time;
                _earlyFrames = 0;
            }
            Now = double.IsNaN(Now) ? time : Now + step;
            LastStep = step;
            return Now;
        }
    }
}
