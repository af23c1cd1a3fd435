using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Records a live headset to a session (format v1, Documentation~/session-format.md) as it happens: every device's
    /// pose and tracking, its analog trigger and grip, and the trigger events, one frame at a time through a
    /// <see cref="SessionWriter"/>: nothing but the line being written is held in memory. Allocation-free per frame.
    /// </summary>
    public sealed class SessionRecorder : IDisposable
    {
        private readonly SessionWriter _writer;
        private readonly SessionFrame _frame;
        private double _start = double.NaN;

        /// <summary>Starts a recording of the devices of <paramref name="writer"/>'s header into it (the recorder then owns it).</summary>
        public SessionRecorder(SessionWriter writer)
        {
            _writer = writer ?? throw new ArgumentNullException(nameof(writer));
            _frame = new SessionFrame(writer.Header);
        }

        /// <summary>The frames recorded so far.</summary>
        public int FrameCount => _writer.FrameCount;

        /// <summary>
        /// Records one frame at <paramref name="time"/> (any clock; the session's times start at 0 with the first frame):
        /// every device's sample (in header order), its analog trigger and grip (empty spans: none), and this frame's events.
        /// A time earlier than the previous frame's is recorded as the previous one (a clock that stepped back), and so is a
        /// time that is not finite (the first frame's: 0).
        /// A tracked sample the format cannot hold (not finite, a non-unit quaternion, beyond ±<see cref="SessionLimits.MaxPosition"/>)
        /// is recorded as lost.
        /// </summary>
        public void Record(double time, ReadOnlySpan<DeviceSample> samples, ReadOnlySpan<float> trigger, ReadOnlySpan<float> grip, IReadOnlyList<DeviceEvent> events)
        {
            int n = _frame.Samples.Length;
            if (samples.Length != n) throw new ArgumentException($"Expected {n} samples, got {samples.Length}.", nameof(samples));
            // A time that is not finite (a broken clock) is a frame in which no time passed, as the pipeline takes it: it
            // neither starts the session's clock nor moves it (NaN compares false below).
            bool finite = !double.IsNaN(time) && !double.IsInfinity(time);
            if (finite && double.IsNaN(_start)) _start = time;
            double t = finite ? time - _start : double.NaN;
            _frame.Time = t > _frame.Time ? t : FrameCount == 0 ? 0 : _frame.Time;
            for (int d = 0; d < n; d++)
            {
                DeviceSample s = samples[d];
                // A tracked sample the writer would refuse is recorded as lost: NaN or a non-unit quaternion, as the pipeline
                // treats it; a position beyond the format's ±10 km (a driver glitch, which the pipeline's glitch filter
                // drops), rather than the writer's refusal ending the recording.
                _frame.Samples[d] = s.IsTracked && !IsRecordable(s.Pose) ? new DeviceSample(RigidPose.Identity, false) : s;
                _frame.Trigger[d] = trigger.Length == n ? Clamp01OrNaN(trigger[d]) : float.NaN;
                _frame.Grip[d] = grip.Length == n ? Clamp01OrNaN(grip[d]) : float.NaN;
            }
            _frame.Events.Clear();
            for (int e = 0; events != null && e < events.Count; e++)
                if (_writer.Header.IndexOf(events[e].DeviceId) >= 0) _frame.Events.Add(events[e]);
            _writer.WriteFrame(_frame);
        }

        /// <summary>Ends the session (writes its end line).</summary>
        public void Complete() => _writer.Complete();

        /// <summary>Completes the session and closes the writer.</summary>
        public void Dispose() => _writer.Dispose();

        private static bool IsRecordable(RigidPose p) =>
            p.IsValid && Math.Abs(p.Position.X) <= SessionLimits.MaxPosition && Math.Abs(p.Position.Y) <= SessionLimits.MaxPosition
            && Math.Abs(p.Position.Z) <= SessionLimits.MaxPosition;

        private static float Clamp01OrNaN(float v) => float.IsNaN(v) ? float.NaN : v < 0f ? 0f : v > 1f ? 1f : v;
    }
}
