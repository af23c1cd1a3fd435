using System;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>What the oracle throws for a failure that is not an exception of the code under test (a later stage's
/// exception, a poisoned value, a writer/reader round trip that does not hold).</summary>
internal sealed class FuzzFailure : Exception
{
    /// <param name="kind">A short, stable name of the kind of failure (failures are grouped by it).</param>
    /// <param name="message">What happened, with the values.</param>
    /// <param name="inner">The exception a later stage threw, if any.</param>
    public FuzzFailure(string kind, string message, Exception inner = null) : base(message, inner) { Kind = kind; }

    /// <summary>A short, stable name of the kind of failure.</summary>
    public string Kind { get; }
}
