using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.RegularExpressions;

namespace AvatarGo.UnityGate;

/// <summary>
/// Unity's asmdef <c>defineConstraints</c>, restated from UnityCsReference@2021.3
/// Editor/Mono/Scripting/ScriptCompilation/DefineConstraintsHelper.cs: the assembly compiles only when every entry
/// holds. An entry is symbols joined by <c>||</c>, each optionally negated with <c>!</c>. Unity's rule for one entry,
/// kept exactly (including its quirk with several negations): it holds when any plain symbol is defined, or when none
/// of the negated symbols is defined; an entry with only negations (<c>!A || !B</c>) therefore holds only when neither
/// A nor B is defined. A symbol written both plain and negated in one entry cancels out. Empty entries, <c>|| ||</c>
/// and names that are not C# symbols are invalid (Unity refuses the asmdef).
/// </summary>
public static class DefineConstraints
{
    private static readonly Regex Symbol = new(@"^[\p{L}_][\p{L}\p{N}_]{0,246}$", RegexOptions.CultureInvariant); // SymbolNameRestrictions in CustomScriptAssembly.cs

    /// <summary>True when every constraint holds for <paramref name="defines"/>; throws <see cref="FormatException"/> for an invalid one.</summary>
    public static bool AllHold(IEnumerable<string> constraints, IReadOnlySet<string> defines) =>
        constraints.All(c => Holds(c, defines));

    /// <summary>True when one constraint entry holds; throws <see cref="FormatException"/> when Unity would call it invalid.</summary>
    public static bool Holds(string constraint, IReadOnlySet<string> defines)
    {
        if (string.IsNullOrEmpty(constraint)) throw new FormatException("an empty define constraint is invalid");
        string[] parts = Regex.Split(constraint, @"(\|\|)").Select(p => p.Trim(' ', '\t')).ToArray();
        for (int i = 0; i + 1 < parts.Length; i++)
            if (parts[i] == "||" && parts[i + 1] == "||") throw new FormatException($"'{constraint}': two '||' in a row");

        var expected = new HashSet<string>(parts.Where(p => p != "||" && !p.StartsWith('!')), StringComparer.Ordinal);
        var negated = new HashSet<string>(parts.Where(p => p != "||" && p.StartsWith('!')).Select(p => p.Substring(1)), StringComparer.Ordinal);
        foreach (string s in expected.Concat(negated))
            if (!Symbol.IsMatch(s)) throw new FormatException($"'{constraint}': '{s}' is not a symbol name");

        var both = new HashSet<string>(expected.Intersect(negated), StringComparer.Ordinal);
        expected.ExceptWith(both);
        negated.ExceptWith(both);
        if (expected.Count == 0 && negated.Count == 0) throw new FormatException($"'{constraint}' names no symbol");

        bool anyExpected = expected.Any(defines.Contains);
        bool noneNegated = !negated.Any(defines.Contains);
        if (negated.Count == 0) return anyExpected;
        if (expected.Count == 0) return noneNegated;
        return anyExpected || noneNegated;
    }
}
