using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// Arguments a command cannot honour are bad arguments (exit 2, naming the option), found before any work: each case
/// here once failed later, as an unreadable input (exit 1) naming something else, or aborted the process.
/// </summary>
public class ArgumentRangeTests : TempFolderTests
{
    private static void AssertBadArgument(CliRunner.Result r, string option)
    {
        Assert.That(r.ExitCode, Is.EqualTo(2), r.ToString());
        StringAssert.Contains(option, r.Stderr);
    }

    [Test]
    public void AnOptionGivenTwiceIsABadArgument()
    {
        // The second value used to win silently: frame 2 was printed.
        var r = CliRunner.Run("bvh", "positions", Paths.Mocap("mocapbank_30fps.bvh"), "--frames", "0:1", "--frames", "2:3");
        AssertBadArgument(r, "--frames");
        StringAssert.Contains("twice", r.Stderr);
    }

    [Test]
    public void AMisspeltFlagIsAnUnknownOptionAndTakesNoOtherOptionAsItsValue()
    {
        // "--jsn" at the end was "needs a value", and before another option it swallowed that option as its value.
        string session = Path.Combine(Dir, "missing.agsession");
        var last = CliRunner.Run("calibrate", session, "--jsn");
        AssertBadArgument(last, "unknown option --jsn");
        var before = CliRunner.Run("calibrate", session, "--jsn", "--save", Path.Combine(Dir, "p.json"));
        AssertBadArgument(before, "unknown option --jsn");
        // A known option without its value still says so.
        AssertBadArgument(CliRunner.Run("calibrate", session, "--save"), "option --save needs a value");
        AssertBadArgument(CliRunner.Run("bvh", "positions", Paths.Mocap("mocapbank_30fps.bvh"), "--scale", "--frames", "0:1"), "option --scale needs a value");
    }

    [Test]
    public void AClipInInchesThatReadsAsCentimetresIsReadRightWithUnits()
    {
        // MocapBank scaled to a 2.3 m person and written in inches: its longest chain, 65 units, is a person in
        // centimetres too, and the guess takes centimetres (a 0.9 m wearer). --units in reads it right.
        string text = File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh"));
        // Only the lengths scale: the OFFSET lines and the root's three position channels.
        var lines = text.Split('\n');
        bool motion = false;
        for (int i = 0; i < lines.Length; i++)
        {
            string l = lines[i];
            if (l.StartsWith("MOTION", StringComparison.Ordinal)) motion = true;
            string t = l.TrimStart();
            if (!motion && t.StartsWith("OFFSET", StringComparison.Ordinal)) lines[i] = "OFFSET " + string.Join(" ", t.Substring(6).Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(Scale));
            else if (motion && t.Length > 0 && (char.IsDigit(t[0]) || t[0] == '-') && !t.StartsWith("Frame", StringComparison.Ordinal))
            {
                string[] v = t.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                for (int k = 0; k < 3 && k < v.Length; k++) v[k] = Scale(v[k]); // the root's Xposition Yposition Zposition
                lines[i] = string.Join(" ", v);
            }
        }
        static string Scale(string v) => (double.Parse(v, System.Globalization.CultureInfo.InvariantCulture) * 1.42 / 2.54).ToString("R", System.Globalization.CultureInfo.InvariantCulture);
        string clip = Path.Combine(Dir, "giant-inches.bvh");
        File.WriteAllText(clip, string.Join("\n", lines));
        string guessed = Path.Combine(Dir, "guessed.agsession"), given = Path.Combine(Dir, "given.agsession");
        Assert.That(CliRunner.Run("simulate", "--bvh", clip, "--out", guessed).ExitCode, Is.EqualTo(0));
        var r = CliRunner.Run("simulate", "--bvh", clip, "--out", given, "--units", "in");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        double Height(string session) => double.Parse(System.Text.RegularExpressions.Regex.Match(CliRunner.Run("calibrate", session).Stdout, @"wearer eye height ([0-9.]+) m").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
        Assert.That(Height(guessed), Is.LessThan(1.2), "read as centimetres: a small person");
        // The eye height measured from the headset scales with the body but for the device's own offsets: within 3 %.
        Assert.That(Height(given), Is.EqualTo(1.42 * Height(Session("plain"))).Within(0.03 * 1.42 * 1.575), "read as inches: the giant");
        AssertBadArgument(CliRunner.Run("simulate", "--bvh", clip, "--out", given, "--units", "furlongs"), "--units");
    }

    private string Session(string name)
    {
        string path = Path.Combine(Dir, name + ".agsession");
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", path).ExitCode, Is.EqualTo(0));
        return path;
    }

    // Beyond what a session holds (positions within 10 km) the writer refused a device's pose: exit 1, on some seeds.
    [TestCase("--noise-mm", "1e7")]
    [TestCase("--noise-deg", "1e12")]
    [TestCase("--misalign-mm", "1e12")]
    [TestCase("--misalign-deg", "-1e12")]
    public void SimulatedNoiseAndMisalignmentBeyondASessionsRangeAreBadArguments(string option, string value)
    {
        string output = Path.Combine(Dir, "x.agsession");
        AssertBadArgument(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", output, option, value), option);
        Assert.That(File.Exists(output), Is.False, "nothing written");
    }

    [Test]
    public void AScaleThatIsZeroAsAFloatIsABadArgument() =>
        // 1e-50 passed the check on the double and reached the reader as 0: exit 1 naming BvhReadOptions.Scale.
        AssertBadArgument(CliRunner.Run("bvh", "positions", Paths.Mocap("mocapbank_30fps.bvh"), "--scale", "1e-50"), "--scale");

    [Test]
    public void ASeedWithBonesAlongXIsABadArgument() =>
        AssertBadArgument(CliRunner.Run("bvh", "rebase", Paths.Mocap("mocapbank_30fps.bvh"), Path.Combine(Dir, "out.bvh"), "--rest", "x-along", "--seed", "5"), "--seed");

    [TestCase("--seconds", "1e12")] // a TimeSpan overflowed: the process aborted
    [TestCase("--slow-ms", "-1")]   // every input counted as slow and valid seeds were saved as failures
    [TestCase("--replay", "abc")]   // parsed on the fuzzing thread: the process aborted
    [TestCase("--replay", "-3")]
    public void FuzzOptionsOutOfRangeAreBadArguments(string option, string value) =>
        AssertBadArgument(CliRunner.Run("fuzz", "--target", "json", "--inputs", "1", "--no-crafted", "--corpus", Dir, option, value), option);

    [Test]
    public void WhatTheFuzzingThreadThrowsIsReportedNotAnAbort()
    {
        // An output folder that does not exist, written on the fuzzing thread: the process aborted (exit 134).
        var r = CliRunner.Run("fuzz", "--target", "json", "--replay", "3", "--out", Path.Combine(Dir, "missing", "x.json"));
        Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
        StringAssert.Contains("does not exist", r.Stderr);
    }

    [TestCase("--json")]
    [TestCase("--frames")]
    public void OptionsOfTheFrameBenchAreRefusedWithTheCalibrationBench(string option)
    {
        string[] args = option == "--json" ? new[] { "bench", "--calibration", "--json" } : new[] { "bench", "--calibration", "--frames", "5" };
        AssertBadArgument(CliRunner.Run(args), "--calibration");
    }
}
