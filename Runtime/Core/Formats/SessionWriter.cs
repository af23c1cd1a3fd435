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
    public sealed class SessionWriter : IDisposable
    {
        private readonly TextWriter _writer;
        private readonly bool _ownsWriter;
        private char[] _line = new char[256];
        private int _length;
        private double _lastTime = double.NegativeInfinity;
        private bool _completed;

        /// <summary>Writes the header of <paramref name="header"/> to <paramref name="writer"/>.</summary>
        /// <param name="writer">Where the text goes.</param>
        /// <param name="header">The session header.</param>
        /// <param name="ownsWriter">Dispose <paramref name="writer"/> when this writer is disposed.</param>
        /// <exception cref="ArgumentException">A serial or joint name contains white space or is empty.</exception>
        public SessionWriter(TextWriter writer, SessionHeader header, bool ownsWriter = false)
        {
            _writer = writer ?? throw new ArgumentNullException(nameof(writer));
            Header = header ?? throw new ArgumentNullException(nameof(header));
            _ownsWriter = ownsWriter;
            _writer.NewLine = "\n";
            WriteHeader();
        }

        /// <summary>Opens a file for writing (replacing it) and writes the header.</summary>
        public static SessionWriter Create(string path, SessionHeader header) =>
            new SessionWriter(new StreamWriter(path, false, new UTF8Encoding(false), 1 << 16), header, ownsWriter: true);

        /// <summary>The header written.</summary>
        public SessionHeader Header { get; }

        /// <summary>The number of frames written.</summary>
        public int FrameCount { get; private set; }

        /// <summary>
        /// Writes one frame: its time, one pose line per device (in header order), an input line per device that
        /// has an analog value, its events and its ground-truth joints. Allocates nothing (lines are formatted
        /// into a reused buffer). A lost sample whose pose is not finite is written as the identity pose.
        /// </summary>
        /// <exception cref="ArgumentException">The frame is for another header, its time goes backwards or is not finite,
        /// an event names an unknown device, or a tracked pose or a truth pose is not valid (<see cref="RigidPose.IsValid"/>).</exception>
        /// <exception cref="InvalidOperationException">The session is already complete.</exception>
        public void WriteFrame(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (_completed) throw new InvalidOperationException("The session is complete.");
            if (frame.Samples.Length != Header.Devices.Count) throw new ArgumentException("The frame was made for another header.", nameof(frame));
            if (double.IsNaN(frame.Time) || double.IsInfinity(frame.Time) || frame.Time < _lastTime)
                throw new ArgumentException($"Frame time {frame.Time} is not finite or goes backwards (previous {_lastTime}).", nameof(frame));
            // Check everything before writing anything, so that a rejected frame leaves the file valid.
            for (int i = 0; i < frame.Samples.Length; i++)
                if (frame.Samples[i].IsTracked && !frame.Samples[i].Pose.IsValid)
                    throw new ArgumentException($"Device {Header.Devices[i].Id} is tracked with an invalid pose {frame.Samples[i].Pose}.", nameof(frame));
            for (int k = 0; k < frame.Events.Count; k++)
                if (Header.IndexOf(frame.Events[k].DeviceId) < 0) throw new ArgumentException($"Event from unknown device {frame.Events[k].DeviceId}.", nameof(frame));
            for (int b = 0; b < frame.HasTruth.Length; b++)
                if (frame.HasTruth[b] && !frame.Truth[b].IsValid) throw new ArgumentException($"Truth pose of {(HumanoidBone)b} is not valid: {frame.Truth[b]}.", nameof(frame));
            _lastTime = frame.Time;

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
            FrameCount++;
        }

        /// <summary>Writes the end line (the frame count) and flushes. Called by <see cref="Dispose"/>.</summary>
        public void Complete()
        {
            if (_completed) return;
            _completed = true;
            Begin("end ").Append(FrameCount).EndLine();
            _writer.Flush();
        }

        /// <summary>Completes the session and releases the writer if owned.</summary>
        public void Dispose()
        {
            Complete();
            if (_ownsWriter) _writer.Dispose();
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

        private SessionWriter Append(double v)
        {
            int written;
            while (!v.TryFormat(_line.AsSpan(_length), out written, "R".AsSpan(), CultureInfo.InvariantCulture)) Ensure(_line.Length);
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
                    if (!rest.IsValid) throw new ArgumentException($"Joint '{name}' has an invalid rest pose {rest}.");
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
