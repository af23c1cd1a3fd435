using System;
using System.Collections.Generic;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// The calibrator component's refinement exercise (<see cref="SelfAvatarPipeline.BeginRefinement"/>,
    /// <see cref="ProportionRefinement"/>), decided without Unity: when a new calibration completes (and
    /// <see cref="Enabled"/>) it starts the exercise; it shows the wearer what to do with a countdown; it ends the exercise
    /// when <see cref="ExerciseSeconds"/> are up or a controller's trigger is pressed (after the first
    /// <see cref="IgnorePressesSeconds"/>), applies it, and shows what changed for <see cref="SummarySeconds"/>. A reset, new
    /// devices or a restored profile drop a running exercise (<see cref="Cancel"/>). Allocation-free per frame while the
    /// exercise runs; starting and ending it allocate (the pipeline's recorder, the report, the summary).
    /// </summary>
    /// <remarks>
    /// Each frame the shell calls <see cref="BeforeUpdate"/> before the pipeline runs it and <see cref="AfterUpdate"/> after
    /// the calibration flow saw it. The exercise ends before the pipeline runs the frame, so that frame is already solved on
    /// the refined avatar (ending it after would leave the new avatar in its calibration T-pose for that one frame): the
    /// frames recorded are those after the calibrating frame and before the one at or past
    /// <see cref="ExerciseSeconds"/>. The first presses are ignored because the press that calibrated came from one trigger
    /// and the other is often pressed with it.
    /// </remarks>
    public sealed class RefinementFlow
    {
        /// <summary>What the wearer is asked to do (the motion the refinement can read the arms from, calibration.md).</summary>
        public const string Instruction = "Refining your arms: circle your arms stretched out, reach forward and overhead, then squat twice.";

        /// <summary>Shortest exercise (s) <see cref="ExerciseSeconds"/> accepts.</summary>
        public const float MinimumExerciseSeconds = 2f;

        /// <summary>Longest exercise (s) <see cref="ExerciseSeconds"/> accepts.</summary>
        public const float MaximumExerciseSeconds = 60f;

        /// <summary>The default exercise (8 s: two arm circles, the reaches and two squats, as the simulated wearer does them).</summary>
        public const float DefaultExerciseSeconds = 8f;

        // Frames the pipeline's recorder holds: the longest exercise at 150 Hz, at least its default (20 s at 90 Hz).
        private const float RecorderRate = 150f;

        private const string PressTooEarly = "a trigger press in the first seconds of the refinement exercise was ignored (the calibration's own press, or the other trigger pressed with it)";
        private const string PressNotController = "a trigger press from a device that is not a controller was ignored: only a controller's trigger ends the refinement exercise";

        private float _seconds = DefaultExerciseSeconds;
        private string[] _countdown = Array.Empty<string>();
        private int _shown;
        private double _startedAt, _endsAt, _summaryUntil;
        private double _lastTime;                         // the last frame time that was a finite number
        private SelfAvatarPipeline _pipeline;

        /// <summary>Run the exercise after each new calibration (not after a restored one). Read when a calibration completes.</summary>
        public bool Enabled { get; set; }

        /// <summary>How long the exercise lasts (s), held within <see cref="MinimumExerciseSeconds"/>…<see cref="MaximumExerciseSeconds"/>
        /// (not finite: the default). Read when it starts.</summary>
        public float ExerciseSeconds
        {
            get => _seconds;
            set => _seconds = float.IsNaN(value) || float.IsInfinity(value) ? DefaultExerciseSeconds : Math.Max(MinimumExerciseSeconds, Math.Min(MaximumExerciseSeconds, value));
        }

        private float _ignorePressesSeconds = 2f, _summarySeconds = 8f;

        /// <summary>How long (s) after the start a trigger press does not end the exercise (2 s; NaN gives the default, a negative time 0).</summary>
        public float IgnorePressesSeconds
        {
            get => _ignorePressesSeconds;
            set => _ignorePressesSeconds = float.IsNaN(value) ? 2f : Math.Max(0f, value);
        }

        /// <summary>
        /// How long (s) the summary of what changed stays up after the exercise (8 s; NaN gives the default, a negative time 0,
        /// infinity keeps it up until the next reset or calibration).
        /// </summary>
        public float SummarySeconds
        {
            get => _summarySeconds;
            set => _summarySeconds = float.IsNaN(value) ? 8f : Math.Max(0f, value);
        }

        /// <summary>Where the exercise is.</summary>
        public RefinementPhase Phase { get; private set; }

        /// <summary>The last applied exercise's report (null before one ended).</summary>
        public RefinementReport LastReport { get; private set; }

        /// <summary>What the wearer was told the last exercise changed (empty before one ended): <see cref="Summarize"/> of <see cref="LastReport"/>.</summary>
        public string Summary { get; private set; } = string.Empty;

        /// <summary>For the developer's log: why the last press was ignored or the start refused, or how the exercise ended and the report.</summary>
        public string Explanation { get; private set; } = string.Empty;

        /// <summary>Seconds left in the exercise (0 when none runs).</summary>
        public double SecondsLeft { get; private set; }

        /// <summary>The text for the wearer now: the instruction with the countdown, then the summary; empty otherwise.</summary>
        public string Message => Phase == RefinementPhase.Exercising ? _countdown[_shown] : Phase == RefinementPhase.Summary ? Summary : string.Empty;

        /// <summary>True while there is a <see cref="Message"/> to show.</summary>
        public bool ShowsMessage => Phase != RefinementPhase.Idle;

        /// <summary>What the wearer reads: this flow's <see cref="Message"/> while it has one, else <paramref name="calibrationMessage"/> (the calibration's).</summary>
        public string Shown(string calibrationMessage) => ShowsMessage ? Message : calibrationMessage ?? string.Empty;

        /// <summary>
        /// Before <paramref name="pipeline"/> runs <paramref name="frame"/>: ends the running exercise when its time is up or a
        /// controller's trigger is pressed in this frame (the devices and the any-device rule are the calibration's), and
        /// applies it, so the frame is solved on the refined avatar. Allocation-free unless it ends the exercise.
        /// </summary>
        public RefinementFlowEvents BeforeUpdate(SessionFrame frame, SelfAvatarPipeline pipeline)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            double time = Finite(frame.Time);
            if (Phase != RefinementPhase.Exercising) return RefinementFlowEvents.None;
            if (pipeline == null || !ReferenceEquals(pipeline, _pipeline) || !pipeline.IsRefining)
                return Drop("the pipeline stopped recording the exercise (it was ended or reset from elsewhere, or the pipeline was made again)");
            RefinementFlowEvents events = RefinementFlowEvents.None;
            bool pressed = false;
            List<DeviceEvent> list = frame.Events;
            for (int e = 0; e < list.Count && !pressed; e++)
            {
                if (list[e].Kind != DeviceEventKind.TriggerPressed) continue;
                string ignored = WhyIgnored(list[e].DeviceId, time, pipeline);
                if (ignored == null) pressed = true;
                else
                {
                    Explanation = ignored;
                    events |= RefinementFlowEvents.PressIgnored;
                }
            }
            if (!pressed && time < _endsAt) return events;
            return events | End(pipeline, time, pressed);
        }

        // A time that is not a number or infinite (a broken clock, a bad recording) is a frame in which no time passed, as the
        // pipeline takes it: compared with the end, it ended the exercise.
        private double Finite(double time)
        {
            if (double.IsNaN(time) || double.IsInfinity(time)) return _lastTime;
            _lastTime = time;
            return time;
        }

        /// <summary>
        /// After <paramref name="pipeline"/> ran the frame at <paramref name="time"/> and the calibration flow reported
        /// <paramref name="calibration"/>: starts the exercise when a new calibration completed and <see cref="Enabled"/>,
        /// drops it on a reset, updates the countdown, and ends the summary when its time is up. Allocation-free unless it starts
        /// the exercise.
        /// </summary>
        public RefinementFlowEvents AfterUpdate(double time, SelfAvatarPipeline pipeline, CalibrationFlowEvents calibration)
        {
            time = Finite(time);
            RefinementFlowEvents events = RefinementFlowEvents.None;
            if ((calibration & (CalibrationFlowEvents.Reset | CalibrationFlowEvents.Restored | CalibrationFlowEvents.Calibrated)) != 0) events |= Cancel(pipeline);
            if ((calibration & CalibrationFlowEvents.Calibrated) != 0 && Enabled) events |= Begin(time, pipeline);
            if (Phase == RefinementPhase.Exercising)
            {
                SecondsLeft = Math.Max(0.0, _endsAt - time);
                _shown = Math.Min(_countdown.Length - 1, (int)Math.Ceiling(SecondsLeft));
            }
            else if (Phase == RefinementPhase.Summary && time - _summaryUntil >= 0.0) Phase = RefinementPhase.Idle;
            return events;
        }

        /// <summary>
        /// Drops a running exercise without applying it (a reset, new devices, a restored profile) and takes the summary
        /// down; the recording of <paramref name="pipeline"/>, when it is the one the exercise runs on, is dropped too.
        /// Returns <see cref="RefinementFlowEvents.Cancelled"/> when an exercise was running.
        /// </summary>
        public RefinementFlowEvents Cancel(SelfAvatarPipeline pipeline)
        {
            bool running = Phase == RefinementPhase.Exercising;
            if (running && pipeline != null && ReferenceEquals(pipeline, _pipeline)) pipeline.CancelRefinement();
            if (running) Explanation = "the refinement exercise was dropped (a reset, new devices or a restored calibration)";
            Stop();
            return running ? RefinementFlowEvents.Cancelled : RefinementFlowEvents.None;
        }

        /// <summary>The instruction with <paramref name="seconds"/> left in the exercise. Allocates.</summary>
        public static string Countdown(int seconds) =>
            Instruction + "\n" + seconds.ToString(System.Globalization.CultureInfo.InvariantCulture) + " s left; press a trigger when done.";

        /// <summary>
        /// What the wearer is told an exercise changed: per arm its length before and after (mm), or that it was kept (and
        /// why, when too little of its motion was seen). Allocates.
        /// </summary>
        public static string Summarize(RefinementReport report)
        {
            if (report == null) throw new ArgumentNullException(nameof(report));
            LimbRefinement left = report.Arm(BodySide.Left), right = report.Arm(BodySide.Right);
            bool unseen = TooLittle(left) || TooLittle(right);
            var text = new StringBuilder(160);
            text.Append(report.Changed ? "Arms refined from your motion." : unseen ? "Arms kept: too little arm motion was seen (keep both controllers tracked)." : "Arms kept: they already fit your reach.");
            Arm(text, "Left", left);
            Arm(text, "Right", right);
            return text.ToString();
        }

        private static bool TooLittle(LimbRefinement arm) => !arm.Refined && arm.Samples < ProportionRefinement.DefaultMinimumSamples;

        private static void Arm(StringBuilder text, string side, LimbRefinement arm)
        {
            text.Append('\n').Append(side).Append(" arm: ");
            text.Append(arm.Refined ? FormattableString.Invariant($"{arm.LengthBefore * 1000f:0} -> {arm.LengthAfter * 1000f:0} mm") : FormattableString.Invariant($"{arm.LengthBefore * 1000f:0} mm, kept"));
            if (TooLittle(arm)) text.Append(" (too little motion seen)");
            text.Append('.');
        }

        private RefinementFlowEvents Begin(double time, SelfAvatarPipeline pipeline)
        {
            int capacity = Math.Max(1800, (int)Math.Ceiling(_seconds * RecorderRate));
            if (pipeline == null || !pipeline.BeginRefinement(capacity))
            {
                Explanation = "the refinement exercise cannot start: the pipeline is not calibrated";
                return RefinementFlowEvents.BeginRefused;
            }
            _pipeline = pipeline;
            _startedAt = time;
            _endsAt = time + _seconds;
            int whole = (int)Math.Ceiling(_seconds);
            if (_countdown.Length != whole + 1)
            {
                _countdown = new string[whole + 1];
                for (int s = 0; s <= whole; s++) _countdown[s] = Countdown(s);
            }
            _shown = whole;
            SecondsLeft = _seconds;
            Phase = RefinementPhase.Exercising;
            Explanation = FormattableString.Invariant($"the refinement exercise started ({_seconds:0.#} s, up to {capacity} frames recorded)");
            return RefinementFlowEvents.Began;
        }

        private RefinementFlowEvents End(SelfAvatarPipeline pipeline, double time, bool pressed)
        {
            RefinementReport report = pipeline.EndRefinement();
            if (report == null) return Drop("the pipeline had no exercise to end");
            LastReport = report;
            Summary = Summarize(report);
            Explanation = FormattableString.Invariant($"the refinement exercise ended {(pressed ? "by a trigger press" : "on time")} after {time - _startedAt:0.0} s: {report}");
            _pipeline = null;
            Phase = RefinementPhase.Summary;
            SecondsLeft = 0.0;
            _summaryUntil = time + SummarySeconds;
            return report.Changed ? RefinementFlowEvents.Ended | RefinementFlowEvents.ArmsChanged | RefinementFlowEvents.SaveProfile : RefinementFlowEvents.Ended;
        }

        private RefinementFlowEvents Drop(string why)
        {
            Explanation = why;
            Stop();
            return RefinementFlowEvents.Cancelled;
        }

        private void Stop()
        {
            Phase = RefinementPhase.Idle;
            SecondsLeft = 0.0;
            _pipeline = null;
        }

        // Why this press does not end the exercise, or null when it does: the calibration's rule for which device may press,
        // and not in the first seconds.
        private string WhyIgnored(int deviceId, double time, SelfAvatarPipeline pipeline)
        {
            IReadOnlyList<DeviceInfo> devices = pipeline.Devices;
            DeviceInfo device = null;
            for (int d = 0; d < devices.Count && device == null; d++)
                if (devices[d].Id == deviceId) device = devices[d];
            if (device == null || (!pipeline.Settings.Calibration.AcceptTriggerFromAnyDevice && device.Class != DeviceClass.Controller)) return PressNotController;
            return time - _startedAt < IgnorePressesSeconds ? PressTooEarly : null;
        }
    }
}
