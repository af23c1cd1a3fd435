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

    [TestCase("bvh", "info")]
    [TestCase("bvh", "positions")]
    public void EveryCommandHasHelp(string a, string b)
    {
        var r = CliRunner.Run(a, b, "--help");
        Assert.That(r.ExitCode, Is.EqualTo(0));
        StringAssert.StartsWith("avatargo " + a + " " + b, r.Stdout);
    }

    [Test]
    public void UnknownOptionIsAUsageError()
    {
        var r = CliRunner.Run("bvh", "info", "x.bvh", "--bogus", "1");
        Assert.That(r.ExitCode, Is.EqualTo(2));
        StringAssert.Contains("unknown option --bogus", r.Stderr);
    }
}
