using System;
using System.IO;

namespace AvatarGo.Core
{
    /// <summary>
    /// Reads text one line at a time into one reused buffer (no string per line), counting lines, and refuses a line
    /// longer than a limit before holding more than that limit in memory. Lines end with LF, CRLF or a lone CR (as
    /// <see cref="TextReader.ReadLine"/> has it). A byte-order mark at the start of the text is skipped.
    /// </summary>
    internal sealed class TextLineReader
    {
        private readonly TextReader _reader;
        private readonly string _source;
        private readonly int _maxLineLength;
        private char[] _buffer = new char[1 << 12];
        private int _pos;
        private int _end;
        private bool _endOfText;
        private int _lineStart;
        private int _lineLength;

        public TextLineReader(TextReader reader, string source, int maxLineLength)
        {
            _reader = reader;
            _source = source;
            _maxLineLength = maxLineLength;
        }

        /// <summary>The 1-based number of the current line (0 before the first).</summary>
        public int LineNumber { get; private set; }

        /// <summary>The current line, without its line end; valid until the next <see cref="Next"/>.</summary>
        public ReadOnlySpan<char> Line => new ReadOnlySpan<char>(_buffer, _lineStart, _lineLength);

        /// <summary>Moves to the next line; false at the end of the text.</summary>
        /// <exception cref="FormatException">The line is longer than the limit.</exception>
        public bool Next()
        {
            int scanFrom = _pos;
            while (true)
            {
                int terminator = -1;
                for (int i = scanFrom; i < _end; i++)
                {
                    char c = _buffer[i];
                    if (c == '\n' || c == '\r') { terminator = i; break; }
                }
                if (terminator >= 0)
                {
                    // A CR at the end of the buffer may be the first half of a CRLF: read on before deciding.
                    if (_buffer[terminator] == '\r' && terminator + 1 == _end && !_endOfText)
                    {
                        scanFrom = terminator;
                        Fill(ref scanFrom);
                        continue;
                    }
                    _lineStart = _pos;
                    _lineLength = terminator - _pos;
                    _pos = terminator + (_buffer[terminator] == '\r' && terminator + 1 < _end && _buffer[terminator + 1] == '\n' ? 2 : 1);
                    LineNumber++;
                    TakeLine();
                    return true;
                }
                if (_endOfText)
                {
                    if (_pos >= _end) return false;
                    _lineStart = _pos;
                    _lineLength = _end - _pos;
                    _pos = _end;
                    LineNumber++;
                    TakeLine();
                    return true;
                }
                scanFrom = _end;
                Fill(ref scanFrom);
            }
        }

        // The line just found: refused when too long; at the start of the text, without a byte-order mark.
        private void TakeLine()
        {
            if (_lineLength > _maxLineLength) throw TooLong(LineNumber);
            // A UTF-8 byte-order mark a stream reader would have dropped (text handed over as a string keeps it).
            if (LineNumber == 1 && _lineLength > 0 && _buffer[_lineStart] == '\uFEFF')
            {
                _lineStart++;
                _lineLength--;
            }
        }

        private FormatException TooLong(int line) => new FormatException($"{_source}:{line}: a line longer than {_maxLineLength} characters (the reader's limit)");

        // Reads more text after the current line's start, moving it to the front or growing the buffer (up to the line
        // limit) as needed; `scanFrom` is kept pointing at the same character. False at the end of the text.
        private bool Fill(ref int scanFrom)
        {
            int pending = _end - _pos;
            if (pending > _maxLineLength) throw TooLong(LineNumber + 1);
            if (_pos > 0)
            {
                Array.Copy(_buffer, _pos, _buffer, 0, pending);
                scanFrom -= _pos;
                _pos = 0;
                _end = pending;
            }
            if (_end == _buffer.Length) Array.Resize(ref _buffer, (int)Math.Min((long)_buffer.Length * 2, (long)_maxLineLength + 2));
            int read = _reader.Read(_buffer, _end, _buffer.Length - _end);
            if (read <= 0)
            {
                _endOfText = true;
                return false;
            }
            _end += read;
            return true;
        }
    }
}
