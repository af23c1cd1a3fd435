using System;

namespace AvatarGo.Cli;

/// <summary>Wrong arguments: printed as a one-line error with a pointer to --help, exit code 2.</summary>
public sealed class UsageException : Exception
{
    public UsageException(string message) : base(message) { }
}
