using System;

namespace AvatarGo.UnityGate;

/// <summary>
/// Unity's version-range grammar for asmdef <c>versionDefines</c> expressions, restated from UnityCsReference@2021.3
/// Editor/Mono/Scripting/ScriptCompilation/ExpressionTypeFactory.cs and VersionRanges.cs (unchanged to 6000.5):
/// <c>1.2.3</c> (x ≥ 1.2.3), <c>[1.2.3]</c> (x = 1.2.3), <c>(1.2.3,)</c> (x &gt; 1.2.3), <c>(,1.2.3]</c> (x ≤ 1.2.3),
/// <c>(,1.2.3)</c> (x &lt; 1.2.3) and the two-sided <c>[a,b]</c>, <c>(a,b)</c>, <c>[a,b)</c>, <c>(a,b]</c>.
/// Everything else is invalid, notably <c>[1.2.3,)</c> (write the bare version), <c>(1.2.3)</c>, a bracket without
/// its partner and any character a version cannot hold. Unity logs an invalid expression as an error on the asmdef and
/// leaves the symbol undefined; the gate reports it as a problem.
/// </summary>
public sealed class VersionRange
{
    private readonly char _open, _close;
    private readonly string _low, _high;
    private readonly Func<int?, int?, bool> _accepts; // (compare(x, low), compare(x, high)) -> in range

    private VersionRange(string expression, char open, char close, string low, string high, Func<int?, int?, bool> accepts)
    {
        Expression = expression;
        _open = open;
        _close = close;
        _low = low;
        _high = high;
        _accepts = accepts;
    }

    /// <summary>The expression as written.</summary>
    public string Expression { get; }

    /// <summary>Parses an expression; throws <see cref="FormatException"/> naming what Unity would reject.</summary>
    /// <param name="expression">The expression from the asmdef.</param>
    /// <param name="unityVersions">True for the "Unity" resource (editor versions also allow '/'), false for packages.</param>
    public static VersionRange Parse(string expression, bool unityVersions)
    {
        if (string.IsNullOrEmpty(expression)) throw new FormatException("an empty expression is not a range");
        bool separator = expression.Contains(',');
        int begin = 0, end = expression.Length - 1;
        char open = '\0', close = '\0';
        if (!char.IsDigit(expression[0]))
        {
            open = expression[0];
            if (open != '[' && open != '(') throw new FormatException($"Invalid character '{open}' in expression '{expression}'");
            begin++;
        }
        char last = expression[end];
        bool lastAllowed = unityVersions ? IsVersionChar(last, true) : char.IsAsciiLetterOrDigit(last);
        if (!lastAllowed)
        {
            close = last;
            if (close != ']' && close != ')') throw new FormatException($"Invalid character '{close}' in expression '{expression}'");
            end--;
        }
        if ((open == '\0') != (close == '\0'))
            throw new FormatException($"Incomplete expression '{expression}': a bracket at one end needs its partner at the other");

        string low = Pop(expression, ref begin, end, unityVersions);
        string high = Pop(expression, ref begin, end, unityVersions);
        bool hasLow = !string.IsNullOrEmpty(low), hasHigh = !string.IsNullOrEmpty(high);

        Func<int?, int?, bool> accepts = (open, close, separator, hasLow, hasHigh) switch
        {
            ('\0', '\0', false, true, false) => (l, _) => l >= 0,
            ('(', ')', true, true, false) => (l, _) => l > 0,
            ('[', ']', false, true, false) => (l, _) => l == 0,
            ('(', ']', true, false, true) => (_, h) => h <= 0,
            ('(', ')', true, false, true) => (_, h) => h < 0,
            ('(', ']', true, true, true) => (l, h) => l > 0 && h <= 0,
            ('[', ']', true, true, true) => (l, h) => l >= 0 && h <= 0,
            ('(', ')', true, true, true) => (l, h) => l > 0 && h < 0,
            ('[', ')', true, true, true) => (l, h) => l >= 0 && h < 0,
            _ => null,
        };
        if (accepts == null) throw new FormatException($"'{expression}' is not a valid expression");
        var range = new VersionRange(expression, open, close, hasLow ? low : null, hasHigh ? high : null, accepts);
        // Unity parses both bounds when it parses the expression: a bound that is no version makes it invalid.
        if (hasLow) range.ParseBound(low, unityVersions);
        if (hasHigh) range.ParseBound(high, unityVersions);
        return range;
    }

    /// <summary>True when the package version <paramref name="version"/> is in the range.</summary>
    public bool Contains(SemanticVersion version) =>
        _accepts(_low == null ? null : version.CompareTo(SemanticVersion.Parse(_low)),
            _high == null ? null : version.CompareTo(SemanticVersion.Parse(_high)));

    /// <summary>True when the editor version <paramref name="version"/> is in the range.</summary>
    public bool Contains(UnityVersion version) =>
        _accepts(_low == null ? null : version.CompareTo(UnityVersion.Parse(_low)),
            _high == null ? null : version.CompareTo(UnityVersion.Parse(_high)));

    private void ParseBound(string bound, bool unityVersions)
    {
        if (unityVersions) UnityVersion.Parse(bound);
        else SemanticVersion.Parse(bound);
    }

    private static string Pop(string expression, ref int cursor, int end, bool unityVersions)
    {
        if (cursor > end) return null;
        int start = cursor;
        while (cursor <= end && expression[cursor] != ',')
        {
            if (!IsVersionChar(expression[cursor], unityVersions))
                throw new FormatException($"'{expression[cursor]}' is not valid in the expression '{expression}'");
            cursor++;
        }
        string s = expression.Substring(start, cursor - start);
        if (cursor <= end) cursor++; // skip the comma
        return s;
    }

    private static bool IsVersionChar(char c, bool unityVersions) =>
        char.IsAsciiLetterOrDigit(c) || c == '.' || c == '-' || (unityVersions && c == '/');

    /// <inheritdoc />
    public override string ToString() => $"{Expression} ({_open}{_low},{_high}{_close})";
}
