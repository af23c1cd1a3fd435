using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using System.Threading;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// The commands that write files never lose one: issue 14's `simulate` failures (spaces in joint names, Frames: 0)
/// leave an existing output byte-identical, a writer process killed mid-write leaves the old file and a leftover the
/// next write cleans, and concurrent saves from several processes all succeed.
/// </summary>
public class FileSafetyCommandTests
{
    private string _dir;

    [SetUp]
    public void MakeFolder()
    {
        _dir = Path.Combine(Path.GetTempPath(), "avatargo-files-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void RemoveFolder()
    {
        if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
    }

    private string Existing(string name)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, "the previous " + name + ", which must survive\n");
        return path;
    }

    private string[] Files() => Directory.GetFiles(_dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToArray();

    private string Clip(string name, Func<string, string> edit)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, edit(File.ReadAllText(Paths.Mocap("mixamo_fingers_30fps.bvh"))));
        return path;
    }

    [Test]
    public void SimulateOnAClipWithSpacesInJointNamesFailsClearlyAndKeepsTheExistingOutput()
    {
        // Issue 14: "simulate on a clip with spaces in joint names aborts with an unhandled exception after truncating
        // an existing output file to 0 bytes".
        string bvh = Clip("spaced.bvh", t => t.Replace("JOINT mixamorig:Spine1", "JOINT mixamorig:Spine One"));
        string output = Existing("out.agsession");
        byte[] before = File.ReadAllBytes(output);
        var r = CliRunner.Run("simulate", "--bvh", bvh, "--out", output);
        Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
        Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1), r.Stderr);
        StringAssert.Contains("avatargo simulate: the session cannot hold this clip's skeleton: Joint name 'mixamorig:Spine One' contains white space", r.Stderr);
        Assert.That(File.ReadAllBytes(output), Is.EqualTo(before), "the existing output is byte-identical");
        Assert.That(Files(), Is.EqualTo(new[] { "out.agsession", "spaced.bvh" }), "no temporary file");
    }

    [Test]
    public void SimulateOnAClipWithoutFramesFailsClearlyAndKeepsTheExistingOutput()
    {
        // Issue 14: "Frames: 0 crashes simulate".
        string bvh = Clip("still.bvh", t => t.Substring(0, t.IndexOf("Frame Time:", StringComparison.Ordinal)).Replace("Frames: 69", "Frames: 0") + "Frame Time: 0.0333333\n");
        Assert.That(BvhReader.ReadFile(bvh).FrameCount, Is.EqualTo(0), "test setup");
        string output = Existing("out.agsession");
        byte[] before = File.ReadAllBytes(output);
        foreach (string command in new[] { "simulate", "demo" })
        {
            var r = command == "simulate" ? CliRunner.Run("simulate", "--bvh", bvh, "--out", output) : CliRunner.Run("demo", "--bvh", bvh, "--out-bvh", output);
            Assert.That(r.ExitCode, Is.EqualTo(1), r.ToString());
            Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1), r.Stderr);
            StringAssert.Contains($"avatargo {command}: still.bvh cannot be simulated: The clip has no frames", r.Stderr);
            Assert.That(File.ReadAllBytes(output), Is.EqualTo(before));
        }
        Assert.That(Files(), Is.EqualTo(new[] { "out.agsession", "still.bvh" }));
    }

    [Test]
    public void EvaluateJsonReplacesItsOutputWhole()
    {
        string session = Path.Combine(_dir, "s.agsession");
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", session, "--seed", "4").ExitCode, Is.EqualTo(0));
        string json = Existing("report.json");
        var r = CliRunner.Run("evaluate", session, "--json", json);
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        StringAssert.Contains("\"mpjpe_mm\"", File.ReadAllText(json));
        File.SetAttributes(json, FileAttributes.ReadOnly);
        byte[] before = File.ReadAllBytes(json);
        r = CliRunner.Run("evaluate", session, "--json", json);
        Assert.That(r.ExitCode, Is.EqualTo(1), "a read-only report is not replaced");
        StringAssert.Contains("read-only", r.Stderr);
        Assert.That(File.ReadAllBytes(json), Is.EqualTo(before));
        File.SetAttributes(json, FileAttributes.Normal);
        Assert.That(Files(), Is.EqualTo(new[] { "report.json", "s.agsession" }));
    }

    [Test]
    public void CommandsGivenASkeletonWithoutHumanoidBonesSayItInOneLine()
    {
        string bvh = Path.Combine(_dir, "stick.bvh");
        File.WriteAllText(bvh, "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 3 Xrotation Yrotation Zrotation\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n0 0 0\n0 0 0\n");
        string session = Path.Combine(_dir, "s.agsession");
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", session).ExitCode, Is.EqualTo(0));
        foreach (string[] args in new[]
        {
            new[] { "simulate", "--bvh", bvh, "--out", Path.Combine(_dir, "x.agsession") },
            new[] { "calibrate", session, "--avatar", bvh },
            new[] { "evaluate", session, "--avatar", bvh },
            new[] { "bench", "--bvh", bvh, "--frames", "10", "--runs", "1" },
            new[] { "fingers", "--hand", bvh, "--profile", "vive-wand" },
        })
        {
            var r = CliRunner.Run(args);
            Assert.That(r.ExitCode, Is.EqualTo(1), string.Join(" ", args) + "\n" + r);
            Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1), r.Stderr);
            StringAssert.StartsWith("avatargo " + args[0] + ": ", r.Stderr);
        }
        Assert.That(File.Exists(Path.Combine(_dir, "x.agsession")), Is.False);
    }

    /// <summary>
    /// An avatar file whose joint names say nothing (numbered) is read from its hierarchy and motion: `evaluate --avatar`
    /// with the session's own skeleton so numbered gives the figures of the session's own skeleton.
    /// </summary>
    [Test]
    public void AnAvatarFileWithNumberedJointsIsReadFromItsStructure()
    {
        string text = File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh"));
        int next = 0;
        string numbered = System.Text.RegularExpressions.Regex.Replace(text, @"^(\s*(?:ROOT|JOINT)\s+)(\S+)", m => m.Groups[1].Value + "j" + next++, System.Text.RegularExpressions.RegexOptions.Multiline);
        string avatar = Path.Combine(_dir, "numbered.bvh"), session = Path.Combine(_dir, "s.agsession");
        File.WriteAllText(avatar, numbered);
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", session).ExitCode, Is.EqualTo(0));
        string own = Path.Combine(_dir, "own.json"), other = Path.Combine(_dir, "other.json");
        var a = CliRunner.Run("evaluate", session, "--json", own);
        var b = CliRunner.Run("evaluate", session, "--avatar", avatar, "--json", other);
        Assert.That(a.ExitCode, Is.EqualTo(0), a.ToString());
        Assert.That(b.ExitCode, Is.EqualTo(0), b.ToString());
        double Mpjpe(string json) => System.Text.Json.JsonDocument.Parse(File.ReadAllText(json)).RootElement.GetProperty("mpjpe_mm").GetDouble();
        Assert.That(Mpjpe(other), Is.EqualTo(Mpjpe(own)).Within(0.01), "MPJPE (mm)");
    }

    /// <summary>
    /// `--avatar-map`: an avatar file of its rest pose alone (one frame: its knees and elbows cannot show) whose left arm's
    /// names say nothing is refused, naming the bones it lacks; with a map file giving those three joints their bones,
    /// `calibrate` calibrates and `evaluate` gives the figures of the session's own skeleton (the same skeleton). Without
    /// `--avatar` the map is a usage error (the session's skeleton was mapped when it was simulated).
    /// </summary>
    [Test]
    public void AnAvatarMapGivesTheBonesAnAvatarFilesNamesMiss()
    {
        string text = File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh"));
        string renamed = text.Replace("JOINT LeftShoulder", "JOINT Bone.010").Replace("JOINT LeftElbow", "JOINT Bone.011").Replace("JOINT LeftWrist", "JOINT Bone.012");
        // The rest pose alone: the hierarchy, then one frame of zeros.
        string[] lines = renamed.Split('\n');
        int frames = Array.FindIndex(lines, l => l.StartsWith("Frames:"));
        int channels = lines[frames + 2].Split((char[])null, StringSplitOptions.RemoveEmptyEntries).Length;
        string restOnly = string.Join("\n", lines.Take(frames)) + "\nFrames: 1\n" + lines[frames + 1] + "\n" + string.Join(" ", Enumerable.Repeat("0", channels)) + "\n";
        string avatar = Path.Combine(_dir, "rest.bvh"), map = Path.Combine(_dir, "map.txt"), session = Path.Combine(_dir, "s.agsession");
        File.WriteAllText(avatar, restOnly);
        File.WriteAllText(map, "Bone.010 = LeftUpperArm\nBone.011 = LeftLowerArm\nBone.012 = LeftHand\n");
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", session).ExitCode, Is.EqualTo(0));

        var refused = CliRunner.Run("evaluate", session, "--avatar", avatar);
        Assert.That(refused.ExitCode, Is.EqualTo(1), refused.ToString());
        StringAssert.Contains("its skeleton lacks LeftUpperArm, LeftLowerArm, LeftHand", refused.Stderr);
        StringAssert.Contains("--avatar-map FILE", refused.Stderr);

        var calibrated = CliRunner.Run("calibrate", session, "--avatar", avatar, "--avatar-map", map);
        Assert.That(calibrated.ExitCode, Is.EqualTo(0), calibrated.ToString());
        StringAssert.StartsWith("status: calibrated", calibrated.Stdout);
        string own = Path.Combine(_dir, "own.json"), mapped = Path.Combine(_dir, "mapped.json");
        var a = CliRunner.Run("evaluate", session, "--json", own);
        var b = CliRunner.Run("evaluate", session, "--avatar", avatar, "--avatar-map", map, "--json", mapped);
        Assert.That(a.ExitCode, Is.EqualTo(0), a.ToString());
        Assert.That(b.ExitCode, Is.EqualTo(0), b.ToString());
        double Mpjpe(string json) => System.Text.Json.JsonDocument.Parse(File.ReadAllText(json)).RootElement.GetProperty("mpjpe_mm").GetDouble();
        Assert.That(Mpjpe(mapped), Is.EqualTo(Mpjpe(own)).Within(0.01), "MPJPE (mm)");

        var noAvatar = CliRunner.Run("evaluate", session, "--avatar-map", map);
        Assert.That(noAvatar.ExitCode, Is.EqualTo(2), noAvatar.ToString());
        StringAssert.Contains("--avatar-map needs --avatar", noAvatar.Stderr);
    }

    // ---- Child processes -------------------------------------------------------------------------------

    private static Process StartCli(params string[] args)
    {
        string dll = typeof(AvatarGo.Cli.Program).Assembly.Location;
        var info = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        info.ArgumentList.Add(dll);
        foreach (string a in args) info.ArgumentList.Add(a);
        return Process.Start(info);
    }

    [Test]
    public void AWriterKilledMidWriteLeavesTheOldFileAndTheNextWriteCleansItsLeftover()
    {
        string output = Existing("big.agsession");
        byte[] before = File.ReadAllBytes(output);
        // A long session (1 kHz) so that it is still being written when it is killed.
        using Process child = StartCli("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", output, "--rate", "1000");
        string leftover = null;
        var clock = Stopwatch.StartNew();
        while (clock.Elapsed < TimeSpan.FromSeconds(60) && !child.HasExited)
        {
            leftover = Directory.GetFiles(_dir, ".big.agsession.*.tmp").FirstOrDefault();
            if (leftover != null && new FileInfo(leftover).Length > (1 << 20)) break; // a megabyte in: mid-write
            Thread.Sleep(10);
        }
        Assert.That(child.HasExited, Is.False, "the child was still writing");
        child.Kill(entireProcessTree: true);
        child.WaitForExit();
        Assert.That(leftover, Is.Not.Null);
        StringAssert.Contains("." + child.Id + "-", Path.GetFileName(leftover), "the temporary file names its writer's process");
        Assert.That(File.Exists(leftover), Is.True, "a killed process cannot clean up");
        Assert.That(File.ReadAllBytes(output), Is.EqualTo(before), "the old file is byte-identical");

        // The next write of the same file deletes the dead writer's leftover.
        var r = CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", output);
        Assert.That(r.ExitCode, Is.EqualTo(0), r.ToString());
        Assert.That(File.Exists(leftover), Is.False, "the stale temporary file is gone");
        Assert.That(Files(), Is.EqualTo(new[] { "big.agsession" }));
        using SessionReader reader = SessionReader.Open(output);
        Assert.That(reader.Header.Devices.Count, Is.EqualTo(6));
    }

    [Test]
    public void ConcurrentSavesOfOneProfileFromSeveralProcessesAllSucceed()
    {
        string session = Path.Combine(_dir, "s.agsession");
        Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", session, "--seed", "9").ExitCode, Is.EqualTo(0));
        string profile = Path.Combine(_dir, "wearer.json"); // does not exist yet: first saves race
        Process[] children = Enumerable.Range(0, 4).Select(_ => StartCli("calibrate", session, "--save", profile)).ToArray();
        foreach (Process child in children)
        {
            string stdout = child.StandardOutput.ReadToEnd(), stderr = child.StandardError.ReadToEnd();
            child.WaitForExit();
            Assert.That(child.ExitCode, Is.EqualTo(0), stdout + stderr);
            StringAssert.Contains("profile saved to", stdout);
            child.Dispose();
        }
        Assert.That(CalibrationProfileStore.Load(profile).DeviceId(DeviceRole.LeftFoot), Is.EqualTo(3));
        Assert.That(Files(), Is.EqualTo(new[] { "s.agsession", "wearer.json" }), "no temporary file");
    }

    [Test]
    public void ProcessIdsInTemporaryNamesAreThoseOfTheWriters()
    {
        // What the cleaning relies on: this process's id in its own temporary files.
        string path = Path.Combine(_dir, "x.json");
        using var writer = new AtomicFileWriter(path);
        Assert.That(Regex.IsMatch(Path.GetFileName(writer.TemporaryPath), $"^\\.x\\.json\\.{Environment.ProcessId}-[0-9a-f]{{32}}\\.tmp$"), Is.True, writer.TemporaryPath);
    }
}
