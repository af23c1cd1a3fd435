using System;
using System.Collections.Generic;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// One parser under fuzzing: how to parse a text (where a <see cref="FormatException"/> is the documented way to
/// refuse it) and what to do with what it parsed (later stages, where any exception, FormatException included, is a
/// failure: a file the parser accepted must be usable).
/// </summary>
internal sealed class FuzzTarget
{
    public FuzzTarget(string name, string extension, Func<string, object> parse, Action<object> use,
        IReadOnlyList<string> seeds, IReadOnlyList<string> dictionary, Func<IReadOnlyList<string>, IEnumerable<CraftedInput>> crafted, int maxInputLength)
    {
        MaxInputLength = maxInputLength;
        Name = name;
        Extension = extension;
        Parse = parse;
        Use = use;
        Seeds = seeds;
        Dictionary = dictionary;
        Crafted = crafted;
    }

    /// <summary>bvh, session, profile, controller or json.</summary>
    public string Name { get; }

    /// <summary>The file extension of this target's corpus files (".bvh", ".agsession", ".profile.json", ...).</summary>
    public string Extension { get; }

    /// <summary>Parses the text; may throw <see cref="FormatException"/> (the documented error) and nothing else.</summary>
    public Func<string, object> Parse { get; }

    /// <summary>Uses a parsed value the way the package's later stages do; must not throw at all.</summary>
    public Action<object> Use { get; }

    /// <summary>Valid files the mutations start from.</summary>
    public IReadOnlyList<string> Seeds { get; }

    /// <summary>Tokens of the format that mutations insert.</summary>
    public IReadOnlyList<string> Dictionary { get; }

    /// <summary>Hand-made edge cases, from the seeds (generated on demand: some are megabytes).</summary>
    public Func<IReadOnlyList<string>, IEnumerable<CraftedInput>> Crafted { get; }

    /// <summary>
    /// The longest generated input, in characters: 4 Mi for the line formats (beyond their line limit), 1.5 Mi for the
    /// JSON ones (far beyond the profiles' 64 Ki limit; JSON builds a node per value, so a 4 MB array takes most of a second).
    /// </summary>
    public int MaxInputLength { get; }

    /// <summary>Runs one input through the parser and, when it parses, the later stages.</summary>
    /// <returns>True when the input parsed; false when it was refused with a FormatException.</returns>
    /// <exception cref="Exception">Anything else: a failure.</exception>
    public bool Check(string text)
    {
        object parsed;
        try
        {
            parsed = Parse(text);
        }
        catch (FormatException e) when (e.Message.IndexOf('\n') < 0)
        {
            return false;
        }
        catch (FormatException e)
        {
            throw new FuzzFailure("a format error of more than one line", "a format error of more than one line: " + e.Message.Replace("\n", "\\n"));
        }
        try
        {
            Use(parsed);
        }
        catch (FuzzFailure)
        {
            throw;
        }
        catch (Exception e)
        {
            throw new FuzzFailure("later stage threw", $"accepted, then a later stage threw {e.GetType().Name}: {e.Message}", e);
        }
        return true;
    }
}
