using System;
using System.IO;
using System.Globalization;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Writes a session (format v1) as a stream: the header first, then one frame at a time, then an end
    /// line with the frame count when disposed (<see cref="Complete"/>). Nothing is held in memory but the
    /// line being written. See Documentation~/session-format.md.
    /// </summary>
    /// <remarks>
    /// A file made by <see cref="Create"/> is written whole or not at all (<see cref="AtomicFileWriter"/>): the frames go
    /// to a temporary file beside the target, which replaces the target when the session is complete. Until then a
    /// file already at the path is untouched, and it stays so when writing fails (the writer's own I/O, a header the
    /// format cannot hold) or when <see cref="Discard"/> abandons the session.
    /// </remarks>
    public sealed class SessionWriter : IDisposable
    {
        private readonly TextWriter _writer;
        private readonly bool _ownsWriter;
        private readonly AtomicFileWriter _file;
        private char[] _line = new char[256];
        private int _length;
        private double _lastTime = double.NegativeInfinity;
        private bool _completed;
        private bool _failed;
        private bool _disposed;

        /// <summary>Writes the header of <paramref name="header"/> to <paramref name="writer"/>.</summary>
        /// <param name="writer">Where the text goes.</param>
        /// <param name="header">The session header.</param>
        /// <param name="ownsWriter">Dispose <paramref name="writer"/> when this writer is disposed.</param>
        /// <exception cref="ArgumentException">A serial or joint name contains white space or is empty, a serial is "-", or a joint's rest
        /// pose is not one the format holds.</exception>
        public SessionWriter(TextWriter writer, SessionHeader header, bool ownsWriter = false)
            : this(writer, header, ownsWriter, null)
        {
        }

        private SessionWriter(TextWriter writer, SessionHeader header, bool ownsWriter, AtomicFileWriter file)
        {
            _writer = writer ?? throw new ArgumentNullException(nameof(writer));
            Header = header ?? throw new ArgumentNullException(nameof(header));
            _ownsWriter = ownsWriter;
            _file = file;
            _writer.NewLine = "\n";
            WriteHeader();
        }

        /// <summary>
        /// Starts a session file at <paramref name="path"/> and writes the header. The file appears (replacing any file
        /// there) only when the session is complete (<see cref="Complete"/> or <see cref="Dispose"/>); see the remarks.
        /// </summary>
        /// <exception cref="ArgumentException">The header holds a serial or joint name the format cannot (nothing is written).</exception>
        /// <exception cref="IOException">The file cannot be created.</exception>
        public static SessionWriter Create(string path, SessionHeader header)
        {
            if (header == null) throw new ArgumentNullException(nameof(header));
            var file = new AtomicFileWriter(path);
            try
            {
                return new SessionWriter(new StreamWriter(file.Stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true), header, false, file);
            }
            catch
            {
                file.Dispose(); // the temporary file goes; a file already at the path stays as it was
                throw;
            }
        }

        /// <summary>
        /// Writes a whole session file: <paramref name="write"/> writes the frames to a writer made by <see cref="Create"/>,
        /// and the file appears only if it returns; if it throws, the session is discarded (a file already at the path stays
        /// as it was) and the exception goes on. A bare <c>using</c> would complete the frames written so far instead.
        /// </summary>
        /// <exception cref="ArgumentException">The header holds a serial or joint name the format cannot (nothing is written).</exception>
        /// <exception cref="IOException">The file cannot be created or written.</exception>
        public static void WriteFile(string path, SessionHeader header, Action<SessionWriter> write)
        {
            if (write == null) throw new ArgumentNullException(nameof(write));
            using (SessionWriter writer = Create(path, header))
            {
                try
                {
                    write(writer);
                    writer.Complete();
                }
                catch
                {
                    writer.Discard();
                    throw;
                }
            }
        }

        /// <summary>The header written.</summary>
        public SessionHeader Header { get; }

        /// <summary>The number of frames written.</summary>
        public int FrameCount { get; private set; }

        /// <summary>
        /// Writes one frame: its time, one pose line per device (in header order), an input line per device that
        /// has an analog value, its events and its ground-truth joints. Allocates nothing (lines are formatted
        /// into a reused buffer). A lost sample whose pose is not finite is written as the identity pose.
        /// </summary>
        /// <exception cref="ArgumentException">The frame is for another header, its time goes backwards or is beyond
        /// ±<see cref="SessionLimits.MaxTime"/>, it has more than <see cref="SessionLimits.MaxEventsPerFrame"/> events, an event
        /// names an unknown device, or a tracked pose or a truth pose is not valid (<see cref="RigidPose.IsValid"/>) or lies
        /// beyond ±<see cref="SessionLimits.MaxPosition"/>.</exception>
        /// <exception cref="InvalidOperationException">The session is already complete, discarded, or failed.</exception>
        public void WriteFrame(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            CheckOpen();
            if (frame.Samples.Length != Header.Devices.Count) throw new ArgumentException("The frame was made for another header.", nameof(frame));
            if (!(Math.Abs(frame.Time) <= SessionLimits.MaxTime) || frame.Time < _lastTime)
                throw new ArgumentException($"Frame time {frame.Time} is not finite, beyond ±{SessionLimits.MaxTime} s, or goes backwards (previous {_lastTime}).", nameof(frame));
            // Check everything before writing anything, so that a rejected frame leaves the file valid.
            for (int i = 0; i < frame.Samples.Length; i++)
                if (frame.Samples[i].IsTracked && !IsWritable(frame.Samples[i].Pose))
                    throw new ArgumentException($"Device {Header.Devices[i].Id} is tracked with an invalid pose {frame.Samples[i].Pose}.", nameof(frame));
            if (frame.Events.Count > SessionLimits.MaxEventsPerFrame)
                throw new ArgumentException($"{frame.Events.Count} events in one frame; the format holds at most {SessionLimits.MaxEventsPerFrame}.", nameof(frame));
            for (int k = 0; k < frame.Events.Count; k++)
                if (Header.IndexOf(frame.Events[k].DeviceId) < 0) throw new ArgumentException($"Event from unknown device {frame.Events[k].DeviceId}.", nameof(frame));
            for (int b = 0; b < frame.HasTruth.Length; b++)
                if (frame.HasTruth[b] && !IsWritable(frame.Truth[b])) throw new ArgumentException($"Truth pose of {(HumanoidBone)b} is not valid: {frame.Truth[b]}.", nameof(frame));
            _lastTime = frame.Time;
            try
            {
                WriteFrameLines(frame);
            }
            catch
            {
                _failed = true; // a torn line may be in the text: the session must not be completed
                throw;
            }
            FrameCount++;
        }

        // Valid (finite, unit quaternion) and within the format's positions.
        private static bool IsWritable(RigidPose p) =>
            p.IsValid && Math.Abs(p.Position.X) <= SessionLimits.MaxPosition && Math.Abs(p.Position.Y) <= SessionLimits.MaxPosition && Math.Abs(p.Position.Z) <= SessionLimits.MaxPosition;

        private void CheckOpen()
        {
            if (_failed) throw new InvalidOperationException("The session was discarded, or writing it failed earlier; it cannot be continued.");
            if (_completed) throw new InvalidOperationException("The session is complete.");
        }

        private void WriteFrameLines(SessionFrame frame)
        {

            Begin("frame ").Append(frame.Time).EndLine();
            for (int i = 0; i < frame.Samples.Length; i++)
            {
                DeviceSample s = frame.Samples[i];
                RigidPose p = s.Pose;
                if (!s.IsTracked && !(Vectors.IsFinite(p.Position) && Rotations.IsFinite(p.Rotation))) p = RigidPose.Identity;
                Begin("pose ").Append(Header.Devices[i].Id).Append(s.IsTracked ? " tracked " : " lost ").Append(p).EndLine();
                if (!float.IsNaN(frame.Trigger[i]) || !float.IsNaN(frame.Grip[i]))
                    Begin("input ").Append(Header.Devices[i].Id).Append(" ").AppendAnalog(frame.Trigger[i]).Append(" ").AppendAnalog(frame.Grip[i]).EndLine();
            }
            for (int k = 0; k < frame.Events.Count; k++)
            {
                DeviceEvent e = frame.Events[k];
                Begin("event ").Append(e.DeviceId).Append(" ").Append(SessionText.EventName(e.Kind)).EndLine();
            }
            for (int b = 0; b < frame.HasTruth.Length; b++)
                if (frame.HasTruth[b]) Begin("truth ").Append(SessionText.BoneName((HumanoidBone)b)).Append(" ").Append(frame.Truth[b]).EndLine();
        }

        /// <summary>
        /// Writes the end line (the frame count) and flushes; for a file made by <see cref="Create"/>, the file then replaces
        /// any file at its path. Called by <see cref="Dispose"/>.
        /// </summary>
        /// <exception cref="InvalidOperationException">The session was discarded, or writing it failed earlier.</exception>
        /// <exception cref="IOException">The file cannot be written or replaced (a file at its path is left as it was).</exception>
        public void Complete()
        {
            if (_completed) return;
            if (_failed) throw new InvalidOperationException("The session was discarded, or writing it failed earlier; it cannot be completed.");
            try
            {
                Begin("end ").Append(FrameCount).EndLine();
                _writer.Flush();
                if (_file != null)
                {
                    _writer.Dispose(); // the stream stays open (leaveOpen) for the commit
                    _file.Commit();
                }
            }
            catch
            {
                _failed = true;
                _file?.Dispose();
                throw;
            }
            _completed = true;
        }

        /// <summary>
        /// Abandons the session: no end line is written, and a file made by <see cref="Create"/> is deleted, so that a
        /// file already at its path stays as it was. For a caller whose own code failed mid-session (a recording whose
        /// source broke, a simulation that threw). Text already given to a <see cref="TextWriter"/> stays there.
        /// </summary>
        public void Discard()
        {
            if (_completed) return;
            _failed = true;
            _file?.Dispose();
        }

        /// <summary>
        /// Completes the session (as <see cref="Complete"/>) unless it was discarded or writing it failed, in which case a
        /// file made by <see cref="Create"/> is deleted and a file already at its path left as it was; releases the writer.
        /// </summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            try
            {
                if (!_failed) Complete();
            }
            finally
            {
                if (_file != null) _file.Dispose();
                else if (_ownsWriter) _writer.Dispose();
            }
        }

        private SessionWriter Begin(string keyword)
        {
            _length = 0;
            return Append(keyword);
        }

        private SessionWriter Append(string text)
        {
            Ensure(text.Length);
            text.CopyTo(0, _line, _length, text.Length);
            _length += text.Length;
            return this;
        }

        private SessionWriter Append(int v)
        {
            int written;
            while (!v.TryFormat(_line.AsSpan(_length), out written, default, CultureInfo.InvariantCulture)) Ensure(_line.Length);
            _length += written;
            return this;
        }

        // "R": the shortest text that parses back to the same float/double (exact round trip).
        private SessionWriter Append(float v)
        {
            int written;
            while (!v.TryFormat(_line.AsSpan(_length), out written, "R".AsSpan(), CultureInfo.InvariantCulture)) Ensure(_line.Length);
            _length += written;
            return this;
        }

        // Doubles (the times) through RoundTripNumber: "R" does not round-trip every double on 64-bit .NET Framework.
        private SessionWriter Append(double v)
        {
            int written;
            while (!RoundTripNumber.TryFormat(v, _line.AsSpan(_length), out written)) Ensure(_line.Length);
            _length += written;
            return this;
        }

        private SessionWriter AppendAnalog(float v) => float.IsNaN(v) ? Append("-") : Append(Math.Max(0f, Math.Min(1f, v)));

        private SessionWriter Append(RigidPose p) =>
            Append(p.Position.X).Append(" ").Append(p.Position.Y).Append(" ").Append(p.Position.Z).Append(" ")
                .Append(p.Rotation.X).Append(" ").Append(p.Rotation.Y).Append(" ").Append(p.Rotation.Z).Append(" ").Append(p.Rotation.W);

        private void EndLine()
        {
            Append("\n");
            _writer.Write(_line, 0, _length);
        }

        private void Ensure(int extra)
        {
            if (_length + extra > _line.Length) Array.Resize(ref _line, Math.Max(_line.Length * 2, _length + extra));
        }

        private void WriteHeader()
        {
            Begin(SessionText.Magic).Append(" ").Append(SessionHeader.FormatVersion.Major).Append(".").Append(SessionHeader.FormatVersion.Minor).EndLine();
            Begin("units m s").EndLine();
            Begin("handedness left y-up z-forward").EndLine();
            Begin("rate ").Append(Header.Rate).EndLine();
            foreach (DeviceInfo d in Header.Devices)
            {
                string serial = d.Serial.Length == 0 ? "-" : d.Serial;
                if (!SessionText.IsToken(serial)) throw new ArgumentException($"Serial '{d.Serial}' of device {d.Id} contains white space.");
                // "-" is how the format writes no serial: a serial that is "-" would read back as none (found in review).
                if (d.Serial == "-") throw new ArgumentException($"Serial '-' of device {d.Id}: the session format writes '-' for a device without a serial.");
                Begin("device ").Append(d.Id).Append(" ").Append(SessionText.ClassName(d.Class)).Append(" ").Append(serial).Append(" ")
                    .Append(SessionText.RoleName(d.RuntimeRole)).EndLine();
            }
            if (Header.HasTrueRoles)
                for (int i = 0; i < Header.Devices.Count; i++)
                    Begin("truth-role ").Append(Header.Devices[i].Id).Append(" ").Append(SessionText.RoleName(Header.TrueRole(i))).EndLine();
            HumanoidMap map = Header.TruthHumanoid;
            if (map != null)
            {
                Skeleton s = map.Skeleton;
                for (int j = 0; j < s.JointCount; j++)
                {
                    string name = s.GetName(j);
                    if (!SessionText.IsToken(name)) throw new ArgumentException($"Joint name '{name}' contains white space.");
                    RigidPose rest = s.GetRestLocal(j);
                    if (!IsWritable(rest)) throw new ArgumentException($"Joint '{name}' has an invalid rest pose {rest} (or one beyond ±{SessionLimits.MaxPosition} m).");
                    HumanoidBone bone = map.BoneOf(j);
                    Begin("truth-joint ").Append(j).Append(" ").Append(s.GetParent(j)).Append(" ")
                        .Append(bone == HumanoidBone.LastBone ? "-" : SessionText.BoneName(bone)).Append(s.IsEndSite(j) ? " end " : " joint ")
                        .Append(name).Append(" ").Append(rest).EndLine();
                }
            }
            Begin("end-header").EndLine();
        }
    }
}
