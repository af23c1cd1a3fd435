namespace AvatarGo.Cli.Fuzzing;

/// <summary>A hand-made edge case: a name saying what it probes, and the text.</summary>
internal sealed record CraftedInput(string Name, string Text);
