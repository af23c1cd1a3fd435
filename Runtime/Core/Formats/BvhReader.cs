using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Reads BVH motion files: any rotation channel order, position channels on any joint, tabs and CRLF,
    /// End Sites. Every malformed input throws a <see cref="FormatException"/> that names the source, the
    /// 1-based line and the problem. See <see cref="BvhClip"/> for the channel semantics and the conversion
    /// to Unity's frame.
    /// </summary>
    /// <remarks>
    /// Hostile files are safe to read: the hierarchy is parsed without recursion, time is linear in the file's size,
    /// and memory grows only with what has been read (a header announcing billions of frames allocates nothing for
    /// them). Files beyond these limits are refused with the usual <c>SOURCE:LINE: problem</c> error:
    /// <see cref="MaxJoints"/> joints (End Sites included), <see cref="MaxChannels"/> channels, <see cref="MaxValues"/>
    /// channel values in all, lines of <see cref="MaxLineLength"/> characters, every number within
    /// ±<see cref="MaxMagnitude"/>, and a frame time from <see cref="MinFrameTime"/> to <see cref="MaxFrameTime"/> s.
    /// See Documentation~/robustness.md.
    /// </remarks>
    public static class BvhReader
    {
        /// <summary>The most joints a file may have, End Sites included (65,536; a full body with fingers and face has a few hundred).</summary>
        public const int MaxJoints = 1 << 16;

        /// <summary>The most channels a frame may have (65,536: about 20,000 joints with three rotations each).</summary>
        public const int MaxChannels = 1 << 16;

        /// <summary>The most channel values a file may hold in all (2^27, 512 MiB as floats: an hour at 120 Hz of 300 channels).</summary>
        public const int MaxValues = 1 << 27;

        /// <summary>The longest line, in characters (4 Mi: a frame line of the most channels, 64 characters per value).</summary>
        public const int MaxLineLength = 1 << 22;

        /// <summary>
        /// The largest magnitude of any number (offsets, positions, angles): 10,000,000 (10 km in millimetres), so that
        /// every pose of every joint stays finite.
        /// </summary>
        public const float MaxMagnitude = 1e7f;

        /// <summary>The shortest frame time, in seconds (10 kHz).</summary>
        public const float MinFrameTime = 1e-4f;

        /// <summary>The longest frame time, in seconds.</summary>
        public const float MaxFrameTime = 60f;

        /// <summary>Reads a BVH file from disk.</summary>
        /// <exception cref="FormatException">The file is not valid BVH.</exception>
        /// <exception cref="IOException">The file cannot be read, or the path is a folder.</exception>
        public static BvhClip ReadFile(string path, BvhReadOptions options = null)
        {
            InputFiles.ThrowIfFolder(path);
            using (var reader = new StreamReader(path))
                return Read(reader, Path.GetFileName(path), options);
        }

        /// <summary>Reads BVH text; <paramref name="sourceName"/> names the source in error messages.</summary>
        /// <exception cref="FormatException">The text is not valid BVH.</exception>
        /// <exception cref="ArgumentOutOfRangeException"><see cref="BvhReadOptions.Scale"/> is not positive and finite.</exception>
        public static BvhClip Read(TextReader reader, string sourceName, BvhReadOptions options = null)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            float scale = options?.ToMetres == true ? 1f : options?.Scale ?? 1f;
            if (!(scale > 0f) || float.IsInfinity(scale)) throw new ArgumentOutOfRangeException(nameof(options), scale, "BvhReadOptions.Scale must be positive and finite.");
            var parser = new Parser(reader, sourceName ?? "BVH");
            BvhClip clip = parser.Parse(scale);
            if (options?.ToMetres == true)
            {
                float metresPerUnit = clip.GuessMetresPerUnit();
                if (metresPerUnit != 1f) clip = clip.WithScale(metresPerUnit);
            }
            return clip;
        }

        private sealed class Parser
        {
            private readonly TextLineReader _lines;
            private readonly string _source;
            // The current hierarchy line's tokens, as ranges of _lines.Line (no string per token: only names are kept).
            private int[] _tokenStarts = new int[16];
            private int[] _tokenLengths = new int[16];
            private int _tokenCount;
            private int _tokenIndex;
            private int _tokenLine;

            private readonly List<string> _names = new List<string>();
            private readonly HashSet<string> _nameSet = new HashSet<string>(StringComparer.Ordinal);
            // For End Site names: the next suffix to try after "<parent>_End" (so many End Sites under one joint stay linear).
            private readonly Dictionary<string, int> _nextSuffix = new Dictionary<string, int>(StringComparer.Ordinal);
            private readonly List<int> _parents = new List<int>();
            private readonly List<bool> _endSites = new List<bool>();
            private readonly List<Vector3> _offsets = new List<Vector3>();
            private readonly List<BvhChannel[]> _channels = new List<BvhChannel[]>();
            private int _channelTotal;

            /// <summary>A joint whose '{' has been read and whose '}' has not.</summary>
            private struct OpenJoint
            {
                public int Index;
                public int Line;
                public bool EndSite;
                public bool HasOffset;
                public bool HasChannels;
            }

            public Parser(TextReader reader, string source)
            {
                _source = source;
                _lines = new TextLineReader(reader, source, MaxLineLength);
            }

            private int LineNumber => _lines.LineNumber;

            public BvhClip Parse(float scale)
            {
                if (!Try(out ReadOnlySpan<char> first)) throw Error(Math.Max(1, LineNumber), "the file is empty; expected HIERARCHY");
                if (!Is(first, "HIERARCHY")) throw Error(_tokenLine, $"expected HIERARCHY, found '{Shorten(first)}'");
                ReadOnlySpan<char> root = Next("ROOT");
                if (!Is(root, "ROOT")) throw Error(_tokenLine, $"expected ROOT, found '{Shorten(root)}'");
                ParseHierarchy();
                ReadOnlySpan<char> motion = Next("MOTION");
                if (!Is(motion, "MOTION"))
                    throw Error(_tokenLine, Is(motion, "ROOT") ? "a second ROOT is not supported" : $"expected MOTION, found '{Shorten(motion)}'");
                if (_tokenIndex < _tokenCount) throw Error(_tokenLine, $"unexpected '{Shorten(Token(_tokenIndex))}' after MOTION");
                return ParseMotion(scale);
            }

            // The joint tree, with an explicit stack of the joints still open (no recursion: nesting is bounded only by
            // MaxJoints, which would overflow any thread's stack).
            private void ParseHierarchy()
            {
                var open = new List<OpenJoint>();
                open.Add(BeginJoint(-1, false));
                while (open.Count > 0)
                {
                    OpenJoint joint = open[open.Count - 1];
                    string name = _names[joint.Index];
                    ReadOnlySpan<char> token = Next("}");
                    if (token.Length == 1 && token[0] == '}')
                    {
                        if (!joint.HasOffset) throw Error(joint.Line, $"joint '{Shorten(name)}' has no OFFSET");
                        if (!joint.EndSite && !joint.HasChannels) throw Error(joint.Line, $"joint '{Shorten(name)}' has no CHANNELS");
                        open.RemoveAt(open.Count - 1);
                    }
                    else if (Is(token, "OFFSET"))
                    {
                        if (joint.HasOffset) throw Error(_tokenLine, $"joint '{Shorten(name)}' has two OFFSETs");
                        int l = _tokenLine;
                        _offsets[joint.Index] = new Vector3(Number(l), Number(l), Number(l));
                        if (_tokenIndex < _tokenCount) throw Error(l, "OFFSET takes 3 numbers; found more");
                        joint.HasOffset = true;
                        open[open.Count - 1] = joint;
                    }
                    else if (Is(token, "CHANNELS"))
                    {
                        if (joint.EndSite) throw Error(_tokenLine, "an End Site has no channels");
                        if (joint.HasChannels) throw Error(_tokenLine, $"joint '{Shorten(name)}' has two CHANNELS lines");
                        _channels[joint.Index] = ParseChannels(name);
                        joint.HasChannels = true;
                        open[open.Count - 1] = joint;
                    }
                    else if (Is(token, "JOINT"))
                    {
                        if (joint.EndSite) throw Error(_tokenLine, "an End Site cannot have child joints");
                        open.Add(BeginJoint(joint.Index, false));
                    }
                    else if (Is(token, "End"))
                    {
                        if (joint.EndSite) throw Error(_tokenLine, "an End Site cannot have an End Site");
                        open.Add(BeginJoint(joint.Index, true));
                    }
                    else throw Error(_tokenLine, $"unexpected '{Shorten(token)}' in joint '{Shorten(name)}'");
                }
            }

            // Reads a joint's name (or an End Site's "Site") and its '{', and adds the joint.
            private OpenJoint BeginJoint(int parent, bool endSite)
            {
                int line = _tokenLine;
                if (_names.Count == MaxJoints) throw Error(line, $"more than {MaxJoints} joints (the reader's limit)");
                string name;
                if (endSite)
                {
                    ReadOnlySpan<char> site = Next("Site");
                    if (!Is(site, "Site")) throw Error(_tokenLine, $"expected 'Site' after 'End', found '{Shorten(site)}'");
                    name = UniqueName(_names[parent] + "_End");
                }
                else
                {
                    name = RestOfLine();
                    if (name.Length == 0) throw Error(line, "a joint needs a name");
                    if (_nameSet.Contains(name)) throw Error(line, $"joint name '{Shorten(name)}' is used twice");
                }
                ReadOnlySpan<char> open = Next("{");
                if (!(open.Length == 1 && open[0] == '{')) throw Error(_tokenLine, $"expected '{{' to open joint '{Shorten(name)}', found '{Shorten(open)}'");

                int index = _names.Count;
                _names.Add(name);
                _nameSet.Add(name);
                _parents.Add(parent);
                _endSites.Add(endSite);
                _offsets.Add(Vector3.Zero);
                _channels.Add(Array.Empty<BvhChannel>());
                return new OpenJoint { Index = index, Line = line, EndSite = endSite };
            }

            private BvhChannel[] ParseChannels(string joint)
            {
                int line = _tokenLine;
                ReadOnlySpan<char> countText = Next("a channel count");
                if (!int.TryParse(countText, NumberStyles.Integer, CultureInfo.InvariantCulture, out int count) || count < 0 || count > 6)
                    throw Error(line, $"channel count must be 0 to 6, found '{Shorten(countText)}'");
                int available = _tokenCount - _tokenIndex;
                if (available != count)
                    throw Error(line, $"CHANNELS {count} of joint '{Shorten(joint)}' lists {available} channel name(s)");
                if (_channelTotal + count > MaxChannels) throw Error(line, $"more than {MaxChannels} channels (the reader's limit)");
                var channels = new BvhChannel[count];
                int seen = 0;
                for (int i = 0; i < count; i++)
                {
                    ReadOnlySpan<char> c = Token(_tokenIndex++);
                    if (!TryChannel(c, out channels[i])) throw Error(line, $"unknown channel '{Shorten(c)}'");
                    int bit = 1 << (int)channels[i];
                    if ((seen & bit) != 0) throw Error(line, $"channel '{c.ToString()}' is listed twice");
                    seen |= bit;
                }
                _channelTotal += count;
                return channels;
            }

            private BvhClip ParseMotion(float scale)
            {
                int frames = (int)ParseHeaderNumber("Frames:", out int framesLine, integer: true);
                if (frames < 0) throw Error(framesLine, $"frame count must not be negative, found {frames}");
                if ((long)frames * _channelTotal > MaxValues)
                    throw Error(framesLine, $"{frames} frames of {_channelTotal} channels are more than {MaxValues} values (the reader's limit)");
                float frameTime = (float)ParseHeaderNumber("Frame Time:", out int timeLine, integer: false);
                if (!(frameTime >= MinFrameTime && frameTime <= MaxFrameTime))
                    throw Error(timeLine, $"frame time must be from {MinFrameTime.ToString(CultureInfo.InvariantCulture)} to {MaxFrameTime.ToString(CultureInfo.InvariantCulture)} seconds, found {frameTime.ToString(CultureInfo.InvariantCulture)}");

                // Grow as frame lines arrive: the header's frame count is not trusted to size memory (a file that
                // claims ten million frames must fail at its end, not allocate gigabytes first). Start at about 64 KiB.
                long total = (long)frames * _channelTotal;
                var values = new float[Math.Min(total, Math.Max(_channelTotal, 1 << 14))];
                int k = 0;
                for (int f = 0; f < frames; f++)
                {
                    if (!NextNonEmptyLine()) throw Error(LineNumber + 1, $"the file ends after {f} of {frames} frames (truncated?)");
                    if ((long)k + _channelTotal > values.Length) Array.Resize(ref values, (int)Math.Min((long)values.Length * 2 + _channelTotal, total));
                    ReadOnlySpan<char> line = _lines.Line;
                    int count = 0;
                    int pos = 0;
                    while (NextField(line, ref pos, out int start, out int length))
                    {
                        if (count == _channelTotal) throw Error(LineNumber, $"frame {f} has more than {_channelTotal} values");
                        ReadOnlySpan<char> field = line.Slice(start, length);
                        if (!float.TryParse(field, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || !(Math.Abs(v) <= MaxMagnitude))
                            throw Error(LineNumber, $"frame {f}, value {count + 1}: '{Shorten(field.ToString())}' is not a number within ±{MaxMagnitude.ToString(CultureInfo.InvariantCulture)}");
                        values[k++] = v;
                        count++;
                    }
                    if (count != _channelTotal) throw Error(LineNumber, $"frame {f} has {count} values; the hierarchy has {_channelTotal} channels");
                }
                if (NextNonEmptyLine()) throw Error(LineNumber, $"more frame lines than 'Frames: {frames}' announces");

                try
                {
                    if (values.Length != k) Array.Resize(ref values, k);
                    return new BvhClip(_names, _parents, _endSites, _offsets, _channels, frames, frameTime, values, scale);
                }
                catch (ArgumentException e)
                {
                    throw Error(1, e.Message.Split('\n')[0].TrimEnd('\r'));
                }
            }

            // A double, which holds every frame count exactly (a float made 2147483647 frames -2147483648).
            private double ParseHeaderNumber(string label, out int line, bool integer)
            {
                bool found = NextNonEmptyLine();
                line = LineNumber;
                if (!found) throw Error(LineNumber + 1, $"the file ends before '{label}'");
                string trimmed = _lines.Line.Trim().ToString();
                if (!trimmed.StartsWith(label, StringComparison.OrdinalIgnoreCase)) throw Error(line, $"expected '{label}', found '{Shorten(trimmed)}'");
                string number = trimmed.Substring(label.Length).Trim();
                if (integer)
                {
                    if (!int.TryParse(number, NumberStyles.Integer, CultureInfo.InvariantCulture, out int n)) throw Error(line, $"'{Shorten(number)}' is not a whole number of frames");
                    return n;
                }
                if (!float.TryParse(number, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || float.IsNaN(v)) throw Error(line, $"'{Shorten(number)}' is not a number of seconds");
                return v;
            }

            private static bool NextField(ReadOnlySpan<char> line, ref int pos, out int start, out int length)
            {
                while (pos < line.Length && char.IsWhiteSpace(line[pos])) pos++;
                start = pos;
                while (pos < line.Length && !char.IsWhiteSpace(line[pos])) pos++;
                length = pos - start;
                return length > 0;
            }

            private bool NextNonEmptyLine()
            {
                while (_lines.Next())
                    if (!_lines.Line.IsWhiteSpace()) return true;
                return false;
            }

            private ReadOnlySpan<char> Token(int i) => _lines.Line.Slice(_tokenStarts[i], _tokenLengths[i]);

            // The next token, reading lines as needed. The span is valid until the next call.
            private bool Try(out ReadOnlySpan<char> token)
            {
                while (_tokenIndex >= _tokenCount)
                {
                    if (!_lines.Next())
                    {
                        token = default;
                        return false;
                    }
                    Tokenise(_lines.Line);
                    _tokenLine = LineNumber;
                }
                token = Token(_tokenIndex++);
                return true;
            }

            // Splits on white space as string.Split(null) does.
            private void Tokenise(ReadOnlySpan<char> line)
            {
                _tokenCount = 0;
                _tokenIndex = 0;
                int pos = 0;
                while (NextField(line, ref pos, out int start, out int length))
                {
                    if (_tokenCount == _tokenStarts.Length)
                    {
                        Array.Resize(ref _tokenStarts, _tokenCount * 2);
                        Array.Resize(ref _tokenLengths, _tokenCount * 2);
                    }
                    _tokenStarts[_tokenCount] = start;
                    _tokenLengths[_tokenCount] = length;
                    _tokenCount++;
                }
            }

            private ReadOnlySpan<char> Next(string expected)
            {
                if (!Try(out ReadOnlySpan<char> token)) throw Error(LineNumber + 1, $"the file ends where '{expected}' was expected (truncated?)");
                return token;
            }

            // The rest of the line's tokens joined by single spaces (a joint's name).
            private string RestOfLine()
            {
                if (_tokenIndex >= _tokenCount) return string.Empty;
                int length = _tokenCount - _tokenIndex - 1;
                for (int i = _tokenIndex; i < _tokenCount; i++) length += _tokenLengths[i];
                var chars = new char[length];
                int at = 0;
                for (int i = _tokenIndex; i < _tokenCount; i++)
                {
                    if (at > 0) chars[at++] = ' ';
                    Token(i).CopyTo(new Span<char>(chars, at, _tokenLengths[i]));
                    at += _tokenLengths[i];
                }
                _tokenIndex = _tokenCount;
                return new string(chars);
            }

            private float Number(int line)
            {
                if (_tokenIndex >= _tokenCount) throw Error(line, "OFFSET takes 3 numbers; found fewer");
                ReadOnlySpan<char> t = Token(_tokenIndex++);
                if (!float.TryParse(t, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || !(Math.Abs(v) <= MaxMagnitude))
                    throw Error(line, $"'{Shorten(t)}' is not a number within ±{MaxMagnitude.ToString(CultureInfo.InvariantCulture)}");
                return v;
            }

            // "<parent>_End", or with the first free suffix 2, 3, …; the suffix search resumes where the last one for this
            // name stopped (names are never removed, so every suffix below it is still taken).
            private string UniqueName(string name)
            {
                if (!_nameSet.Contains(name)) return name;
                _nextSuffix.TryGetValue(name, out int i);
                if (i < 2) i = 2;
                string candidate;
                while (_nameSet.Contains(candidate = name + i.ToString(CultureInfo.InvariantCulture))) i++;
                _nextSuffix[name] = i + 1;
                return candidate;
            }

            private static bool Is(ReadOnlySpan<char> token, string keyword) => token.Equals(keyword.AsSpan(), StringComparison.OrdinalIgnoreCase);

            // Error messages quote file content; a long token (a 20 MB joint name) is cut so that the message stays short.
            private static string Shorten(string s) => s.Length <= 60 ? s : s.Substring(0, 60) + "...";

            private static string Shorten(ReadOnlySpan<char> s) => s.Length <= 60 ? s.ToString() : s.Slice(0, 60).ToString() + "...";

            private static readonly string[] ChannelNames = { "Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation" };

            private static bool TryChannel(ReadOnlySpan<char> name, out BvhChannel channel)
            {
                for (int i = 0; i < ChannelNames.Length; i++)
                    if (Is(name, ChannelNames[i])) { channel = (BvhChannel)i; return true; }
                channel = default;
                return false;
            }

            private FormatException Error(int line, string problem) => new FormatException($"{_source}:{line}: {problem}");
        }
    }
}
