using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// A parsed JSON value (object, array, string, number, true/false, null) with a small strict parser:
    /// the core runs inside Unity, which has no System.Text.Json, and its data (calibration profiles,
    /// controller profiles) is small. Malformed text raises a <see cref="FormatException"/> naming line and column.
    /// </summary>
    /// <remarks>
    /// Hostile text is safe to parse: nesting deeper than <see cref="MaxDepth"/> is refused (the parser recurses once
    /// per level, so its stack use is bounded), time and memory are linear in the text's length, every number must be
    /// finite as a double, and a <c>\u</c> escape may not leave half of a surrogate pair (such a string could not be
    /// written back as UTF-8).
    /// </remarks>
    public sealed class JsonNode
    {
        // Objects: keys and values in document order, exactly sized; an index only for objects of more than
        // IndexedMembers members (small objects are searched: fewer objects to allocate and collect). Arrays: items.
        private const int IndexedMembers = 8;
        private string[] _keys;
        private JsonNode[] _values;
        private Dictionary<string, int> _index;
        private JsonNode[] _items;
        private readonly string _source;

        /// <summary>The deepest nesting of arrays and objects <see cref="Parse(string)"/> accepts (64).</summary>
        public const int MaxDepth = 64;

        /// <summary>The kind of value.</summary>
        public JsonKind Kind { get; }

        /// <summary>The string value (strings only).</summary>
        public string String { get; }

        /// <summary>The numeric value (numbers only).</summary>
        public double Number { get; }

        /// <summary>The boolean value (true/false only).</summary>
        public bool Bool { get; }

        private JsonNode(JsonKind kind, int line, string source, string s = null, double n = 0, bool b = false)
        {
            Kind = kind;
            Line = line;
            _source = source;
            String = s;
            Number = n;
            Bool = b;
        }

        /// <summary>The 1-based line of the text where this value starts.</summary>
        public int Line { get; }

        /// <summary>
        /// A <see cref="FormatException"/> about this value: <c>SOURCE:LINE: problem</c> when the text was parsed with a
        /// source name (<see cref="Parse(string, string)"/>), otherwise just the problem.
        /// </summary>
        public FormatException Error(string problem) => new FormatException(_source == null ? problem : $"{_source}:{Line}: {problem}");

        /// <summary>
        /// A string from the text made fit for a one-line message: control characters escaped (<c>\n</c>, <c>\u0007</c>)
        /// and cut after 40 characters.
        /// </summary>
        internal static string Printable(string s)
        {
            var sb = new StringBuilder(Math.Min(s.Length, 48));
            for (int i = 0; i < s.Length && i < 40; i++)
            {
                char c = s[i];
                if (c == '\n') sb.Append("\\n");
                else if (c == '\r') sb.Append("\\r");
                else if (c == '\t') sb.Append("\\t");
                else if (c < ' ' || c == 0x7f || c == '\u2028' || c == '\u2029' || char.IsSurrogate(c)) sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                else sb.Append(c);
            }
            if (s.Length > 40) sb.Append("...");
            return sb.ToString();
        }

        /// <summary>The member names of an object, in document order (empty otherwise).</summary>
        public IReadOnlyList<string> Keys => _keys ?? Array.Empty<string>();

        /// <summary>The items of an array (empty otherwise).</summary>
        public IReadOnlyList<JsonNode> Items => _items ?? Array.Empty<JsonNode>();

        /// <summary>The member <paramref name="name"/> of an object, or null.</summary>
        public JsonNode this[string name]
        {
            get
            {
                if (_keys == null || name == null) return null;
                if (_index != null) return _index.TryGetValue(name, out int i) ? _values[i] : null;
                for (int i = 0; i < _keys.Length; i++)
                    if (string.Equals(_keys[i], name, StringComparison.Ordinal)) return _values[i];
                return null;
            }
        }

        /// <summary>The member as a number; throws <see cref="FormatException"/> when missing or not a number.</summary>
        public double GetNumber(string name)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.Number) throw (v ?? this).Error($"'{name}' must be a number.");
            return v.Number;
        }

        /// <summary>The member as a string; throws <see cref="FormatException"/> when missing or not a string.</summary>
        public string GetString(string name)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.String) throw (v ?? this).Error($"'{name}' must be a string.");
            return v.String;
        }

        /// <summary>The member as an array of numbers of the given length.</summary>
        public double[] GetNumbers(string name, int count)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.Array || v._items.Length != count) throw (v ?? this).Error($"'{name}' must be an array of {count} numbers.");
            var result = new double[count];
            for (int i = 0; i < count; i++)
            {
                if (v._items[i].Kind != JsonKind.Number) throw v._items[i].Error($"'{name}' must be an array of {count} numbers.");
                result[i] = v._items[i].Number;
            }
            return result;
        }

        /// <summary>The member as a finite 3-vector written as an array of three numbers.</summary>
        public System.Numerics.Vector3 GetVector3(string name)
        {
            double[] v = GetNumbers(name, 3);
            var result = new System.Numerics.Vector3((float)v[0], (float)v[1], (float)v[2]);
            if (!Vectors.IsFinite(result)) throw this[name].Error($"'{name}' must be finite (each number within ±3.4e38).");
            return result;
        }

        /// <summary>Parses JSON text (one value, nothing but white space after it).</summary>
        /// <exception cref="FormatException">The text is not valid JSON; the message (<c>JSON line L, column C: problem</c>) names line and column.</exception>
        public static JsonNode Parse(string text) => Parse(text, null);

        /// <summary>
        /// Parses JSON text read from <paramref name="sourceName"/> (a file name): errors, and those of
        /// <see cref="Error"/> and the typed getters of the values parsed, read <c>SOURCE:LINE: problem</c>.
        /// </summary>
        /// <exception cref="FormatException">The text is not valid JSON.</exception>
        public static JsonNode Parse(string text, string sourceName)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            var p = new Parser(text, sourceName);
            p.SkipSpace();
            JsonNode value = p.Value(0);
            p.SkipSpace();
            if (!p.AtEnd) throw p.Error("unexpected text after the value");
            return value;
        }

        private sealed class Parser
        {
            private readonly string _s;
            private readonly string _source;
            private readonly StringBuilder _sb = new StringBuilder();
            private int _i;
            // Line breaks occur only in white space (strings may not hold raw control characters), so counting them
            // in SkipSpace keeps the current line exact in O(1) per character.
            private int _line = 1;
            private int _lineStart;

            public Parser(string s, string source)
            {
                _s = s;
                _source = source;
            }

            public bool AtEnd => _i >= _s.Length;

            public void SkipSpace()
            {
                while (_i < _s.Length)
                {
                    char c = _s[_i];
                    if (c == '\n') { _line++; _lineStart = _i + 1; }
                    else if (c != ' ' && c != '\t' && c != '\r') break;
                    _i++;
                }
            }

            public FormatException Error(string problem)
            {
                int column = Math.Min(_i, _s.Length) - _lineStart + 1;
                return new FormatException(_source == null
                    ? $"JSON line {_line}, column {column}: {problem}"
                    : $"{_source}:{_line}: {problem} (column {column})");
            }

            private JsonNode Node(JsonKind kind, string s = null, double n = 0, bool b = false) => new JsonNode(kind, _line, _source, s, n, b);

            public JsonNode Value(int depth)
            {
                if (depth > MaxDepth) throw Error("nested too deeply");
                if (AtEnd) throw Error("unexpected end of text");
                char c = _s[_i];
                if (c == '{') return Object(depth);
                if (c == '[') return Array(depth);
                if (c == '"') return Node(JsonKind.String, StringLiteral());
                if (c == '-' || (c >= '0' && c <= '9')) return NumberLiteral();
                if (Word("true")) return Node(JsonKind.Bool, b: true);
                if (Word("false")) return Node(JsonKind.Bool, b: false);
                if (Word("null")) return Node(JsonKind.Null);
                throw Error($"unexpected character {Describe(c)}");
            }

            private bool Word(string w)
            {
                if (string.CompareOrdinal(_s, _i, w, 0, w.Length) != 0) return false;
                _i += w.Length;
                return true;
            }

            // Members and items are gathered in lists reused per depth, then copied into exactly sized arrays.
            private readonly List<string>[] _scratchKeys = new List<string>[MaxDepth + 2];
            private readonly List<JsonNode>[] _scratchValues = new List<JsonNode>[MaxDepth + 2];

            private List<T> Scratch<T>(List<T>[] lists, int depth)
            {
                List<T> list = lists[depth] ?? (lists[depth] = new List<T>());
                list.Clear();
                return list;
            }

            private JsonNode Object(int depth)
            {
                var node = Node(JsonKind.Object);
                node._keys = System.Array.Empty<string>();
                node._values = System.Array.Empty<JsonNode>();
                _i++;
                SkipSpace();
                if (!AtEnd && _s[_i] == '}') { _i++; return node; }
                List<string> keys = Scratch(_scratchKeys, depth);
                List<JsonNode> values = Scratch(_scratchValues, depth);
                Dictionary<string, int> index = null;
                while (true)
                {
                    SkipSpace();
                    if (AtEnd || _s[_i] != '"') throw Error("expected a member name in quotes");
                    string key = StringLiteral();
                    if (index == null && keys.Count == IndexedMembers)
                    {
                        index = new Dictionary<string, int>(StringComparer.Ordinal);
                        for (int k = 0; k < keys.Count; k++) index.Add(keys[k], k);
                    }
                    if (index != null ? index.ContainsKey(key) : keys.Contains(key)) throw Error($"member '{Shorten(key)}' appears twice");
                    SkipSpace();
                    if (AtEnd || _s[_i] != ':') throw Error("expected ':'");
                    _i++;
                    SkipSpace();
                    index?.Add(key, keys.Count);
                    keys.Add(key);
                    values.Add(Value(depth + 1));
                    SkipSpace();
                    if (AtEnd) throw Error("unexpected end of text in an object");
                    if (_s[_i] == ',') { _i++; continue; }
                    if (_s[_i] == '}')
                    {
                        _i++;
                        node._keys = keys.ToArray();
                        node._values = values.ToArray();
                        node._index = index;
                        keys.Clear();
                        values.Clear();
                        return node;
                    }
                    throw Error("expected ',' or '}'");
                }
            }

            private JsonNode Array(int depth)
            {
                var node = Node(JsonKind.Array);
                node._items = System.Array.Empty<JsonNode>();
                _i++;
                SkipSpace();
                if (!AtEnd && _s[_i] == ']') { _i++; return node; }
                List<JsonNode> items = Scratch(_scratchValues, depth);
                while (true)
                {
                    SkipSpace();
                    items.Add(Value(depth + 1));
                    SkipSpace();
                    if (AtEnd) throw Error("unexpected end of text in an array");
                    if (_s[_i] == ',') { _i++; continue; }
                    if (_s[_i] == ']')
                    {
                        _i++;
                        node._items = items.ToArray();
                        items.Clear();
                        return node;
                    }
                    throw Error("expected ',' or ']'");
                }
            }

            private string StringLiteral()
            {
                StringBuilder sb = _sb.Clear();
                _i++;
                while (true)
                {
                    if (AtEnd) throw Error("unterminated string");
                    char c = _s[_i++];
                    if (c == '"') return sb.ToString();
                    if (c < ' ') { _i--; throw Error($"control character {Describe(c)} in a string (escape it)"); }
                    if (char.IsSurrogate(c))
                    {
                        // Half a surrogate pair is not valid UTF-16 and cannot be written back as UTF-8.
                        if (!char.IsHighSurrogate(c) || AtEnd || !char.IsLowSurrogate(_s[_i])) { _i--; throw Error("half of a surrogate pair in a string"); }
                        sb.Append(c).Append(_s[_i++]);
                        continue;
                    }
                    if (c != '\\') { sb.Append(c); continue; }
                    if (AtEnd) throw Error("unterminated escape");
                    char e = _s[_i++];
                    switch (e)
                    {
                        case '"': sb.Append('"'); break;
                        case '\\': sb.Append('\\'); break;
                        case '/': sb.Append('/'); break;
                        case 'b': sb.Append('\b'); break;
                        case 'f': sb.Append('\f'); break;
                        case 'n': sb.Append('\n'); break;
                        case 'r': sb.Append('\r'); break;
                        case 't': sb.Append('\t'); break;
                        case 'u':
                        {
                            int start = _i - 2;
                            int code = Hex4();
                            if (code >= 0xDC00 && code <= 0xDFFF) { _i = start; throw Error("a \\u escape of the low half of a surrogate pair without its high half"); }
                            if (code >= 0xD800 && code <= 0xDBFF)
                            {
                                // The high half must be followed at once by the escape of the low half.
                                if (_i + 1 >= _s.Length || _s[_i] != '\\' || _s[_i + 1] != 'u') { _i = start; throw Error("a \\u escape of the high half of a surrogate pair without its low half"); }
                                _i += 2;
                                int low = Hex4();
                                if (low < 0xDC00 || low > 0xDFFF) { _i = start; throw Error("a \\u escape of the high half of a surrogate pair without its low half"); }
                                sb.Append((char)code).Append((char)low);
                            }
                            else sb.Append((char)code);
                            break;
                        }
                        default: _i -= 2; throw Error($"bad escape '\\' followed by {Describe(e)}");
                    }
                }
            }

            // RFC 8259 grammar, strictly: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? ("01", "1.", ".5", "+1" are errors).
            private JsonNode NumberLiteral()
            {
                int start = _i;
                if (_s[_i] == '-') _i++;
                if (AtEnd || !IsDigit(_s[_i])) throw NumberError(start);
                if (_s[_i] == '0')
                {
                    _i++;
                    if (!AtEnd && IsDigit(_s[_i])) throw NumberError(start);
                }
                else Digits();
                if (!AtEnd && _s[_i] == '.')
                {
                    _i++;
                    if (AtEnd || !IsDigit(_s[_i])) throw NumberError(start);
                    Digits();
                }
                if (!AtEnd && (_s[_i] == 'e' || _s[_i] == 'E'))
                {
                    _i++;
                    if (!AtEnd && (_s[_i] == '+' || _s[_i] == '-')) _i++;
                    if (AtEnd || !IsDigit(_s[_i])) throw NumberError(start);
                    Digits();
                }
                if (!double.TryParse(_s.AsSpan(start, _i - start), NumberStyles.Float, CultureInfo.InvariantCulture, out double v) || double.IsInfinity(v) || double.IsNaN(v))
                {
                    string text = Shorten(_s.Substring(start, _i - start));
                    _i = start;
                    throw Error($"'{text}' is out of range");
                }
                return Node(JsonKind.Number, n: v);
            }

            private void Digits()
            {
                while (!AtEnd && IsDigit(_s[_i])) _i++;
            }

            private static bool IsDigit(char c) => c >= '0' && c <= '9';

            private FormatException NumberError(int start)
            {
                int end = _i;
                while (end < _s.Length && "0123456789.eE+-".IndexOf(_s[end]) >= 0) end++;
                string text = Shorten(_s.Substring(start, end - start));
                _i = start;
                return Error($"'{text}' is not a JSON number");
            }

            // A character for a one-line message: printable ones quoted, others by their code (a newline must not split the line).
            private static string Describe(char c) =>
                c < ' ' || c == 0x7f || char.IsSurrogate(c) || char.IsWhiteSpace(c) ? $"U+{(int)c:X4}" : $"'{c}'";

            private static string Shorten(string s) => Printable(s);

            private int Hex4()
            {
                if (_i + 4 > _s.Length) throw Error("bad \\u escape");
                int code = 0;
                for (int k = 0; k < 4; k++)
                {
                    char h = _s[_i + k];
                    int d = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : -1;
                    if (d < 0) throw Error("bad \\u escape");
                    code = code * 16 + d;
                }
                _i += 4;
                return code;
            }
        }
    }
}
