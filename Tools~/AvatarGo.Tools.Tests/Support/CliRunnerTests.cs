using System;
using AvatarGo.Cli;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>The CLI's top level through <see cref="CliRunner"/>: help and unknown commands.</summary>
[TestFixture]
public class CliRunnerTests
{
    [Test]
    public void HelpExitsZeroAndListsEveryCommand()
    {
        CliRunner.Result r = CliRunner.Run("--help");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        Assert.That(r.Stdout, Does.Contain("Commands:"), r.ToString());
        foreach (ICommand c in CommandCatalog.All)
            Assert.That(r.Stdout, Does.Contain(c.Name), $"'{c.Name}' missing from the command list\n{r}");
        Assert.That(r.Stderr, Is.Empty, r.ToString());
    }

    [Test]
    public void UnknownCommandExitsTwoWithOneLineMessage()
    {
        CliRunner.Result r = CliRunner.Run("no-such-command", "--flag");
        Assert.That(r.ExitCode, Is.EqualTo(2), r.ToString());
        string message = r.Stderr.TrimEnd('\n');
        Assert.That(message, Does.Not.Contain("\n"), r.ToString());
        Assert.That(message, Does.Contain("no-such-command").And.Contain("--help"), r.ToString());
        Assert.That(r.Stdout, Is.Empty, r.ToString());
        Assert.That(message.Contains("Exception", StringComparison.Ordinal), Is.False, "no stack trace: " + r);
    }
}
