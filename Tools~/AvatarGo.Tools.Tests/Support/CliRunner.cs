using System.IO;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// Runs the `avatargo` CLI in-process through <see cref="AvatarGo.Cli.Program.Run"/> and captures what
/// it prints. In-process keeps tests fast and debuggable; commands get their writers as arguments, so
/// nothing touches the real console. Not thread-safe only if a command itself uses global state.
/// </summary>
public static class CliRunner
{
    /// <summary>What one CLI run produced.</summary>
    /// <param name="ExitCode">The process exit code Main would return (0 ok, 1 failure, 2 usage error).</param>
    /// <param name="Stdout">Everything written to standard output.</param>
    /// <param name="Stderr">Everything written to standard error.</param>
    public sealed record Result(int ExitCode, string Stdout, string Stderr)
    {
        /// <summary>A readable dump for assertion messages.</summary>
        public override string ToString() => $"exit {ExitCode}\n--- stdout ---\n{Stdout}--- stderr ---\n{Stderr}";
    }

    /// <summary>Runs `avatargo ARGS...` and returns its exit code and output.</summary>
    public static Result Run(params string[] args)
    {
        using var stdout = new StringWriter { NewLine = "\n" };
        using var stderr = new StringWriter { NewLine = "\n" };
        int code = AvatarGo.Cli.Program.Run(args, stdout, stderr);
        return new Result(code, stdout.ToString(), stderr.ToString());
    }
}
