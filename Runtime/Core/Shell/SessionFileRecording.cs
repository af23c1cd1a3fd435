using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// A recording to a session file that appears whole or not at all: frames are streamed (through a
    /// <see cref="SessionRecorder"/>, never the whole session in memory) into <see cref="PartialPath"/> beside the target,
    /// and <see cref="Complete"/> writes the end line, flushes the file to disk and renames it onto <see cref="Path"/> in one
    /// step (replacing an older file of that name). If the process dies first, the target is untouched and the partial file
    /// holds every frame written up to the last flush (at most the writer's buffers, about 68 KiB or a second of a
    /// 90 Hz six-device session, are lost), without its end line:
    /// <see cref="SessionReader"/> reads those frames and then reports the file as truncated.
    /// A device serial the format cannot hold (white space in it, or "-", the format's "no serial": a runtime's serial is
    /// whatever its driver reports) is recorded with '_' in its place (<see cref="Header"/> is the header as recorded), so
    /// that no device's serial stops a recording; ids, classes and roles are recorded as they are.
    /// </summary>
    public sealed class SessionFileRecording : IDisposable
    {
        private const int BufferSize = 1 << 16;
        private readonly FileStream _stream;
        private readonly StreamWriter _text;
        private readonly SessionRecorder _recorder;

        /// <summary>The file name suffix of a recording in progress (or of one a crash interrupted).</summary>
        public const string PartialSuffix = ".partial";

        /// <summary>Starts recording the devices of <paramref name="header"/> to <paramref name="path"/> (its folder is created).</summary>
        /// <exception cref="IOException">The partial file cannot be created.</exception>
        /// <exception cref="ArgumentException">The header holds ground truth the format cannot (a joint name with white space in it).</exception>
        public SessionFileRecording(string path, SessionHeader header)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (header == null) throw new ArgumentNullException(nameof(header));
            Header = WithWritableSerials(header);
            Path = System.IO.Path.GetFullPath(path);
            PartialPath = Path + PartialSuffix;
            Directory.CreateDirectory(System.IO.Path.GetDirectoryName(Path));
            _stream = new FileStream(PartialPath, FileMode.Create, FileAccess.Write, FileShare.Read, 4096);
            try
            {
                _text = new StreamWriter(_stream, new UTF8Encoding(false), BufferSize);
                _recorder = new SessionRecorder(new SessionWriter(_text, Header));
            }
            catch
            {
                _stream.Dispose();
                File.Delete(PartialPath);
                throw;
            }
        }

        /// <summary>
        /// The devices recorded (every frame must be made for them): the header given, or, when a serial had to be
        /// rewritten for the format, a copy with the serials as recorded.
        /// </summary>
        public SessionHeader Header { get; }

        // The header itself when the format can write every serial; otherwise a copy with the serials it can.
        private static SessionHeader WithWritableSerials(SessionHeader header)
        {
            IReadOnlyList<DeviceInfo> devices = header.Devices;
            DeviceInfo[] written = null;
            for (int i = 0; i < devices.Count; i++)
            {
                DeviceInfo d = devices[i];
                string serial = SessionText.WritableSerial(d.Serial);
                if (serial == d.Serial) continue;
                if (written == null)
                {
                    written = new DeviceInfo[devices.Count];
                    for (int k = 0; k < devices.Count; k++) written[k] = devices[k];
                }
                written[i] = new DeviceInfo(d.Id, d.Class, serial, d.RuntimeRole);
            }
            if (written == null) return header;
            DeviceRole[] trueRoles = null;
            if (header.HasTrueRoles)
            {
                trueRoles = new DeviceRole[devices.Count];
                for (int i = 0; i < trueRoles.Length; i++) trueRoles[i] = header.TrueRole(i);
            }
            return new SessionHeader(header.Rate, written, trueRoles, header.TruthHumanoid);
        }

        /// <summary>The file the recording becomes when completed.</summary>
        public string Path { get; }

        /// <summary>Where the frames go until then.</summary>
        public string PartialPath { get; }

        /// <summary>True until <see cref="Complete"/> or <see cref="Abandon"/>.</summary>
        public bool IsOpen { get; private set; } = true;

        /// <summary>The frames recorded so far.</summary>
        public int FrameCount => _recorder.FrameCount;

        /// <summary>
        /// Records one frame (any clock: the session's times start at 0): every device's sample, trigger and grip, and the
        /// frame's events (<see cref="SessionRecorder.Record"/>). Allocation-free.
        /// </summary>
        /// <exception cref="InvalidOperationException">The recording is closed.</exception>
        public void Record(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (!IsOpen) throw new InvalidOperationException("The recording is closed.");
            _recorder.Record(frame.Time, frame.Samples, frame.Trigger, frame.Grip, frame.Events);
        }

        /// <summary>
        /// Ends the session: writes its end line, flushes it to disk and moves it onto <see cref="Path"/> atomically.
        /// Does nothing when already closed.
        /// </summary>
        /// <exception cref="IOException">The file could not be written or moved, now or at an earlier frame (a full disk); the
        /// partial file is left in place with the frames written before the failure.</exception>
        public void Complete()
        {
            if (!IsOpen) return;
            IsOpen = false;
            try
            {
                _recorder.Complete();
                _text.Flush();
                _stream.Flush(true);
            }
            catch (InvalidOperationException e)
            {
                // The writer refuses to end a session one of whose frames failed to be written (a torn line may be in it):
                // to the caller that is the same failure to write the file.
                throw new IOException($"Writing the recording failed at an earlier frame; the frames before it are in {PartialPath}.", e);
            }
            finally
            {
                // Disposing flushes what is buffered: on a full disk that throws again, over the error above.
                try { _stream.Dispose(); } catch (IOException) { }
            }
            if (File.Exists(Path)) File.Replace(PartialPath, Path, null);
            else File.Move(PartialPath, Path);
        }

        /// <summary>Stops without keeping anything: the partial file is deleted and the target left as it was.</summary>
        public void Abandon()
        {
            if (!IsOpen) return;
            IsOpen = false;
            _stream.Dispose();
            File.Delete(PartialPath);
        }

        /// <summary>Completes the recording if it is still open.</summary>
        public void Dispose() => Complete();
    }
}
