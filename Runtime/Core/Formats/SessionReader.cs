using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Reads a session (format v1) as a stream: the header is read and checked on construction, then
    /// <see cref="ReadFrame"/> fills a reused <see cref="SessionFrame"/> one frame at a time. Any malformed,
    /// truncated or unknown-version content throws a <see cref="FormatException"/> naming the source, the
    /// 1-based line and the problem. See Documentation~/session-format.md.
    /// </summary>
    /// <remarks>
    /// Hostile files are safe to read: time is linear in the file's size, memory grows only with what has been read,
    /// and files beyond <see cref="SessionLimits"/> (devices, truth joints, events per frame, line length, rate, times,
    /// positions) are refused with the usual <c>SOURCE:LINE: problem</c> error.
    /// </remarks>
    public sealed class SessionReader : IDisposable
    {
        private const int MaxTokens = 16;
        private const int MaxLineLength = SessionLimits.MaxLineLength;

        /// <summary>|length² - 1| up to which a quaternion is taken as unit and kept bit for bit (float drift of a long chain of products).</summary>
        private const float UnitTolerance = 1e-5f;
        private readonly TextReader _reader;
        private readonly bool _ownsReader;
        private readonly string _source;
        private readonly int[] _starts = new int[MaxTokens];
        private readonly int[] _lengths = new int[MaxTokens];
        private readonly bool[] _seen;
        private readonly bool[] _seenInput;
        private char[] _buffer = new char[1 << 14];
        private int _bufferPos;
        private int _bufferEnd;
        private bool _endOfText;
        private int _lineStart;
        private int _lineLength;
        private int _tokenCount;
        private int _lineNumber;
        private bool _lineEnded; // the current physical line ended with LF (the text did not stop inside it)
        private bool _contentLineEnded; // the same of the last line that was not blank or a comment
        private bool _unread;
        private FormatException _failure;
        private double _lastTime = double.NegativeInfinity;
        private bool _ended;
        private readonly int _minor;

        /// <summary>Reads and validates the header from <paramref name="reader"/>.</summary>
        /// <param name="reader">The text.</param>
        /// <param name="sourceName">Names the source in error messages.</param>
        /// <param name="ownsReader">Dispose <paramref name="reader"/> with this reader.</param>
        /// <exception cref="FormatException">The header is missing, malformed or of an unknown major version.</exception>
        public SessionReader(TextReader reader, string sourceName, bool ownsReader = false)
        {
            _reader = reader ?? throw new ArgumentNullException(nameof(reader));
            _source = sourceName ?? "session";
            _ownsReader = ownsReader;
            Header = ReadHeader(out _minor);
            _seen = new bool[Header.Devices.Count];
            _seenInput = new bool[Header.Devices.Count];
        }

        /// <summary>Opens a session file and reads its header.</summary>
        /// <exception cref="IOException">The file cannot be read, or the path is a folder.</exception>
        public static SessionReader Open(string path)
        {
            InputFiles.ThrowIfFolder(path);
            return new SessionReader(new StreamReader(path, System.Text.Encoding.UTF8, true, 1 << 16), Path.GetFileName(path), ownsReader: true);
        }

        /// <summary>The session header.</summary>
        public SessionHeader Header { get; }

        /// <summary>The number of frames read so far.</summary>
        public int FrameCount { get; private set; }

        /// <summary>A frame buffer sized for this session's header.</summary>
        public SessionFrame CreateFrame() => new SessionFrame(Header);

        /// <summary>
        /// Reads the next frame into <paramref name="frame"/>; false at the end of the session (after the
        /// end line has been checked against the frame count).
        /// </summary>
        /// <remarks>
        /// Allocates nothing. After a <see cref="FormatException"/> the content of <paramref name="frame"/> is undefined
        /// and every later call throws the same error; the frames returned before it are whole and valid.
        /// </remarks>
        /// <exception cref="FormatException">The frame is malformed, or the file ends without its end line (truncated).</exception>
        public bool ReadFrame(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (frame.Samples.Length != Header.Devices.Count) throw new ArgumentException("The frame was made for another header.", nameof(frame));
            if (_failure != null) throw new FormatException(_failure.Message);
            try
            {
                return ReadFrameCore(frame);
            }
            catch (FormatException e)
            {
                _failure = e; // the stream position is now unreliable: every later call reports the same problem
                throw;
            }
        }

        private bool ReadFrameCore(SessionFrame frame)
        {
            if (_ended) return false;
            if (!NextLine()) throw Error(_lineNumber + 1, $"the file ends after {FrameCount} frames without its 'end' line (truncated?)");
            if (Is(0, "end"))
            {
                Expect(2, "end FRAME_COUNT");
                int declared = Int(1);
                if (declared != FrameCount) throw Error(_lineNumber, $"'end {declared}' but the file has {FrameCount} frames");
                _ended = true;
                if (NextLine()) throw Error(_lineNumber, "content after the 'end' line");
                return false;
            }
            if (!Is(0, "frame")) throw Error(_lineNumber, $"expected 'frame' or 'end', found '{Quote(0)}'");
            Expect(2, "frame TIME");
            frame.Clear();
            int frameLine = _lineNumber;
            double time = Double(1);
            if (!(Math.Abs(time) <= SessionLimits.MaxTime)) throw Error(_lineNumber, $"time {time.ToString("R", CultureInfo.InvariantCulture)} is beyond ±{SessionLimits.MaxTime.ToString("R", CultureInfo.InvariantCulture)} s");
            if (time < _lastTime) throw Error(_lineNumber, $"time {time.ToString("R", CultureInfo.InvariantCulture)} goes back before {_lastTime.ToString("R", CultureInfo.InvariantCulture)}");
            _lastTime = time;
            frame.Time = time;
            Array.Clear(_seen, 0, _seen.Length);
            Array.Clear(_seenInput, 0, _seenInput.Length);

            while (NextLine())
            {
                if (Is(0, "frame") || Is(0, "end"))
                {
                    Unread();
                    break;
                }
                if (Is(0, "pose"))
                {
                    Expect(10, "pose ID tracked|lost PX PY PZ QX QY QZ QW");
                    int index = Device(1);
                    if (_seen[index]) throw Error(_lineNumber, $"device {Header.Devices[index].Id} has two poses in one frame");
                    _seen[index] = true;
                    bool tracked;
                    if (Is(2, "tracked")) tracked = true;
                    else if (Is(2, "lost")) tracked = false;
                    else throw Error(_lineNumber, $"expected 'tracked' or 'lost', found '{Quote(2)}'");
                    RigidPose p = ReadPose(3, tracked);
                    frame.Samples[index] = new DeviceSample(p, tracked);
                }
                else if (Is(0, "input"))
                {
                    Expect(4, "input ID TRIGGER GRIP");
                    int index = Device(1);
                    if (_seenInput[index]) throw Error(_lineNumber, $"device {Header.Devices[index].Id} has two input lines in one frame");
                    _seenInput[index] = true;
                    frame.Trigger[index] = Analog(2);
                    frame.Grip[index] = Analog(3);
                }
                else if (Is(0, "event"))
                {
                    Expect(3, "event ID KIND");
                    int index = Device(1);
                    if (!SessionText.TryEvent(Token(2), out DeviceEventKind kind)) throw Error(_lineNumber, $"unknown event '{Quote(2)}'");
                    if (frame.Events.Count == SessionLimits.MaxEventsPerFrame) throw Error(_lineNumber, $"more than {SessionLimits.MaxEventsPerFrame} events in one frame (the format's limit)");
                    frame.Events.Add(new DeviceEvent(Header.Devices[index].Id, kind));
                }
                else if (Is(0, "truth"))
                {
                    Expect(9, "truth BONE PX PY PZ QX QY QZ QW");
                    if (!TryBone(Token(1), out HumanoidBone bone)) throw Error(_lineNumber, $"unknown humanoid bone '{Quote(1)}'");
                    if (frame.HasTruth[(int)bone]) throw Error(_lineNumber, $"bone {SessionText.BoneName(bone)} has two truth poses in one frame");
                    frame.Truth[(int)bone] = ReadPose(2, true);
                    frame.HasTruth[(int)bone] = true;
                }
                else if (_minor > SessionHeader.FormatVersion.Minor) continue; // a newer minor version's line: skipped
                else throw Error(_lineNumber, $"unknown line '{Quote(0)}' in a frame");
            }
            for (int i = 0; i < _seen.Length; i++)
                if (!_seen[i]) throw Error(_unread ? _lineNumber : _lineNumber + 1, $"the frame at line {frameLine} has no pose for device {Header.Devices[i].Id}{(_unread ? "" : " (truncated?)")}");
            // The text stopped inside the frame's last line: a crash may have cut it inside a number that still parses
            // ("0.95" cut to "0.9"), so the frame may hold values never written. Only the end line may lack its line end.
            if (!_unread && !_contentLineEnded)
                throw Error(_lineNumber, $"the file ends inside this line, in the frame at line {frameLine}, without its 'end' line (truncated?)");
            FrameCount++;
            return true;
        }

        /// <summary>Releases the reader if owned.</summary>
        public void Dispose()
        {
            if (_ownsReader) _reader.Dispose();
        }

        private SessionHeader ReadHeader(out int minor)
        {
            if (!NextLine()) throw Error(1, "the file is empty; expected 'avatargo-session 1.0'");
            if (!Is(0, SessionText.Magic)) throw Error(_lineNumber, $"not an AvatarGo session: expected '{SessionText.Magic} 1.0', found '{Quote(0)}'");
            Expect(2, SessionText.Magic + " VERSION");
            ReadOnlySpan<char> v = Token(1);
            int dot = v.IndexOf('.');
            if (dot < 0 || !int.TryParse(v.Slice(0, dot).ToString(), NumberStyles.None, CultureInfo.InvariantCulture, out int major)
                || !int.TryParse(v.Slice(dot + 1).ToString(), NumberStyles.None, CultureInfo.InvariantCulture, out minor))
                throw Error(_lineNumber, $"version '{Shorten(v.ToString())}' is not MAJOR.MINOR");
            if (major != SessionHeader.FormatVersion.Major)
                throw Error(_lineNumber, $"format version {Shorten(v.ToString())} is not supported (this reader reads {SessionHeader.FormatVersion.Major}.x)");

            float rate = float.NaN;
            bool units = false, handedness = false;
            var devices = new List<DeviceInfo>();
            var deviceIds = new HashSet<int>();
            var trueRoles = new Dictionary<int, DeviceRole>();
            var names = new List<string>();
            var nameSet = new HashSet<string>(StringComparer.Ordinal);
            var parents = new List<int>();
            var rest = new List<RigidPose>();
            var endSites = new List<bool>();
            var bones = new List<KeyValuePair<HumanoidBone, string>>();
            var boneMapped = new bool[HumanoidBones.Count];
            while (true)
            {
                if (!NextLine()) throw Error(_lineNumber + 1, "the file ends inside the header (no 'end-header')");
                if (Is(0, "end-header")) break;
                if (Is(0, "units"))
                {
                    if (units) throw Error(_lineNumber, "a second 'units' line");
                    Expect(3, "units m s");
                    if (!Is(1, "m") || !Is(2, "s")) throw Error(_lineNumber, "only 'units m s' (metres, seconds) is defined");
                    units = true;
                }
                else if (Is(0, "handedness"))
                {
                    if (handedness) throw Error(_lineNumber, "a second 'handedness' line");
                    Expect(4, "handedness left y-up z-forward");
                    if (!Is(1, "left") || !Is(2, "y-up") || !Is(3, "z-forward")) throw Error(_lineNumber, "only 'handedness left y-up z-forward' (Unity's frame) is defined");
                    handedness = true;
                }
                else if (Is(0, "rate"))
                {
                    if (!float.IsNaN(rate)) throw Error(_lineNumber, "a second 'rate' line");
                    Expect(2, "rate HZ");
                    rate = Float(1);
                    if (!(rate >= SessionLimits.MinRate && rate <= SessionLimits.MaxRate))
                        throw Error(_lineNumber, $"the rate must be from {SessionLimits.MinRate.ToString(CultureInfo.InvariantCulture)} to {SessionLimits.MaxRate.ToString(CultureInfo.InvariantCulture)} Hz");
                }
                else if (Is(0, "device"))
                {
                    Expect(5, "device ID CLASS SERIAL ROLE");
                    int id = Int(1);
                    if (id < 0) throw Error(_lineNumber, "device ids are non-negative");
                    if (!deviceIds.Add(id)) throw Error(_lineNumber, $"device id {id} is used twice");
                    if (devices.Count == SessionLimits.MaxDevices) throw Error(_lineNumber, $"more than {SessionLimits.MaxDevices} devices (the format's limit)");
                    if (!SessionText.TryClass(Token(2), out DeviceClass c)) throw Error(_lineNumber, $"unknown device class '{Quote(2)}' (hmd, controller, tracker)");
                    if (!SessionText.TryRole(Token(4), out DeviceRole role)) throw Error(_lineNumber, $"unknown role '{Quote(4)}'");
                    string serial = Token(3).ToString();
                    devices.Add(new DeviceInfo(id, c, serial == "-" ? "" : serial, role));
                }
                else if (Is(0, "truth-role"))
                {
                    Expect(3, "truth-role ID ROLE");
                    int id = Int(1);
                    if (!SessionText.TryRole(Token(2), out DeviceRole role)) throw Error(_lineNumber, $"unknown role '{Quote(2)}'");
                    if (trueRoles.ContainsKey(id)) throw Error(_lineNumber, $"device {id} has two truth-role lines");
                    if (trueRoles.Count == SessionLimits.MaxDevices) throw Error(_lineNumber, $"more than {SessionLimits.MaxDevices} truth-role lines (one per device at most)");
                    trueRoles[id] = role;
                }
                else if (Is(0, "truth-joint"))
                {
                    Expect(13, "truth-joint INDEX PARENT BONE joint|end NAME PX PY PZ QX QY QZ QW");
                    if (Int(1) != names.Count) throw Error(_lineNumber, $"joint index {Int(1)} out of order (expected {names.Count})");
                    if (names.Count == SessionLimits.MaxTruthJoints) throw Error(_lineNumber, $"more than {SessionLimits.MaxTruthJoints} truth joints (the format's limit)");
                    int parent = Int(2);
                    if (parent < -1 || parent >= names.Count) throw Error(_lineNumber, $"parent {parent} must be -1 or an earlier joint");
                    // An end point has no joints below it (found in review: one that had was read, and its solved motion
                    // written by `evaluate --bvh-out` as a BVH no reader takes).
                    if (parent >= 0 && endSites[parent]) throw Error(_lineNumber, $"parent {parent} is an end point ('end'), which has no joints below it");
                    string name = Token(5).ToString();
                    if (!nameSet.Add(name)) throw Error(_lineNumber, $"joint name '{Shorten(name)}' is used twice");
                    bool end;
                    if (Is(4, "end")) end = true;
                    else if (Is(4, "joint")) end = false;
                    else throw Error(_lineNumber, $"expected 'joint' or 'end', found '{Quote(4)}'");
                    if (!Is(3, "-"))
                    {
                        if (!TryBone(Token(3), out HumanoidBone bone)) throw Error(_lineNumber, $"unknown humanoid bone '{Quote(3)}'");
                        if (boneMapped[(int)bone]) throw Error(_lineNumber, $"bone {bone} is mapped twice");
                        boneMapped[(int)bone] = true;
                        bones.Add(new KeyValuePair<HumanoidBone, string>(bone, name));
                    }
                    names.Add(name);
                    parents.Add(parent);
                    endSites.Add(end);
                    rest.Add(ReadPose(6, true));
                }
                else if (minor > SessionHeader.FormatVersion.Minor) continue;
                else throw Error(_lineNumber, $"unknown header line '{Quote(0)}'");
            }
            if (!units) throw Error(_lineNumber, "the header has no 'units' line");
            if (!handedness) throw Error(_lineNumber, "the header has no 'handedness' line");
            if (float.IsNaN(rate)) throw Error(_lineNumber, "the header has no 'rate' line");
            if (devices.Count == 0) throw Error(_lineNumber, "the header lists no devices");

            DeviceRole[] roles = null;
            if (trueRoles.Count > 0)
            {
                roles = new DeviceRole[devices.Count];
                for (int i = 0; i < devices.Count; i++)
                    if (!trueRoles.TryGetValue(devices[i].Id, out roles[i])) throw Error(_lineNumber, $"device {devices[i].Id} has no truth-role while others do");
                foreach (int id in trueRoles.Keys)
                    if (!deviceIds.Contains(id)) throw Error(_lineNumber, $"truth-role names unknown device {id}");
            }
            try
            {
                HumanoidMap truth = null;
                if (names.Count > 0) truth = new HumanoidMap(new Skeleton(names, parents, rest, endSites), bones);
                return new SessionHeader(rate, devices, roles, truth);
            }
            catch (ArgumentException e)
            {
                // The checks above should leave nothing for the constructors to reject; if one does, it is still bad content.
                throw Error(_lineNumber, "the header is inconsistent: " + e.Message.Split('\n')[0].TrimEnd('\r'));
            }
        }

        private RigidPose ReadPose(int first, bool mustBeValid)
        {
            var position = new Vector3(Float(first), Float(first + 1), Float(first + 2));
            var rotation = new Quaternion(Float(first + 3), Float(first + 4), Float(first + 5), Float(first + 6));
            if (mustBeValid && !(Math.Abs(position.X) <= SessionLimits.MaxPosition && Math.Abs(position.Y) <= SessionLimits.MaxPosition && Math.Abs(position.Z) <= SessionLimits.MaxPosition))
                throw Error(_lineNumber, $"position ({Quote(first)} {Quote(first + 1)} {Quote(first + 2)}) is beyond ±{SessionLimits.MaxPosition.ToString(CultureInfo.InvariantCulture)} m");
            float lengthSquared = rotation.LengthSquared();
            if (mustBeValid && !Rotations.IsUnit(rotation))
                throw Error(_lineNumber, $"rotation ({Quote(first + 3)} {Quote(first + 4)} {Quote(first + 5)} {Quote(first + 6)}) is not a unit quaternion (length within 1e-3 of 1)");
            // Quaternions already unit to float precision keep their exact bits (a write/read round trip is exact);
            // others are renormalised, and a (nearly) zero one in a lost sample becomes the identity.
            if (MathF.Abs(lengthSquared - 1f) > UnitTolerance) rotation = Rotations.NormalizeOr(rotation, Quaternion.Identity);
            return new RigidPose(position, rotation);
        }

        private float Analog(int i)
        {
            if (Is(i, "-")) return float.NaN;
            float v = Float(i);
            if (v < 0f || v > 1f) throw Error(_lineNumber, $"analog value {v.ToString(CultureInfo.InvariantCulture)} is outside 0..1");
            return v;
        }

        private int Device(int i)
        {
            int id = Int(i);
            int index = Header.IndexOf(id);
            if (index < 0) throw Error(_lineNumber, $"unknown device id {id}");
            return index;
        }

        private static bool TryBone(ReadOnlySpan<char> s, out HumanoidBone bone) => SessionText.TryBone(s, out bone);

        private bool NextLine()
        {
            if (_unread)
            {
                _unread = false;
                return true;
            }
            while (ReadRawLine())
            {
                Tokenise();
                if (_tokenCount > 0 && _buffer[_starts[0]] != '#')
                {
                    _contentLineEnded = _lineEnded;
                    return true;
                }
            }
            return false;
        }

        /// <summary>Makes the next <see cref="NextLine"/> return the current line again (its tokens are kept).</summary>
        private void Unread() => _unread = true;

        /// <summary>
        /// The next physical line into <c>_buffer[_lineStart.._lineStart+_lineLength)</c>, without its LF or CRLF,
        /// and counts it; false at the end of the text. Reads the text in blocks into one reused buffer, so
        /// a line costs no allocation (the buffer only grows for a line longer than it).
        /// </summary>
        private bool ReadRawLine()
        {
            while (true)
            {
                int newline = _buffer.AsSpan(_bufferPos, _bufferEnd - _bufferPos).IndexOf('\n');
                if (newline >= 0 || (_endOfText && _bufferPos < _bufferEnd))
                {
                    int end = newline >= 0 ? _bufferPos + newline : _bufferEnd;
                    _lineStart = _bufferPos;
                    _lineEnded = newline >= 0;
                    _bufferPos = newline >= 0 ? end + 1 : end;
                    if (end > _lineStart && _buffer[end - 1] == '\r') end--;
                    _lineLength = end - _lineStart;
                    _lineNumber++;
                    // A UTF-8 byte-order mark a stream reader would have dropped (text handed over as a string keeps it).
                    if (_lineNumber == 1 && _lineLength > 0 && _buffer[_lineStart] == '\uFEFF')
                    {
                        _lineStart++;
                        _lineLength--;
                    }
                    return true;
                }
                if (_endOfText) return false;
                int remaining = _bufferEnd - _bufferPos;
                if (remaining >= MaxLineLength) throw Error(_lineNumber + 1, $"a line longer than {MaxLineLength} characters (not a session file?)");
                if (_bufferPos > 0)
                {
                    Array.Copy(_buffer, _bufferPos, _buffer, 0, remaining);
                    _bufferPos = 0;
                    _bufferEnd = remaining;
                }
                if (_bufferEnd == _buffer.Length) Array.Resize(ref _buffer, _buffer.Length * 2);
                int read = _reader.Read(_buffer, _bufferEnd, _buffer.Length - _bufferEnd);
                if (read <= 0) _endOfText = true;
                else _bufferEnd += read;
            }
        }

        private void Tokenise()
        {
            _tokenCount = 0;
            int pos = _lineStart;
            int end = _lineStart + _lineLength;
            char[] s = _buffer;
            while (pos < end)
            {
                while (pos < end && char.IsWhiteSpace(s[pos])) pos++;
                if (pos >= end) break;
                int start = pos;
                while (pos < end && !char.IsWhiteSpace(s[pos])) pos++;
                if (_tokenCount == MaxTokens) { _tokenCount++; return; }
                _starts[_tokenCount] = start;
                _lengths[_tokenCount] = pos - start;
                _tokenCount++;
            }
        }

        private void Expect(int count, string form)
        {
            if (_tokenCount != count) throw Error(_lineNumber, $"expected '{form}' ({count} fields), found {Math.Min(_tokenCount, MaxTokens + 1)}{(_tokenCount > MaxTokens ? "+" : "")} fields");
        }

        private ReadOnlySpan<char> Token(int i) => i < Math.Min(_tokenCount, MaxTokens) ? _buffer.AsSpan(_starts[i], _lengths[i]) : ReadOnlySpan<char>.Empty;

        private bool Is(int i, string word) => Token(i).SequenceEqual(word.AsSpan());

        private int Int(int i)
        {
            if (!int.TryParse(Token(i), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int v))
                throw Error(_lineNumber, $"'{Quote(i)}' is not a whole number");
            return v;
        }

        private float Float(int i)
        {
            if (!float.TryParse(Token(i), NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || float.IsNaN(v) || float.IsInfinity(v))
                throw Error(_lineNumber, $"'{Quote(i)}' is not a finite number");
            return v;
        }

        private double Double(int i)
        {
            if (!double.TryParse(Token(i), NumberStyles.Float, CultureInfo.InvariantCulture, out double v) || double.IsNaN(v) || double.IsInfinity(v))
                throw Error(_lineNumber, $"'{Quote(i)}' is not a finite number");
            return v;
        }

        private FormatException Error(int line, string problem)
        {
            // A problem in the text's last line when it lacks its line end: the text may have been cut inside it (a crash
            // mid-write), which is more likely than the damage the problem names ("0.2" cut to "0": not a unit quaternion).
            if (line == _lineNumber && !_lineEnded && !problem.EndsWith("(truncated?)", StringComparison.Ordinal))
                problem += " (the file ends inside this line: truncated?)";
            return new FormatException($"{_source}:{line}: {problem}");
        }

        // Error messages quote file content; a long token is cut so that the message stays short.
        private static string Shorten(string s) => s.Length <= 60 ? s : s.Substring(0, 60) + "...";

        private string Quote(int token) => Shorten(Token(token).ToString());
    }
}
