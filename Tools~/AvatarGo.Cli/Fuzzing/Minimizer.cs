using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// Shrinks a failing input while it still fails the same way: first whole lines, in halves, quarters … single
/// lines (delta debugging), then characters in runs of 64, 16, 4 and 1, within a time budget.
/// </summary>
internal static class Minimizer
{
    public static string Minimize(string input, Func<string, bool> stillFails, TimeSpan budget)
    {
        var clock = Stopwatch.StartNew();
        bool Expired() => clock.Elapsed > budget;

        // Lines (with their line ends).
        List<string> lines = SplitKeepingEnds(input);
        for (int chunk = Math.Max(1, lines.Count / 2); chunk >= 1 && !Expired(); chunk /= 2)
        {
            for (int start = 0; start < lines.Count && !Expired();)
            {
                int length = Math.Min(chunk, lines.Count - start);
                var candidate = new List<string>(lines);
                candidate.RemoveRange(start, length);
                if (candidate.Count > 0 && stillFails(string.Concat(candidate))) lines = candidate;
                else start += length;
            }
            if (chunk == 1) break;
        }
        string text = string.Concat(lines);

        // Characters.
        foreach (int chunk in new[] { 64, 16, 4, 1 })
        {
            for (int start = 0; start < text.Length && !Expired();)
            {
                int length = Math.Min(chunk, text.Length - start);
                string candidate = text.Remove(start, length);
                if (candidate.Length > 0 && stillFails(candidate)) text = candidate;
                else start += length;
            }
        }
        return text;
    }

    private static List<string> SplitKeepingEnds(string s)
    {
        var lines = new List<string>();
        int start = 0;
        for (int i = 0; i < s.Length; i++)
            if (s[i] == '\n') { lines.Add(s.Substring(start, i + 1 - start)); start = i + 1; }
        if (start < s.Length) lines.Add(s.Substring(start));
        return lines;
    }
}
