using System;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// What a run writes cannot cost what it read or wrote before (found in review): an output that is also an input, or two
/// outputs that are one file, are refused before any work; evaluate's outputs are replaced together or not at all; a
/// folder given as an input says so; demo leaves the shared temporary folder alone; evaluate says when it has nothing to
/// compare; --positions' frame column is the frame's index whatever the session's clock.
/// </summary>
public class OutputClashTests : TempFolderTests
{
    private string Session(string name = "s.agsession")
    {
        string path = Path.Combine(Dir, name);
        var r = CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", path, "--seed", "1");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        return path;
    }

    private string Existing(string name)
    {
        string path = Path.Combine(Dir, name);
        File.WriteAllText(path, "the previous " + name + "\n");
        return path;
    }

    [Test]
    public void AnOutputThatIsAnInputOrAnotherOutputIsRefused()
    {
        string session = Session();
        byte[] before = File.ReadAllBytes(session);
        string clip = Path.Combine(Dir, "clip.bvh");
        File.Copy(Paths.Mocap("mocapbank_30fps.bvh"), clip);
        string link = Path.Combine(Dir, "link.agsession");
        File.CreateSymbolicLink(link, session);
        string folderLink = Path.Combine(Dir, "folder-link");
        Directory.CreateSymbolicLink(folderLink, Dir);
        string same = Path.Combine(Dir, "same");
        var runs = new[]
        {
            new[] { "evaluate", session, "--hands", "calibrated", "--json", session },
            new[] { "evaluate", session, "--hands", "calibrated", "--json", link },          // through a symbolic link
            new[] { "evaluate", session, "--hands", "calibrated", "--json", Path.Combine(folderLink, "s.agsession") }, // a linked folder
            new[] { "evaluate", Path.Combine(folderLink, "s.agsession"), "--hands", "calibrated", "--json", session },
            new[] { "evaluate", session, "--hands", "calibrated", "--positions", same, "--bvh-out", same },
            new[] { "calibrate", session, "--save", session },
            new[] { "simulate", "--bvh", clip, "--out", clip },
            new[] { "demo", "--bvh", clip, "--out-bvh", clip },
        };
        foreach (string[] args in runs)
        {
            var r = CliRunner.Run(args);
            Assert.That(r.ExitCode, Is.EqualTo(2), string.Join(" ", args) + "\n" + r);
            StringAssert.Contains("is the same file as", r.Stderr);
        }
        Assert.That(File.ReadAllBytes(session), Is.EqualTo(before), "the session");
        StringAssert.StartsWith("HIERARCHY", File.ReadAllText(clip), "the clip");
        Assert.That(File.Exists(same), Is.False);
        // A clip rebased in place is still allowed.
        Assert.That(CliRunner.Run("bvh", "rebase", clip, clip, "--rest", "x-along").ExitCode, Is.EqualTo(0));
    }

    [Test]
    public void AnEvaluationThatFailsOnItsLastOutputReplacesNoneOfTheOthers()
    {
        // The plot's folder does not exist: found before the evaluation now, and the JSON and the positions are kept.
        string session = Session();
        string json = Existing("old.json"), csv = Existing("old.csv");
        var r = CliRunner.Run("evaluate", session, "--hands", "calibrated", "--json", json, "--positions", csv, "--plot", Path.Combine(Dir, "missing", "p.png"));
        Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
        Assert.That(File.ReadAllText(json), Is.EqualTo("the previous old.json\n"));
        Assert.That(File.ReadAllText(csv), Is.EqualTo("the previous old.csv\n"));
        Assert.That(Directory.GetFiles(Dir).Select(Path.GetFileName).OrderBy(n => n), Is.EqualTo(new[] { "old.csv", "old.json", "s.agsession" }), "no temporary file left");
        // And all of them when the run succeeds.
        string png = Path.Combine(Dir, "p.png");
        r = CliRunner.Run("evaluate", session, "--hands", "calibrated", "--json", json, "--positions", csv, "--plot", png);
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        StringAssert.StartsWith("{", File.ReadAllText(json));
        StringAssert.StartsWith("frame,time,", File.ReadAllText(csv));
        Assert.That(new FileInfo(png).Length, Is.GreaterThan(1000));
    }

    [Test]
    public void ThePositionsFrameColumnIsTheFramesIndexWhateverTheClockStartsAt()
    {
        // A recording's frames are stamped with Unity's unscaled time, which does not start at 0: the column was
        // round(time x rate), 90360 for frame 360.
        string session = Session();
        string shifted = Path.Combine(Dir, "shifted.agsession");
        File.WriteAllLines(shifted, File.ReadAllLines(session).Select(l => l.StartsWith("frame ", StringComparison.Ordinal)
            ? "frame " + (double.Parse(l.Substring(6), CultureInfo.InvariantCulture) + 1000).ToString("R", CultureInfo.InvariantCulture) : l));
        string a = Path.Combine(Dir, "a.csv"), b = Path.Combine(Dir, "b.csv");
        Assert.That(CliRunner.Run("evaluate", session, "--hands", "calibrated", "--positions", a).ExitCode, Is.EqualTo(0));
        Assert.That(CliRunner.Run("evaluate", shifted, "--hands", "calibrated", "--positions", b).ExitCode, Is.EqualTo(0));
        string[] First(string path) => File.ReadLines(path).Skip(1).Select(l => l.Split(',')[0]).Take(3).ToArray();
        Assert.That(First(b), Is.EqualTo(First(a)));
        int first = int.Parse(First(a)[0], CultureInfo.InvariantCulture);
        Assert.That(First(a), Is.EqualTo(new[] { $"{first}", $"{first + 1}", $"{first + 2}" }), "consecutive indices");
    }

    [Test]
    public void AFolderGivenAsAnInputSaysSo()
    {
        foreach (string[] args in new[]
        {
            new[] { "session", "info", Dir }, new[] { "evaluate", Dir }, new[] { "bvh", "info", Dir },
            new[] { "simulate", "--bvh", Dir, "--out", Path.Combine(Dir, "x.agsession") },
        })
        {
            var r = CliRunner.Run(args);
            Assert.That(r.ExitCode, Is.EqualTo(1), string.Join(" ", args) + "\n" + r);
            StringAssert.Contains("is a folder, not a file", r.Stderr);
        }
    }

    [Test]
    public void EvaluateWithNoTrueJointsInTheSessionSaysThereIsNothingToCompare()
    {
        // A session with its truth lines removed, as a headset records it, evaluated with --avatar: every figure was NaN
        // with exit 0, and --json failed naming a serializer setting.
        string session = Session();
        string bare = Path.Combine(Dir, "bare.agsession");
        File.WriteAllLines(bare, File.ReadAllLines(session).Where(l => !l.StartsWith("truth", StringComparison.Ordinal)));
        string json = Existing("old.json");
        var r = CliRunner.Run("evaluate", bare, "--hands", "calibrated", "--avatar", Paths.Mocap("mocapbank_30fps.bvh"), "--json", json);
        Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
        StringAssert.Contains("nothing to compare", r.Stderr);
        Assert.That(File.ReadAllText(json), Is.EqualTo("the previous old.json\n"));
    }

    /// <summary>
    /// A session without some joints' truth (the format lets bones be absent) is evaluated, and a figure of no frames is
    /// null in the JSON (found in review: without the knees' truth the knee-angle median was NaN, and the run exited 1 with a
    /// serializer message, writing neither the JSON nor the positions).
    /// </summary>
    [Test]
    public void AFigureOfNoFramesIsNullInTheJson()
    {
        string session = Session();
        string partial = Path.Combine(Dir, "no-knees.agsession");
        File.WriteAllLines(partial, File.ReadAllLines(session).Where(l => !l.StartsWith("truth LeftLowerLeg ", StringComparison.Ordinal) && !l.StartsWith("truth RightLowerLeg ", StringComparison.Ordinal)));
        Assume.That(File.ReadAllLines(partial).Length, Is.LessThan(File.ReadAllLines(session).Length), "the knees' truth lines were there");
        string json = Path.Combine(Dir, "r.json"), csv = Path.Combine(Dir, "p.csv");
        var r = CliRunner.Run("evaluate", partial, "--hands", "calibrated", "--json", json, "--positions", csv);
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        using var doc = System.Text.Json.JsonDocument.Parse(File.ReadAllText(json));
        Assert.That(doc.RootElement.GetProperty("knee_angle_error_deg").ValueKind, Is.EqualTo(System.Text.Json.JsonValueKind.Null));
        Assert.That(doc.RootElement.GetProperty("mpjpe_mm").GetDouble(), Is.GreaterThan(0.0));
        Assert.That(File.Exists(csv), Is.True);
    }

    /// <summary>
    /// `bvh positions` quotes a header field whose joint name holds a comma or a quote (RFC 4180), so the header has as many
    /// fields as each row (found in review: `Joint,A "q"` shifted every column after it).
    /// </summary>
    [Test]
    public void APositionsHeaderQuotesNamesWithCommasAndQuotes()
    {
        string clip = Path.Combine(Dir, "odd.bvh");
        File.WriteAllText(clip, File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh")).Replace("JOINT LeftShoulder", "JOINT Left,Arm \"q\""));
        var r = CliRunner.Run("bvh", "positions", clip, "--frames", "0:2");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        string[] lines = r.Stdout.TrimEnd().Split('\n');
        using var parser = new Microsoft.VisualBasic.FileIO.TextFieldParser(new StringReader(string.Join("\n", lines))) { Delimiters = new[] { "," }, HasFieldsEnclosedInQuotes = true };
        string[] header = parser.ReadFields(), row = parser.ReadFields();
        Assert.That(header, Has.Length.EqualTo(row.Length));
        Assert.That(header, Does.Contain("Left,Arm \"q\".x"));
    }

    [Test]
    public void AProfileSavedToARootSaysItIsAFolder()
    {
        // Found in review: the store passed a null folder on and the command printed "Value cannot be null".
        var r = CliRunner.Run("calibrate", Session(), "--save", Path.GetPathRoot(Dir));
        Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
        StringAssert.Contains("is a folder", r.Stderr);
    }

    [Test]
    public void DemoLeavesAFileAtItsOldTemporaryNameAlone()
    {
        string victim = Path.Combine(Path.GetTempPath(), $"avatargo-demo-{Environment.ProcessId}.agsession");
        File.WriteAllText(victim, "someone else's file\n");
        try
        {
            var r = CliRunner.Run("demo");
            Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
            Assert.That(File.ReadAllText(victim), Is.EqualTo("someone else's file\n"));
        }
        finally { File.Delete(victim); }
    }

    [TestCase("--controller", "none"), TestCase("--exercise-seconds", "5")]
    public void DemoRefusesTheSimulationOptionsItDoesNotHonour(string option, string value)
    {
        var r = CliRunner.Run("demo", option, value);
        Assert.That(r.ExitCode, Is.EqualTo(2), r.ToString());
        StringAssert.Contains(option, r.Stderr);
    }
}
