using System;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>Text laid out for world-space labels that do not wrap by themselves (Unity's TextMesh). Engine-free.</summary>
    public static class TextLines
    {
        /// <summary>
        /// <paramref name="text"/> broken into lines of at most <paramref name="width"/> characters at spaces (a longer word
        /// stays whole on its own line); existing line breaks are kept. Allocates.
        /// </summary>
        public static string Wrap(string text, int width)
        {
            if (width < 1) throw new ArgumentOutOfRangeException(nameof(width), width, "A line holds at least one character.");
            if (string.IsNullOrEmpty(text)) return string.Empty;
            var result = new StringBuilder(text.Length + 8);
            string[] paragraphs = text.Replace("\r\n", "\n").Split('\n');
            for (int p = 0; p < paragraphs.Length; p++)
            {
                if (p > 0) result.Append('\n');
                int line = 0;
                foreach (string word in paragraphs[p].Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries))
                {
                    if (line > 0 && line + 1 + word.Length > width)
                    {
                        result.Append('\n');
                        line = 0;
                    }
                    else if (line > 0)
                    {
                        result.Append(' ');
                        line++;
                    }
                    result.Append(word);
                    line += word.Length;
                }
            }
            return result.ToString();
        }
    }
}
