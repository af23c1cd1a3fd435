using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class ProgramTests
{
    [Test]
    public void HelpListsCommands()
    {
        var r = CliRunner.Run("--help");
        Assert.That(r.ExitCode, Is.EqualTo(0));
        StringAssert.Contains("bvh info", r.Stdout);
        StringAssert.Contains("bvh positions", r.Stdout);
    }

    [Test]
    public void UnknownCommandIsAOneLineErrorWithExitCode2()
    {
        var r = CliRunner.Run("frobnicate");
        Assert.That(r.ExitCode, Is.EqualTo(2));
        Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1));
    }

    [Test]
    public void EveryCommandHasHelp()
    {
        Assert.That(AvatarGo.Cli.CommandCatalog.All.Count, Is.GreaterThanOrEqualTo(9), "bvh info, bvh positions, session info, simulate, calibrate, evaluate, demo, bench, fingers");
        foreach (var command in AvatarGo.Cli.CommandCatalog.All)
        {
            var r = CliRunner.Run((command.Name + " --help").Split(' '));
            Assert.That(r.ExitCode, Is.EqualTo(0), command.Name);
            StringAssert.StartsWith("avatargo " + command.Name, r.Stdout, command.Name);
            // Every option on a line of its own: help assembled from pieces once ran one option's text into the next
            // ("(default 8; the session's, as simulated)  --positions OUT.csv").
            foreach (string line in r.Stdout.Split('\n'))
                Assert.That(System.Text.RegularExpressions.Regex.IsMatch(line, @"\S {2,}--[a-z]"), Is.False, $"{command.Name}: an option run into the line before it: '{line.TrimEnd()}'");
        }
    }

    [TestCase(-0.04, "0.0"), TestCase(0.04, "0.0"), TestCase(0.26, "+0.3"), TestCase(-1.25, "-1.2"), TestCase(12.0, "+12.0")]
    public void SignedDifferencesPrintZeroWithoutASign(double value, string printed) =>
        Assert.That(AvatarGo.Cli.Commands.EvaluateCommand.Signed(value), Is.EqualTo(printed));

    [Test]
    public void UnknownOptionIsAUsageError()
    {
        var r = CliRunner.Run("bvh", "info", "x.bvh", "--bogus", "1");
        Assert.That(r.ExitCode, Is.EqualTo(2));
        StringAssert.Contains("unknown option --bogus", r.Stderr);
    }

    /// <summary>
    /// A number beyond any option's range is a bad argument (exit 2) naming the option, before anything is read (found in
    /// review: `--noise-deg 1e39` or `--twist 1e39` became infinite where the command narrowed it to a float and failed
    /// later as an unreadable input, exit 1).
    /// </summary>
    [TestCase("simulate", "--bvh", "x.bvh", "--out", "y.agsession", "--noise-deg", "1e39")]
    [TestCase("bvh", "rebase", "x.bvh", "y.bvh", "--rest", "x-along", "--twist", "1e39")]
    public void ANumberBeyondEveryOptionsRangeIsAUsageError(params string[] args)
    {
        var r = CliRunner.Run(args);
        Assert.That(r.ExitCode, Is.EqualTo(2), r.ToString());
        StringAssert.Contains("expects a number within", r.Stderr);
    }
}
