using System;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>The knobs of a fuzzing run.</summary>
internal sealed class FuzzOptions
{
    public int Seed { get; init; } = 1;
    public TimeSpan Duration { get; init; } = TimeSpan.FromSeconds(60);
    public long MaxInputs { get; init; } = long.MaxValue;
    public string Corpus { get; init; }
    public bool Crafted { get; init; } = true;
    public bool Minimize { get; init; } = true;
    public double SlowMilliseconds { get; init; } = 1000;
    public int HangSeconds { get; init; } = 60;
    public int MaxSavedLength { get; init; } = 64 << 10;
    public bool Trace { get; init; }
}
