using System;
using System.Collections.Generic;
using System.Text;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// Seeded text mutations: characters and spans deleted, inserted, replaced or repeated; lines dropped, doubled,
/// swapped or repeated many times (the shape of complexity attacks); numbers replaced by edge values; the format's
/// own tokens inserted; the text cut anywhere; pieces of other seeds spliced in. One to eight mutations are stacked.
/// The same (seed, index) always gives the same input, so any failure can be replayed.
/// </summary>
internal sealed class Mutator
{
    private readonly int _maxLength;

    private const string Alphabet = " \t\n\r\n{}[]\":,.-+eE0123456789#-_abcdefxyzXYZ\\/\0\u00A0\u2028\uFEFF\u00E9\uD83D";
    private readonly IReadOnlyList<string> _seeds;
    private readonly IReadOnlyList<string> _dictionary;

    /// <param name="seeds">Valid files to start from.</param>
    /// <param name="dictionary">Tokens of the format.</param>
    /// <param name="maxLength">Inputs are kept under this many characters (so that a run is about parsers, not memory).</param>
    public Mutator(IReadOnlyList<string> seeds, IReadOnlyList<string> dictionary, int maxLength)
    {
        _maxLength = maxLength;
        if (seeds.Count == 0) throw new ArgumentException("no seeds", nameof(seeds));
        _seeds = seeds;
        _dictionary = dictionary;
    }

    /// <summary>The <paramref name="index"/>-th input of the run with <paramref name="seed"/>.</summary>
    public string Generate(int seed, long index)
    {
        var rng = new Random(unchecked((int)(seed * 1000003L ^ index * 7919L ^ (index >> 31))));
        var text = new StringBuilder(_seeds[rng.Next(_seeds.Count)]);
        int count = 1;
        while (count < 8 && rng.Next(2) == 0) count++;
        for (int i = 0; i < count; i++) Mutate(text, rng);
        return text.ToString();
    }

    private void Mutate(StringBuilder s, Random rng)
    {
        int n = s.Length;
        int at = n == 0 ? 0 : rng.Next(n + 1);
        switch (rng.Next(17))
        {
            case 0: if (n > 0) s.Remove(Math.Min(at, n - 1), 1); break;
            case 1: s.Insert(at, Alphabet[rng.Next(Alphabet.Length)]); break;
            case 2: if (n > 0) s[Math.Min(at, n - 1)] = Alphabet[rng.Next(Alphabet.Length)]; break;
            case 3: if (n > 0) s.Remove(Math.Min(at, n - 1), Math.Min(n - Math.Min(at, n - 1), 1 + rng.Next(64))); break;
            case 4:
            {
                if (n == 0) break;
                int start = Math.Min(at, n - 1), length = Math.Min(n - start, 1 + rng.Next(256));
                string span = s.ToString(start, length);
                s.Insert(rng.Next(s.Length + 1), span);
                break;
            }
            case 5: case 6: s.Insert(at, _dictionary.Count > 0 ? _dictionary[rng.Next(_dictionary.Count)] : "x"); break;
            case 7: case 8: ReplaceNumber(s, rng); break;
            case 9: LineEdit(s, rng, 0); break;
            case 10: LineEdit(s, rng, 1); break;
            case 11: LineEdit(s, rng, 2); break;
            case 12: LineEdit(s, rng, 3); break;
            case 13: if (n > 0) s.Length = rng.Next(n); break;
            case 14:
            {
                string other = _seeds[rng.Next(_seeds.Count)];
                if (other.Length == 0) break;
                int start = rng.Next(other.Length), length = Math.Min(other.Length - start, 1 + rng.Next(512));
                s.Insert(at, other.Substring(start, length));
                break;
            }
            case 15: s.Insert(at, CraftedInputs.Numbers[rng.Next(CraftedInputs.Numbers.Length)]); break;
            default:
            {
                // Line ends: LF → CRLF or CR, or the other way.
                string all = s.ToString();
                all = rng.Next(3) switch { 0 => all.Replace("\n", "\r\n"), 1 => all.Replace("\n", "\r"), _ => all.Replace("\r", "") };
                s.Clear().Append(all);
                break;
            }
        }
        if (s.Length > _maxLength) s.Length = _maxLength;
    }

    // Replaces one number-like token (digits, sign, point, exponent) with an edge value.
    private static void ReplaceNumber(StringBuilder s, Random rng)
    {
        if (s.Length == 0) return;
        int probe = rng.Next(s.Length);
        for (int tries = 0; tries < 64 && !IsNumberChar(s[probe]); tries++) probe = rng.Next(s.Length);
        if (!IsNumberChar(s[probe])) return;
        int start = probe, end = probe;
        while (start > 0 && IsNumberChar(s[start - 1])) start--;
        while (end < s.Length && IsNumberChar(s[end])) end++;
        s.Remove(start, end - start).Insert(start, CraftedInputs.Numbers[rng.Next(CraftedInputs.Numbers.Length)]);
    }

    private static bool IsNumberChar(char c) => (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E';

    private void LineEdit(StringBuilder s, Random rng, int kind)
    {
        string[] lines = s.ToString().Split('\n');
        if (lines.Length == 0) return;
        var list = new List<string>(lines);
        int i = rng.Next(list.Count);
        switch (kind)
        {
            case 0: list.RemoveAt(i); break;
            case 1: list.Insert(i, list[i]); break;
            case 2:
            {
                int j = rng.Next(list.Count);
                (list[i], list[j]) = (list[j], list[i]);
                break;
            }
            default:
            {
                // Repeat a line (or a block of lines) many times: a linear parser does not mind, a quadratic one does.
                int block = Math.Min(list.Count - i, 1 + rng.Next(4));
                int times = rng.Next(4) == 0 ? 1000 + rng.Next(20000) : 2 + rng.Next(50);
                int length = 0;
                for (int k = 0; k < block; k++) length += list[i + k].Length + 1;
                times = Math.Max(1, Math.Min(times, (_maxLength - s.Length) / Math.Max(1, length)));
                var repeated = new List<string>(block * times);
                for (int t = 0; t < times; t++)
                    for (int k = 0; k < block; k++) repeated.Add(list[i + k]);
                list.InsertRange(i, repeated);
                break;
            }
        }
        s.Clear().Append(string.Join("\n", list));
    }
}
