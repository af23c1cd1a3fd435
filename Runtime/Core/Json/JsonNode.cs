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
    public sealed class JsonNode
    {
        private readonly Dictionary<string, JsonNode> _members;
        private readonly List<string> _order;
        private readonly List<JsonNode> _items;

        /// <summary>The kind of value.</summary>
        public JsonKind Kind { get; }

        /// <summary>The string value (strings only).</summary>
        public string String { get; }

        /// <summary>The numeric value (numbers only).</summary>
        public double Number { get; }

        /// <summary>The boolean value (true/false only).</summary>
        public bool Bool { get; }

        private JsonNode(JsonKind kind, string s = null, double n = 0, bool b = false)
        {
            Kind = kind;
            String = s;
            Number = n;
            Bool = b;
            if (kind == JsonKind.Object) { _members = new Dictionary<string, JsonNode>(StringComparer.Ordinal); _order = new List<string>(); }
            if (kind == JsonKind.Array) _items = new List<JsonNode>();
        }

        /// <summary>The member names of an object, in document order (empty otherwise).</summary>
        public IReadOnlyList<string> Keys => (IReadOnlyList<string>)_order ?? Array.Empty<string>();

        /// <summary>The items of an array (empty otherwise).</summary>
        public IReadOnlyList<JsonNode> Items => (IReadOnlyList<JsonNode>)_items ?? Array.Empty<JsonNode>();

        /// <summary>The member <paramref name="name"/> of an object, or null.</summary>
        public JsonNode this[string name] => _members != null && _members.TryGetValue(name, out JsonNode v) ? v : null;

        /// <summary>The member as a number; throws <see cref="FormatException"/> when missing or not a number.</summary>
        public double GetNumber(string name)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.Number) throw new FormatException($"'{name}' must be a number.");
            return v.Number;
        }

        /// <summary>The member as a string; throws <see cref="FormatException"/> when missing or not a string.</summary>
        public string GetString(string name)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.String) throw new FormatException($"'{name}' must be a string.");
            return v.String;
        }

        /// <summary>The member as an array of numbers of the given length.</summary>
        public double[] GetNumbers(string name, int count)
        {
            JsonNode v = this[name];
            if (v == null || v.Kind != JsonKind.Array || v._items.Count != count) throw new FormatException($"'{name}' must be an array of {count} numbers.");
            var result = new double[count];
            for (int i = 0; i < count; i++)
            {
                if (v._items[i].Kind != JsonKind.Number) throw new FormatException($"'{name}' must be an array of {count} numbers.");
                result[i] = v._items[i].Number;
            }
            return result;
        }

        /// <summary>The member as a finite 3-vector written as an array of three numbers.</summary>
        public System.Numerics.Vector3 GetVector3(string name)
        {
            double[] v = GetNumbers(name, 3);
            var result = new System.Numerics.Vector3((float)v[0], (float)v[1], (float)v[2]);
            if (!Vectors.IsFinite(result)) throw new FormatException($"'{name}' must be finite.");
            return result;
        }

        /// <summary>Parses JSON text (one value, nothing but white space after it).</summary>
        /// <exception cref="FormatException">The text is not valid JSON; the message names line and column.</exception>
        public static JsonNode Parse(string text)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            var p = new Parser(text);
            p.SkipSpace();
            JsonNode value = p.Value(0);
            p.SkipSpace();
            if (!p.AtEnd) throw p.Error("unexpected text after the value");
            return value;
        }

        private sealed class Parser
        {
            private const int MaxDepth = 64;
            private readonly string _s;
            private int _i;

            public Parser(string s) { _s = s; }

            public bool AtEnd => _i >= _s.Length;

            public void SkipSpace()
            {
                while (_i < _s.Length && (_s[_i] == ' ' || _s[_i] == '\t' || _s[_i] == '\n' || _s[_i] == '\r')) _i++;
            }

            public FormatException Error(string problem)
            {
                int line = 1, column = 1;
                for (int k = 0; k < _i && k < _s.Length; k++)
                {
                    if (_s[k] == '\n') { line++; column = 1; }
                    else column++;
                }
                return new FormatException($"JSON line {line}, column {column}: {problem}");
            }

            public JsonNode Value(int depth)
            {
                if (depth > MaxDepth) throw Error("nested too deeply");
                if (AtEnd) throw Error("unexpected end of text");
                char c = _s[_i];
                if (c == '{') return Object(depth);
                if (c == '[') return Array(depth);
                if (c == '"') return new JsonNode(JsonKind.String, StringLiteral());
                if (c == '-' || (c >= '0' && c <= '9')) return NumberLiteral();
                if (Word("true")) return new JsonNode(JsonKind.Bool, b: true);
                if (Word("false")) return new JsonNode(JsonKind.Bool, b: false);
                if (Word("null")) return new JsonNode(JsonKind.Null);
                throw Error($"unexpected character '{c}'");
            }

            private bool Word(string w)
            {
                if (string.CompareOrdinal(_s, _i, w, 0, w.Length) != 0) return false;
                _i += w.Length;
                return true;
            }

            private JsonNode Object(int depth)
            {
                var node = new JsonNode(JsonKind.Object);
                _i++;
                SkipSpace();
                if (!AtEnd && _s[_i] == '}') { _i++; return node; }
                while (true)
                {
                    SkipSpace();
                    if (AtEnd || _s[_i] != '"') throw Error("expected a member name in quotes");
                    string key = StringLiteral();
                    if (node._members.ContainsKey(key)) throw Error($"member '{key}' appears twice");
                    SkipSpace();
                    if (AtEnd || _s[_i] != ':') throw Error("expected ':'");
                    _i++;
                    SkipSpace();
                    node._members[key] = Value(depth + 1);
                    node._order.Add(key);
                    SkipSpace();
                    if (AtEnd) throw Error("unexpected end of text in an object");
                    if (_s[_i] == ',') { _i++; continue; }
                    if (_s[_i] == '}') { _i++; return node; }
                    throw Error("expected ',' or '}'");
                }
            }

            private JsonNode Array(int depth)
            {
                var node = new JsonNode(JsonKind.Array);
                _i++;
                SkipSpace();
                if (!AtEnd && _s[_i] == ']') { _i++; return node; }
                while (true)
                {
                    SkipSpace();
                    node._items.Add(Value(depth + 1));
                    SkipSpace();
                    if (AtEnd) throw Error("unexpected end of text in an array");
                    if (_s[_i] == ',') { _i++; continue; }
                    if (_s[_i] == ']') { _i++; return node; }
                    throw Error("expected ',' or ']'");
                }
            }

            private string StringLiteral()
            {
                var sb = new StringBuilder();
                _i++;
                while (true)
                {
                    if (AtEnd) throw Error("unterminated string");
                    char c = _s[_i++];
                    if (c == '"') return sb.ToString();
                    if (c < ' ') { _i--; throw Error("control character in a string (escape it)"); }
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
                            sb.Append((char)Hex4());
                            break;
                        default: _i -= 2; throw Error($"bad escape '\\{e}'");
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
                string text = _s.Substring(start, _i - start);
                if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) || double.IsInfinity(v))
                {
                    _i = start;
                    throw Error($"'{text}' is out of range");
                }
                return new JsonNode(JsonKind.Number, n: v);
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
                string text = _s.Substring(start, end - start);
                _i = start;
                return Error($"'{text}' is not a JSON number");
            }

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
