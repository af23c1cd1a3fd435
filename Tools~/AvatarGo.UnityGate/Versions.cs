using System;
using System.Globalization;

namespace AvatarGo.UnityGate;

/// <summary>
/// A version Unity compares in asmdef <c>versionDefines</c>: either a package's SemVer or the editor's own version
/// ("Unity" resource). Semantics restated from UnityCsReference@2021.3
/// Editor/Mono/Scripting/ScriptCompilation/SemVersion.cs and UnityVersion.cs (not copied).
/// </summary>
public interface IUnityComparableVersion<T> : IComparable<T>
{
    /// <summary>True when the character may appear inside a version of this kind in a range expression.</summary>
    bool AllowsCharacter(char c);
}

/// <summary>
/// A package version as Unity parses it for versionDefines: MAJOR[.MINOR[.PATCH]][-PRERELEASE][+BUILD]; missing parts are 0.
/// Ordering: by major, minor, patch, then a version with a pre-release sorts before the same version without one
/// (pre-release parts compared numerically when both are numbers, a number before a word, words ordinally); the build
/// part is ignored.
/// </summary>
public readonly record struct SemanticVersion(int Major, int Minor, int Patch, string Prerelease) : IComparable<SemanticVersion>
{
    /// <summary>Parses a package version; throws <see cref="FormatException"/> for anything Unity rejects.</summary>
    public static SemanticVersion Parse(string text)
    {
        if (string.IsNullOrEmpty(text) || !char.IsDigit(text[0])) throw new FormatException($"'{text}' is not a valid package version");
        int cursor = 0;
        int major = ReadNumber(text, ref cursor), minor = 0, patch = 0;
        if (cursor < text.Length && text[cursor] == '.') { cursor++; minor = ReadNumber(text, ref cursor); }
        if (cursor < text.Length && text[cursor] == '.') { cursor++; patch = ReadNumber(text, ref cursor); }
        string prerelease = "";
        if (cursor < text.Length && text[cursor] == '-')
        {
            int plus = text.IndexOf('+', cursor);
            prerelease = plus < 0 ? text.Substring(cursor + 1) : text.Substring(cursor + 1, plus - cursor - 1);
            cursor = plus < 0 ? text.Length : plus;
        }
        if (cursor < text.Length && text[cursor] != '+') throw new FormatException($"'{text}' is not a valid package version");
        return new SemanticVersion(major, minor, patch, prerelease);
    }

    private static int ReadNumber(string text, ref int cursor)
    {
        int start = cursor;
        while (cursor < text.Length && char.IsDigit(text[cursor])) cursor++;
        if (cursor == start) throw new FormatException($"'{text}' is not a valid package version");
        return int.Parse(text.AsSpan(start, cursor - start), NumberStyles.None, CultureInfo.InvariantCulture);
    }

    /// <inheritdoc />
    public int CompareTo(SemanticVersion other)
    {
        int c = Major.CompareTo(other.Major);
        if (c == 0) c = Minor.CompareTo(other.Minor);
        if (c == 0) c = Patch.CompareTo(other.Patch);
        return c != 0 ? c : ComparePrerelease(Prerelease, other.Prerelease);
    }

    private static int ComparePrerelease(string a, string b)
    {
        if (a.Length == 0 || b.Length == 0) return (a.Length == 0 ? 1 : 0) - (b.Length == 0 ? 1 : 0);
        string[] pa = a.Split('.'), pb = b.Split('.');
        for (int i = 0; i < Math.Min(pa.Length, pb.Length); i++)
        {
            bool na = int.TryParse(pa[i], NumberStyles.None, CultureInfo.InvariantCulture, out int ia);
            bool nb = int.TryParse(pb[i], NumberStyles.None, CultureInfo.InvariantCulture, out int ib);
            int c = na && nb ? ia.CompareTo(ib) : na ? -1 : nb ? 1 : string.CompareOrdinal(pa[i], pb[i]);
            if (c != 0) return Math.Sign(c);
        }
        return pa.Length.CompareTo(pb.Length);
    }

    /// <inheritdoc />
    public override string ToString() => $"{Major}.{Minor}.{Patch}" + (Prerelease.Length > 0 ? "-" + Prerelease : "");
}

/// <summary>
/// An editor version such as 2021.3.0f1 or 6000.5.2f1: MAJOR.MINOR.REVISION, a release letter (a, b, f or c, p, x in
/// that order; c counts as f) and an increment. Missing parts are 0 and a missing letter means f.
/// </summary>
public readonly record struct UnityVersion(int Major, int Minor, int Revision, char Release, int Increment) : IComparable<UnityVersion>
{
    private const string ReleaseOrder = "abfpx"; // 'c' (China) ranks as 'f'

    /// <summary>Parses an editor version; throws <see cref="FormatException"/> for anything Unity rejects.</summary>
    public static UnityVersion Parse(string text)
    {
        if (string.IsNullOrEmpty(text) || !char.IsDigit(text[0])) throw new FormatException($"'{text}' is not a valid Unity version");
        int cursor = 0;
        int major = Read(text, ref cursor), minor = 0, revision = 0, increment = 0;
        char release = 'f';
        if (cursor < text.Length && text[cursor] == '.') { cursor++; minor = Read(text, ref cursor); }
        if (cursor < text.Length && text[cursor] == '.') { cursor++; revision = Read(text, ref cursor); }
        if (cursor < text.Length && "abfcpx".IndexOf(text[cursor]) >= 0)
        {
            release = text[cursor] == 'c' ? 'f' : text[cursor];
            cursor++;
            if (cursor < text.Length && char.IsDigit(text[cursor])) increment = Read(text, ref cursor);
        }
        return new UnityVersion(major, minor, revision, release, increment); // anything after is a suffix Unity ignores
    }

    private static int Read(string text, ref int cursor)
    {
        int start = cursor;
        while (cursor < text.Length && char.IsDigit(text[cursor])) cursor++;
        if (cursor == start) throw new FormatException($"'{text}' is not a valid Unity version");
        return int.Parse(text.AsSpan(start, cursor - start), NumberStyles.None, CultureInfo.InvariantCulture);
    }

    /// <inheritdoc />
    public int CompareTo(UnityVersion other)
    {
        int c = Major.CompareTo(other.Major);
        if (c == 0) c = Minor.CompareTo(other.Minor);
        if (c == 0) c = Revision.CompareTo(other.Revision);
        if (c == 0) c = ReleaseOrder.IndexOf(Release).CompareTo(ReleaseOrder.IndexOf(other.Release));
        return c != 0 ? c : Increment.CompareTo(other.Increment);
    }

    /// <inheritdoc />
    public override string ToString() => $"{Major}.{Minor}.{Revision}{Release}{Increment}";
}
