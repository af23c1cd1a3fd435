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
    public static class BvhReader
    {
        /// <summary>Reads a BVH file from disk.</summary>
        /// <exception cref="FormatException">The file is not valid BVH.</exception>
        /// <exception cref="IOException">The file cannot be read.</exception>
        public static BvhClip ReadFile(string path, BvhReadOptions options = null)
        {
            using (var reader = new StreamReader(path))
                return Read(reader, Path.GetFileName(path), options);
        }

        /// <summary>Reads BVH text; <paramref name="sourceName"/> names the source in error messages.</summary>
        /// <exception cref="FormatException">The text is not valid BVH.</exception>
        public static BvhClip Read(TextReader reader, string sourceName, BvhReadOptions options = null)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            var parser = new Parser(reader, sourceName ?? "BVH");
            BvhClip clip = parser.Parse(options?.ToMetres == true ? 1f : options?.Scale ?? 1f);
            if (options?.ToMetres == true)
            {
                float metresPerUnit = clip.GuessMetresPerUnit();
                if (metresPerUnit != 1f) clip = clip.WithScale(metresPerUnit);
            }
            return clip;
        }

        private sealed class Parser
        {
            private readonly TextReader _reader;
            private readonly string _source;
            private int _lineNumber;
            private string[] _tokens = Array.Empty<string>();
            private int _tokenIndex;
            private int _tokenLine;

            private readonly List<string> _names = new List<string>();
            private readonly HashSet<string> _nameSet = new HashSet<string>(StringComparer.Ordinal);
            private readonly List<int> _parents = new List<int>();
            private readonly List<bool> _endSites = new List<bool>();
            private readonly List<Vector3> _offsets = new List<Vector3>();
            private readonly List<BvhChannel[]> _channels = new List<BvhChannel[]>();
            private int _channelTotal;

            public Parser(TextReader reader, string source)
            {
                _reader = reader;
                _source = source;
            }

            public BvhClip Parse(float scale)
            {
                if (!Try(out string first)) throw Error(Math.Max(1, _lineNumber), "the file is empty; expected HIERARCHY");
                if (!Is(first, "HIERARCHY")) throw Error(_tokenLine, $"expected HIERARCHY, found '{first}'");
                string root = Next("ROOT");
                if (!Is(root, "ROOT")) throw Error(_tokenLine, $"expected ROOT, found '{root}'");
                ParseJoint(-1, false);
                string motion = Next("MOTION");
                if (!Is(motion, "MOTION"))
                    throw Error(_tokenLine, Is(motion, "ROOT") ? "a second ROOT is not supported" : $"expected MOTION, found '{motion}'");
                if (_tokenIndex < _tokens.Length) throw Error(_tokenLine, $"unexpected '{_tokens[_tokenIndex]}' after MOTION");
                return ParseMotion(scale);
            }

            private void ParseJoint(int parent, bool endSite)
            {
                int line = _tokenLine;
                string name;
                if (endSite)
                {
                    string site = Next("Site");
                    if (!Is(site, "Site")) throw Error(_tokenLine, $"expected 'Site' after 'End', found '{site}'");
                    name = UniqueName(_names[parent] + "_End");
                }
                else
                {
                    name = RestOfLine();
                    if (name.Length == 0) throw Error(line, "a joint needs a name");
                    if (!_nameSet.Add(name)) throw Error(line, $"joint name '{name}' is used twice");
                }
                string open = Next("{");
                if (open != "{") throw Error(_tokenLine, $"expected '{{' to open joint '{name}', found '{open}'");

                int index = _names.Count;
                _names.Add(name);
                _nameSet.Add(name);
                _parents.Add(parent);
                _endSites.Add(endSite);
                _offsets.Add(Vector3.Zero);
                _channels.Add(Array.Empty<BvhChannel>());
                bool hasOffset = false, hasChannels = false;

                while (true)
                {
                    string token = Next("}");
                    if (token == "}") break;
                    if (Is(token, "OFFSET"))
                    {
                        if (hasOffset) throw Error(_tokenLine, $"joint '{name}' has two OFFSETs");
                        int l = _tokenLine;
                        _offsets[index] = new Vector3(Number(l), Number(l), Number(l));
                        if (_tokenIndex < _tokens.Length) throw Error(l, $"OFFSET takes 3 numbers; found more");
                        hasOffset = true;
                    }
                    else if (Is(token, "CHANNELS"))
                    {
                        if (endSite) throw Error(_tokenLine, "an End Site has no channels");
                        if (hasChannels) throw Error(_tokenLine, $"joint '{name}' has two CHANNELS lines");
                        _channels[index] = ParseChannels(name);
                        hasChannels = true;
                    }
                    else if (Is(token, "JOINT"))
                    {
                        if (endSite) throw Error(_tokenLine, "an End Site cannot have child joints");
                        ParseJoint(index, false);
                    }
                    else if (Is(token, "End"))
                    {
                        if (endSite) throw Error(_tokenLine, "an End Site cannot have an End Site");
                        ParseJoint(index, true);
                    }
                    else throw Error(_tokenLine, $"unexpected '{token}' in joint '{name}'");
                }
                if (!hasOffset) throw Error(line, $"joint '{name}' has no OFFSET");
                if (!endSite && !hasChannels) throw Error(line, $"joint '{name}' has no CHANNELS");
            }

            private BvhChannel[] ParseChannels(string joint)
            {
                int line = _tokenLine;
                string countText = Next("a channel count");
                if (!int.TryParse(countText, NumberStyles.Integer, CultureInfo.InvariantCulture, out int count) || count < 0 || count > 6)
                    throw Error(line, $"channel count must be 0 to 6, found '{countText}'");
                int available = _tokens.Length - _tokenIndex;
                if (available != count)
                    throw Error(line, $"CHANNELS {count} of joint '{joint}' lists {available} channel name(s)");
                var channels = new BvhChannel[count];
                int seen = 0;
                for (int i = 0; i < count; i++)
                {
                    string c = _tokens[_tokenIndex++];
                    if (!TryChannel(c, out channels[i])) throw Error(line, $"unknown channel '{c}'");
                    int bit = 1 << (int)channels[i];
                    if ((seen & bit) != 0) throw Error(line, $"channel '{c}' is listed twice");
                    seen |= bit;
                }
                _channelTotal += count;
                return channels;
            }

            private BvhClip ParseMotion(float scale)
            {
                int frames = (int)ParseHeaderNumber("Frames:", out int framesLine, integer: true);
                if (frames < 0) throw Error(framesLine, $"frame count must not be negative, found {frames}");
                float frameTime = ParseHeaderNumber("Frame Time:", out int timeLine, integer: false);
                if (!(frameTime > 0f) || float.IsInfinity(frameTime)) throw Error(timeLine, $"frame time must be a positive number of seconds, found {frameTime.ToString(CultureInfo.InvariantCulture)}");

                // Grow as frame lines arrive: the header's frame count is not trusted to size memory (a file that
                // claims ten million frames must fail at its end, not allocate gigabytes first).
                var values = new float[(long)Math.Min(frames, 4096) * _channelTotal];
                int k = 0;
                for (int f = 0; f < frames; f++)
                {
                    string line = NextNonEmptyLine();
                    if (line == null) throw Error(_lineNumber + 1, $"the file ends after {f} of {frames} frames (truncated?)");
                    if ((long)k + _channelTotal > values.Length) Array.Resize(ref values, (int)Math.Min((long)values.Length * 2 + _channelTotal, (long)frames * _channelTotal));
                    int count = 0;
                    int pos = 0;
                    while (NextField(line, ref pos, out int start, out int length))
                    {
                        if (count == _channelTotal) throw Error(_lineNumber, $"frame {f} has more than {_channelTotal} values");
                        if (!float.TryParse(line.Substring(start, length), NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || float.IsNaN(v) || float.IsInfinity(v))
                            throw Error(_lineNumber, $"frame {f}, value {count + 1}: '{line.Substring(start, length)}' is not a finite number");
                        values[k++] = v;
                        count++;
                    }
                    if (count != _channelTotal) throw Error(_lineNumber, $"frame {f} has {count} values; the hierarchy has {_channelTotal} channels");
                }
                string extra = NextNonEmptyLine();
                if (extra != null) throw Error(_lineNumber, $"more frame lines than 'Frames: {frames}' announces");

                try
                {
                    if (values.Length != k) Array.Resize(ref values, k);
                    return new BvhClip(_names, _parents, _endSites, _offsets, _channels, frames, frameTime, values, scale);
                }
                catch (ArgumentException e)
                {
                    throw Error(1, e.Message);
                }
            }

            private float ParseHeaderNumber(string label, out int line, bool integer)
            {
                string text = NextNonEmptyLine();
                line = _lineNumber;
                if (text == null) throw Error(_lineNumber + 1, $"the file ends before '{label}'");
                string trimmed = text.Trim();
                if (!trimmed.StartsWith(label, StringComparison.OrdinalIgnoreCase)) throw Error(line, $"expected '{label}', found '{trimmed}'");
                string number = trimmed.Substring(label.Length).Trim();
                if (integer)
                {
                    if (!int.TryParse(number, NumberStyles.Integer, CultureInfo.InvariantCulture, out int n)) throw Error(line, $"'{number}' is not a whole number of frames");
                    return n;
                }
                if (!float.TryParse(number, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || float.IsNaN(v)) throw Error(line, $"'{number}' is not a number of seconds");
                return v;
            }

            private static bool NextField(string line, ref int pos, out int start, out int length)
            {
                while (pos < line.Length && char.IsWhiteSpace(line[pos])) pos++;
                start = pos;
                while (pos < line.Length && !char.IsWhiteSpace(line[pos])) pos++;
                length = pos - start;
                return length > 0;
            }

            private string NextNonEmptyLine()
            {
                string line;
                while ((line = _reader.ReadLine()) != null)
                {
                    _lineNumber++;
                    if (line.Trim().Length > 0) return line;
                }
                return null;
            }

            private bool Try(out string token)
            {
                while (_tokenIndex >= _tokens.Length)
                {
                    string line = _reader.ReadLine();
                    if (line == null)
                    {
                        token = null;
                        return false;
                    }
                    _lineNumber++;
                    _tokens = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                    _tokenIndex = 0;
                    _tokenLine = _lineNumber;
                }
                token = _tokens[_tokenIndex++];
                return true;
            }

            private string Next(string expected)
            {
                if (!Try(out string token)) throw Error(_lineNumber + 1, $"the file ends where '{expected}' was expected (truncated?)");
                return token;
            }

            private string RestOfLine()
            {
                string rest = string.Join(" ", _tokens, _tokenIndex, _tokens.Length - _tokenIndex);
                _tokenIndex = _tokens.Length;
                return rest;
            }

            private float Number(int line)
            {
                if (_tokenIndex >= _tokens.Length) throw Error(line, "OFFSET takes 3 numbers; found fewer");
                string t = _tokens[_tokenIndex++];
                if (!float.TryParse(t, NumberStyles.Float, CultureInfo.InvariantCulture, out float v) || float.IsNaN(v) || float.IsInfinity(v))
                    throw Error(line, $"'{t}' is not a finite number");
                return v;
            }

            private string UniqueName(string name)
            {
                string candidate = name;
                for (int i = 2; _nameSet.Contains(candidate); i++) candidate = name + i.ToString(CultureInfo.InvariantCulture);
                return candidate;
            }

            private static bool Is(string token, string keyword) => string.Equals(token, keyword, StringComparison.OrdinalIgnoreCase);

            private static bool TryChannel(string name, out BvhChannel channel)
            {
                switch (name.ToLowerInvariant())
                {
                    case "xposition": channel = BvhChannel.Xposition; return true;
                    case "yposition": channel = BvhChannel.Yposition; return true;
                    case "zposition": channel = BvhChannel.Zposition; return true;
                    case "xrotation": channel = BvhChannel.Xrotation; return true;
                    case "yrotation": channel = BvhChannel.Yrotation; return true;
                    case "zrotation": channel = BvhChannel.Zrotation; return true;
                    default: channel = default; return false;
                }
            }

            private FormatException Error(int line, string problem) => new FormatException($"{_source}:{line}: {problem}");
        }
    }
}
