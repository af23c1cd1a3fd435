using System.IO;

namespace AvatarGo.Cli;

/// <summary>
/// One `avatargo` command. Implementations are found by reflection, so adding a command is adding a
/// class: no registry to edit. <see cref="Name"/> may have several words ("bvh info").
/// </summary>
public interface ICommand
{
    /// <summary>The words that select the command, e.g. "bvh positions".</summary>
    string Name { get; }

    /// <summary>One line for the command list.</summary>
    string Summary { get; }

    /// <summary>The full help text printed by --help.</summary>
    string Help { get; }

    /// <summary>Runs the command; returns the process exit code.</summary>
    int Run(string[] args, TextWriter stdout, TextWriter stderr);
}
