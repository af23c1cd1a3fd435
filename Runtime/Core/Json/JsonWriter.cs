using System.Globalization;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>Writes indented JSON into a string, numbers with round-trip precision in the invariant culture.</summary>
    public sealed class JsonWriter
    {
        private readonly StringBuilder _sb = new StringBuilder();
        private int _depth;
        private bool _first = true;
        private bool _afterName;

        /// <summary>Starts an object (as a value or a member's value).</summary>
        public JsonWriter BeginObject() => Open('{');

        /// <summary>Ends the current object.</summary>
        public JsonWriter EndObject() => Close('}');

        /// <summary>Starts an array.</summary>
        public JsonWriter BeginArray() => Open('[');

        /// <summary>Ends the current array.</summary>
        public JsonWriter EndArray() => Close(']');

        /// <summary>Writes a member name; the next call writes its value.</summary>
        public JsonWriter Name(string name)
        {
            Separator();
            Quote(name);
            _sb.Append(": ");
            _afterName = true;
            return this;
        }

        /// <summary>Writes a string value.</summary>
        public JsonWriter Value(string value)
        {
            Separator();
            if (value == null) _sb.Append("null"); else Quote(value);
            return this;
        }

        /// <summary>Writes a number value (round-trip precision).</summary>
        /// <exception cref="System.ArgumentOutOfRangeException">The value is NaN or infinite, which JSON cannot represent.</exception>
        public JsonWriter Value(double value)
        {
            CheckFinite(value);
            Separator();
            _sb.Append(RoundTripNumber.Format(value));
            return this;
        }

        /// <summary>Writes a float value (round-trip precision for floats).</summary>
        /// <exception cref="System.ArgumentOutOfRangeException">The value is NaN or infinite, which JSON cannot represent.</exception>
        public JsonWriter Value(float value)
        {
            CheckFinite(value);
            Separator();
            _sb.Append(value.ToString("R", CultureInfo.InvariantCulture));
            return this;
        }

        /// <summary>
        /// Writes an integer value exactly (an <c>int</c> argument comes here: through <see cref="Value(float)"/> it lost its
        /// digits beyond 2^24, a device id 16777217 written as 16777216).
        /// </summary>
        public JsonWriter Value(long value)
        {
            Separator();
            _sb.Append(value.ToString(CultureInfo.InvariantCulture));
            return this;
        }

        /// <summary>Writes true or false.</summary>
        public JsonWriter Value(bool value)
        {
            Separator();
            _sb.Append(value ? "true" : "false");
            return this;
        }

        /// <summary>Writes an array of floats on one line.</summary>
        /// <exception cref="System.ArgumentOutOfRangeException">A value is NaN or infinite, which JSON cannot represent.</exception>
        public JsonWriter Values(params float[] values)
        {
            if (values == null) throw new System.ArgumentNullException(nameof(values));
            foreach (float v in values) CheckFinite(v);
            Separator();
            _sb.Append('[');
            for (int i = 0; i < values.Length; i++)
            {
                if (i > 0) _sb.Append(", ");
                _sb.Append(values[i].ToString("R", CultureInfo.InvariantCulture));
            }
            _sb.Append(']');
            return this;
        }

        /// <summary>The text written so far.</summary>
        public override string ToString() => _sb.ToString();

        private static void CheckFinite(double value)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
                throw new System.ArgumentOutOfRangeException(nameof(value), value, "JSON has no NaN or infinity; write null or leave the member out.");
        }

        /// <summary>Writes null.</summary>
        public JsonWriter Null()
        {
            Separator();
            _sb.Append("null");
            return this;
        }

        private JsonWriter Open(char c)
        {
            Separator();
            _sb.Append(c);
            _depth++;
            _first = true;
            return this;
        }

        private JsonWriter Close(char c)
        {
            _depth--;
            if (!_first) NewLine();
            _sb.Append(c);
            _first = false;
            return this;
        }

        private void Separator()
        {
            if (_afterName) { _afterName = false; return; }
            if (_depth > 0)
            {
                if (!_first) _sb.Append(',');
                NewLine();
            }
            _first = false;
        }

        private void NewLine()
        {
            _sb.Append('\n');
            _sb.Append(' ', _depth * 2);
        }

        private void Quote(string s)
        {
            _sb.Append('"');
            foreach (char c in s)
            {
                switch (c)
                {
                    case '"': _sb.Append("\\\""); break;
                    case '\\': _sb.Append("\\\\"); break;
                    case '\n': _sb.Append("\\n"); break;
                    case '\r': _sb.Append("\\r"); break;
                    case '\t': _sb.Append("\\t"); break;
                    default:
                        if (c < ' ') _sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                        else _sb.Append(c);
                        break;
                }
            }
            _sb.Append('"');
        }
    }
}
