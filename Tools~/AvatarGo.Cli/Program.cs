using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace AvatarGo.Cli;

/// <summary>Entry point of `avatargo`: finds the command named by the leading words and runs it.</summary>
public static class Program
{
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs a command line; used by Main and by the tests.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        IReadOnlyList<ICommand> commands = CommandCatalog.All;
        if (args.Length == 0 || args[0] is "--help" or "-h" or "help")
        {
            PrintUsage(commands, stdout);
            return args.Length == 0 ? 2 : 0;
        }

        ICommand command = CommandCatalog.Match(args, out int consumed);
        if (command == null)
        {
            var group = commands.Where(c => c.Name.StartsWith(args[0] + " ", StringComparison.Ordinal)).ToList();
            if (group.Count > 0 && (args.Length == 1 || args[1] is "--help" or "-h"))
            {
                PrintUsage(group, stdout);
                return args.Length == 1 ? 2 : 0;
            }
            stderr.WriteLine($"avatargo: unknown command '{string.Join(" ", args.TakeWhile(a => !a.StartsWith("-")))}'. Run 'avatargo --help'.");
            return 2;
        }

        string[] rest = args.Skip(consumed).ToArray();
        if (rest.Contains("--help") || rest.Contains("-h"))
        {
            stdout.WriteLine(command.Help.TrimEnd());
            return 0;
        }
        try
        {
            return command.Run(rest, stdout, stderr);
        }
        catch (UsageException e)
        {
            stderr.WriteLine($"avatargo {command.Name}: {e.Message}. Run 'avatargo {command.Name} --help'.");
            return 2;
        }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException or InvalidDataException)
        {
            stderr.WriteLine($"avatargo {command.Name}: {e.Message}");
            return 1;
        }
        catch (ArgumentException e) when (e is not ArgumentNullException)
        {
            // The library refusing what an input file holds (a skeleton without the humanoid bones a command needs, a
            // hand without fingers): one line, not a stack trace. A null argument is a bug and keeps its trace.
            int parameter = e.Message.IndexOf(" (Parameter '", StringComparison.Ordinal);
            stderr.WriteLine($"avatargo {command.Name}: {(parameter >= 0 ? e.Message.Substring(0, parameter) : e.Message).Split('\n')[0].TrimEnd('\r')}");
            return 1;
        }
    }

    private static void PrintUsage(IEnumerable<ICommand> commands, TextWriter stdout)
    {
        stdout.WriteLine("avatargo: AvatarGo's command-line tool (headless calibration, solving and evaluation).");
        stdout.WriteLine();
        stdout.WriteLine("Commands:");
        foreach (ICommand c in commands.OrderBy(c => c.Name, StringComparer.Ordinal))
            stdout.WriteLine($"  {c.Name,-18} {c.Summary}");
        stdout.WriteLine();
        stdout.WriteLine("Run 'avatargo COMMAND --help' for a command's options.");
    }
}
