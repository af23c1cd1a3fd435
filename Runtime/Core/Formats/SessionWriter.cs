using System;
using System.IO;
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
        private readonly StringBuilder _line = new StringBuilder(128);
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

        /// <summary>Writes one frame.</summary>
        /// <exception cref="ArgumentException">The frame is for another header, its time goes backwards or is not finite,
        /// an event names an unknown device, or a tracked pose is not valid.</exception>
        public void WriteFrame(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (_completed) throw new InvalidOperationException("The session is complete.");
            if (frame.Samples.Length != Header.Devices.Count) throw new ArgumentException("The frame was made for another header.", nameof(frame));
            if (double.IsNaN(frame.Time) || double.IsInfinity(frame.Time) || frame.Time < _lastTime)
                throw new ArgumentException($"Frame time {frame.Time} is not finite or goes backwards (previous {_lastTime}).", nameof(frame));
            _lastTime = frame.Time;

            _writer.WriteLine("frame " + SessionText.F(frame.Time));
            for (int i = 0; i < frame.Samples.Length; i++)
            {
                DeviceSample s = frame.Samples[i];
                Pose p = s.Pose;
                if (s.IsTracked && !p.IsValid) throw new ArgumentException($"Device {Header.Devices[i].Id} is tracked with an invalid pose {p}.", nameof(frame));
                if (!s.IsTracked && !(Vectors.IsFinite(p.Position) && Rotations.IsFinite(p.Rotation))) p = Pose.Identity;
                _line.Clear().Append("pose ").Append(Header.Devices[i].Id).Append(s.IsTracked ? " tracked " : " lost ");
                AppendPose(p);
                _writer.WriteLine(_line.ToString());
                if (!float.IsNaN(frame.Trigger[i]) || !float.IsNaN(frame.Grip[i]))
                {
                    _line.Clear().Append("input ").Append(Header.Devices[i].Id).Append(' ')
                        .Append(Analog(frame.Trigger[i])).Append(' ').Append(Analog(frame.Grip[i]));
                    _writer.WriteLine(_line.ToString());
                }
            }
            foreach (InputEvent e in frame.Events)
            {
                if (Header.IndexOf(e.DeviceId) < 0) throw new ArgumentException($"Event from unknown device {e.DeviceId}.", nameof(frame));
                _writer.WriteLine("event " + e.DeviceId + " " + SessionText.EventName(e.Kind));
            }
            for (int b = 0; b < frame.HasTruth.Length; b++)
            {
                if (!frame.HasTruth[b]) continue;
                _line.Clear().Append("truth ").Append(((HumanBone)b).ToString()).Append(' ');
                AppendPose(frame.Truth[b]);
                _writer.WriteLine(_line.ToString());
            }
            FrameCount++;
        }

        /// <summary>Writes the end line (the frame count) and flushes. Called by <see cref="Dispose"/>.</summary>
        public void Complete()
        {
            if (_completed) return;
            _completed = true;
            _writer.WriteLine("end " + FrameCount);
            _writer.Flush();
        }

        /// <summary>Completes the session and releases the writer if owned.</summary>
        public void Dispose()
        {
            Complete();
            if (_ownsWriter) _writer.Dispose();
        }

        private static string Analog(float v) => float.IsNaN(v) ? "-" : SessionText.F(Math.Max(0f, Math.Min(1f, v)));

        private void AppendPose(Pose p)
        {
            _line.Append(SessionText.F(p.Position.X)).Append(' ').Append(SessionText.F(p.Position.Y)).Append(' ').Append(SessionText.F(p.Position.Z)).Append(' ')
                .Append(SessionText.F(p.Rotation.X)).Append(' ').Append(SessionText.F(p.Rotation.Y)).Append(' ')
                .Append(SessionText.F(p.Rotation.Z)).Append(' ').Append(SessionText.F(p.Rotation.W));
        }

        private void WriteHeader()
        {
            _writer.WriteLine($"{SessionText.Magic} {SessionHeader.FormatVersion.Major}.{SessionHeader.FormatVersion.Minor}");
            _writer.WriteLine("units m s");
            _writer.WriteLine("handedness left y-up z-forward");
            _writer.WriteLine("rate " + SessionText.F(Header.Rate));
            foreach (DeviceInfo d in Header.Devices)
            {
                string serial = d.Serial.Length == 0 ? "-" : d.Serial;
                if (!SessionText.IsToken(serial)) throw new ArgumentException($"Serial '{d.Serial}' of device {d.Id} contains white space.");
                _writer.WriteLine($"device {d.Id} {SessionText.ClassName(d.Class)} {serial} {SessionText.RoleName(d.RuntimeRole)}");
            }
            if (Header.HasTrueRoles)
                for (int i = 0; i < Header.Devices.Count; i++)
                    _writer.WriteLine($"truth-role {Header.Devices[i].Id} {SessionText.RoleName(Header.TrueRole(i))}");
            HumanoidMap map = Header.TruthHumanoid;
            if (map != null)
            {
                Skeleton s = map.Skeleton;
                for (int j = 0; j < s.JointCount; j++)
                {
                    string name = s.GetName(j);
                    if (!SessionText.IsToken(name)) throw new ArgumentException($"Joint name '{name}' contains white space.");
                    HumanBone bone = map.BoneOf(j);
                    _line.Clear().Append("truth-joint ").Append(j).Append(' ').Append(s.GetParent(j)).Append(' ')
                        .Append(bone == HumanBone.LastBone ? "-" : bone.ToString()).Append(' ').Append(s.IsEndSite(j) ? "end " : "joint ")
                        .Append(name).Append(' ');
                    AppendPose(s.GetRestLocal(j));
                    _writer.WriteLine(_line.ToString());
                }
            }
            _writer.WriteLine("end-header");
        }
    }
}
