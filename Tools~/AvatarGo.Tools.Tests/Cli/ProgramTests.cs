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
        }
    }

    [Test]
    public void UnknownOptionIsAUsageError()
    {
        var r = CliRunner.Run("bvh", "info", "x.bvh", "--bogus", "1");
        Assert.That(r.ExitCode, Is.EqualTo(2));
        StringAssert.Contains("unknown option --bogus", r.Stderr);
    }
}
