using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using AvatarGo.Cli.Fuzzing;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// `avatargo fuzz`: the corpus of previous failures passes the full oracle (parse, then the later stages), each
/// target runs clean for a few hundred inputs, and the harness itself catches, minimises and saves a failure.
/// </summary>
public class FuzzCommandTests
{
    private static IEnumerable<string> CorpusFiles() =>
        Directory.GetFiles(Path.Combine(Paths.PackageRoot, "Tests", "Core", "Data~", "fuzz-corpus")).Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal);

    [TestCaseSource(nameof(CorpusFiles))]
    public void EveryCorpusFilePassesTheWholeOracleWithinASecond(string file)
    {
        string target = FuzzTargets.TargetOfFile(file);
        Assert.That(target, Is.Not.Null, $"{file}: not a corpus file name");
        string text = File.ReadAllText(Path.Combine(Paths.PackageRoot, "Tests", "Core", "Data~", "fuzz-corpus", file));
        var clock = Stopwatch.StartNew();
        FuzzTargets.ForChecking(target).Check(text); // throws on any failure; false or true are both fine
        Assert.That(clock.ElapsedMilliseconds, Is.LessThan(1000));
    }

    [TestCase("bvh")]
    [TestCase("session")]
    [TestCase("profile")]
    [TestCase("controller")]
    [TestCase("json")]
    public void EachTargetRunsCleanForAFewHundredInputs(string target)
    {
        string corpus = Path.Combine(Path.GetTempPath(), "avatargo-fuzz-" + Guid.NewGuid().ToString("N"));
        try
        {
            // The 1 s limit is for real runs on an idle machine; here the suite shares the cores, so only exceptions count.
            var r = CliRunner.Run("fuzz", "--target", target, "--inputs", "300", "--seconds", "60", "--no-crafted", "--seed", "7", "--corpus", corpus, "--slow-ms", "10000");
            Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
            StringAssert.Contains(target, r.Stdout);
            Assert.That(Directory.Exists(corpus), Is.False, "no failure saved");
        }
        finally { if (Directory.Exists(corpus)) Directory.Delete(corpus, true); }
    }

    [Test]
    public void TheSameSeedGivesTheSameInputs()
    {
        var seeds = new[] { "alpha 1 2 3\nbeta 4 5\n", "{\"x\": [1, 2]}" };
        var a = new Mutator(seeds, new[] { "gamma" }, 1 << 16);
        var b = new Mutator(seeds, new[] { "gamma" }, 1 << 16);
        for (int i = 0; i < 200; i++) Assert.That(b.Generate(3, i), Is.EqualTo(a.Generate(3, i)));
        Assert.That(Enumerable.Range(0, 200).Select(i => a.Generate(3, i)).Distinct().Count(), Is.GreaterThan(150), "inputs differ");
    }

    [Test]
    public void AFailureIsCaughtMinimisedAndSaved()
    {
        // A parser with a planted bug: any input holding "boom" throws IndexOutOfRangeException.
        string corpus = Path.Combine(Path.GetTempPath(), "avatargo-fuzz-" + Guid.NewGuid().ToString("N"));
        var target = new FuzzTarget("json", ".json",
            text => text.Contains("boom") ? throw new IndexOutOfRangeException("planted") : text.Length > 5 ? text : throw new FormatException("x:1: short"),
            _ => { }, new[] { "a long line of text\nand a second line with boom in it\nand a third\n" }, new[] { "boom" }, _ => Array.Empty<CraftedInput>(), 1 << 16);
        try
        {
            var report = new FuzzRunner(target, new FuzzOptions { Seed = 1, MaxInputs = 200, Corpus = corpus, Crafted = false }, TextWriter.Null).Run();
            Assert.That(report.Failures, Is.GreaterThan(0));
            FuzzFinding finding = report.Findings.Single();
            StringAssert.StartsWith("IndexOutOfRangeException", finding.Bucket);
            Assert.That(finding.Example, Is.EqualTo("boom"), "minimised to what fails");
            Assert.That(File.ReadAllText(finding.SavedAs), Is.EqualTo("boom"));
            StringAssert.EndsWith(".json", finding.SavedAs);
        }
        finally { if (Directory.Exists(corpus)) Directory.Delete(corpus, true); }
    }

    [Test]
    public void ASlowInputIsAFailure()
    {
        var target = new FuzzTarget("json", ".json", text => { System.Threading.Thread.Sleep(30); return text; }, _ => { },
            new[] { "x" }, Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 100);
        var report = new FuzzRunner(target, new FuzzOptions { MaxInputs = 3, SlowMilliseconds = 10, Minimize = false, Crafted = false }, TextWriter.Null).Run();
        Assert.That(report.Findings.Single().Bucket, Is.EqualTo("slow"));
    }
}
