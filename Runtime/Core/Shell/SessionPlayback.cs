using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Plays a recorded session (format v1) as a live source would deliver it: in real time (<see cref="Advance"/>: the
    /// playback clock moves by each frame's delta time, and the newest recorded frame at or before it is delivered) or one
    /// recorded frame at a time (<see cref="Step"/>, for tests). Streams the file through a <see cref="SessionReader"/>,
    /// never holding more than two frames. The trigger events of every recorded frame a real-time frame skips are delivered
    /// with it, so a press is never lost at a low frame rate; at the end it loops (times keep increasing) or holds the last
    /// frame. Allocation-free per frame, except when it loops (the session is opened again).
    /// </summary>
    public sealed class SessionPlayback : IDisposable
    {
        // A frame is due when its time is within a tenth of a microsecond of the clock (summed frame times drift).
        private const double ClockTolerance = 1e-7;

        /// <summary>
        /// The longest step one <see cref="Advance"/> plays (1 s): a longer one (a hitch, a game resumed after a pause, a
        /// huge speed) plays that second, not the whole time, so that one call never delivers a flood of frames' events
        /// nor reopens a looping session over and over.
        /// </summary>
        public const double MaxStepSeconds = 1.0;

        private FormatException _lookAheadError; // the frame after the current one could not be read: thrown once the current is delivered
        private readonly Func<SessionReader> _open;
        private readonly List<DeviceEvent> _pending = new List<DeviceEvent>(16);
        private SessionReader _reader;
        private SessionFrame _current, _next;
        private bool _hasCurrent, _hasNext, _currentDelivered;
        private double _clock, _nextOffset, _currentTime;

        /// <summary>
        /// Plays the session <paramref name="open"/> opens (called again for each loop; the playback owns and disposes the
        /// readers). <paramref name="loop"/>: start again after the last frame instead of holding it.
        /// </summary>
        /// <exception cref="FormatException">The session's header or first frame is malformed.</exception>
        public SessionPlayback(Func<SessionReader> open, bool loop)
        {
            _open = open ?? throw new ArgumentNullException(nameof(open));
            Loop = loop;
            _reader = open() ?? throw new ArgumentException("The session factory returned null.", nameof(open));
            try
            {
                Header = _reader.Header;
                _current = _reader.CreateFrame();
                _next = _reader.CreateFrame();
                _hasNext = _reader.ReadFrame(_next);
                if (!_hasNext) throw new FormatException("The session has no frames.");
            }
            catch
            {
                _reader.Dispose(); // its file is not left open
                _reader = null;
                throw;
            }
            _clock = _next.Time;
        }

        /// <summary>The session's header: its devices, in the order every frame's samples come.</summary>
        public SessionHeader Header { get; }

        /// <summary>True to start again after the last frame.</summary>
        public bool Loop { get; set; }

        /// <summary>How many recorded frames have been delivered since the start (loops included).</summary>
        public int FramesPlayed { get; private set; }

        /// <summary>
        /// True once the last frame has been delivered and the playback does not loop; for a truncated or malformed session,
        /// only once its error was thrown (by the <see cref="Step"/> or <see cref="Advance"/> after its last whole frame).
        /// </summary>
        public bool Finished => !_hasNext && !Loop && _lookAheadError == null;

        /// <summary>
        /// Moves the playback clock by <paramref name="deltaSeconds"/> (0 or more) and fills <paramref name="output"/> with the
        /// newest recorded frame at or before it, with the events of every recorded frame passed since the last call; the
        /// first call delivers the first frame (its delta moves nothing). A step is at most <see cref="MaxStepSeconds"/>; while
        /// the last frame is held (not looping) the clock waits on it, so that looping switched on later goes on from there.
        /// Allocation-free (but a loop reopens the session).
        /// </summary>
        /// <exception cref="FormatException">The session is malformed or truncated at the frames reached (thrown on the call
        /// after the one that delivered the last frame that could be read).</exception>
        public void Advance(double deltaSeconds, SessionFrame output)
        {
            CheckOutput(output);
            ThrowPendingError();
            if (_hasCurrent && deltaSeconds > 0 && !double.IsInfinity(deltaSeconds)) _clock += Math.Min(deltaSeconds, MaxStepSeconds);
            _pending.Clear();
            if (!_hasCurrent) TakeNext();
            while (true)
            {
                if (!_hasNext && (_lookAheadError != null || !Rewind())) break;
                if (_next.Time + _nextOffset > _clock + ClockTolerance) break;
                TakeNext();
            }
            if (!_hasNext && !Loop) _clock = Math.Min(_clock, _currentTime); // held: the clock waits on the last frame
            if (!_currentDelivered) for (int e = 0; e < _current.Events.Count; e++) _pending.Add(_current.Events[e]);
            Deliver(output);
        }

        /// <summary>
        /// Delivers exactly the next recorded frame (with its events) into <paramref name="output"/>; false, with the last
        /// frame held and no events, when there is none (and the playback does not loop).
        /// </summary>
        /// <exception cref="FormatException">The session is malformed or truncated at that frame.</exception>
        public bool Step(SessionFrame output)
        {
            CheckOutput(output);
            ThrowPendingError();
            _pending.Clear();
            bool stepped = (_hasNext || (_lookAheadError == null && Rewind())) && TakeNext();
            if (stepped) for (int e = 0; e < _current.Events.Count; e++) _pending.Add(_current.Events[e]);
            if (_hasCurrent) _clock = _currentTime;
            Deliver(output);
            return stepped;
        }

        /// <summary>
        /// Delivers the current frame again (the first frame if none was delivered yet) with no events but those not delivered
        /// yet (a frame's events go with its first delivery): a second read in the same application frame, or a stepped source
        /// read between steps. Allocation-free.
        /// </summary>
        public void Repeat(SessionFrame output)
        {
            CheckOutput(output);
            _pending.Clear();
            if (!_hasCurrent) TakeNext();
            if (!_currentDelivered) for (int e = 0; e < _current.Events.Count; e++) _pending.Add(_current.Events[e]);
            Deliver(output);
        }

        /// <summary>
        /// Fills <paramref name="output"/> with every device lost, no trigger or grip and no events, at the time of the frame
        /// last delivered (the first frame's before any): what a paused source (its component disabled) reports. The clock
        /// does not move and nothing is consumed: the next <see cref="Advance"/>, <see cref="Step"/> or <see cref="Repeat"/>
        /// goes on as if this had not been called. Allocation-free.
        /// </summary>
        public void Pause(SessionFrame output)
        {
            CheckOutput(output);
            output.Clear();
            output.Time = _hasCurrent ? _currentTime : _next.Time + _nextOffset;
        }

        /// <summary>Closes the session.</summary>
        public void Dispose()
        {
            _reader?.Dispose();
            _reader = null;
            _hasNext = false;
        }

        // The lookahead becomes the current frame; its events go with the next delivery.
        private bool TakeNext()
        {
            if (!_hasNext) return false;
            if (_hasCurrent && !_currentDelivered)
                for (int e = 0; e < _current.Events.Count; e++) _pending.Add(_current.Events[e]);
            SessionFrame t = _current;
            _current = _next;
            _next = t;
            _hasCurrent = true;
            _currentDelivered = false;
            _currentTime = _current.Time + _nextOffset;
            FramesPlayed++;
            try
            {
                _hasNext = _reader != null && _reader.ReadFrame(_next);
            }
            catch (FormatException e)
            {
                // A truncated file (a crash-recovered recording): the frame just taken is still delivered; the error comes
                // with the call after.
                _hasNext = false;
                _lookAheadError = e;
            }
            // The events of frames skipped on the way are kept: only the last one's samples are delivered.
            return true;
        }

        private void ThrowPendingError()
        {
            if (_lookAheadError == null || !_currentDelivered) return;
            FormatException e = _lookAheadError;
            _lookAheadError = null;
            throw e;
        }

        // At the end: reopen the session when looping, its times shifted past the last frame's by one nominal frame.
        private bool Rewind()
        {
            if (!Loop || _reader == null) return false;
            _reader.Dispose();
            _reader = _open() ?? throw new InvalidOperationException("The session factory returned null.");
            if (_reader.Header.Devices.Count != Header.Devices.Count) throw new FormatException("The session changed its devices between loops.");
            if (!_reader.ReadFrame(_next)) return false;
            _nextOffset = _currentTime + 1.0 / Header.Rate - _next.Time;
            _hasNext = true;
            return true;
        }

        private void Deliver(SessionFrame output)
        {
            output.Clear();
            if (!_hasCurrent) return;
            output.Time = _currentTime;
            Array.Copy(_current.Samples, output.Samples, output.Samples.Length);
            Array.Copy(_current.Trigger, output.Trigger, output.Trigger.Length);
            Array.Copy(_current.Grip, output.Grip, output.Grip.Length);
            Array.Copy(_current.Truth, output.Truth, output.Truth.Length);
            Array.Copy(_current.HasTruth, output.HasTruth, output.HasTruth.Length);
            for (int e = 0; e < _pending.Count; e++) output.Events.Add(_pending[e]);
            _pending.Clear();
            _currentDelivered = true;
        }

        private void CheckOutput(SessionFrame output)
        {
            if (output == null) throw new ArgumentNullException(nameof(output));
            if (output.Samples.Length != Header.Devices.Count) throw new ArgumentException("The frame was made for another header.", nameof(output));
        }
    }
}
