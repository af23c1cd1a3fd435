using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo demo`: the headless demo of the whole pipeline on a real mocap clip.</summary>
public sealed class DemoCommand : ICommand
{
    public string Name => "demo";
    public string Summary => "Headless demo: simulate a real mocap clip, calibrate, solve, compare exact vs fixed offsets";
    public string Help => """
        avatargo demo [--bvh FILE] [--out-bvh FILE] [simulate options]

        Turns a real mocap clip (default: the bundled mocapbank_30fps.bvh) into a synthetic VR session
        with six virtual devices, then runs the paper's calibration (T-pose identification and
        scaling, walk-in, exact offsets) and the per-frame body solve twice, with exact offsets and with
        the fixed-offset baseline, and prints how closely the avatar follows the wearer's true joints.
          --bvh FILE       the clip to use
          --out-bvh FILE   also write the solved avatar (exact offsets) as BVH, to look at in Blender/Unity
          --seed N, --noise-mm MM, --noise-deg DEG, --misalign-mm MM, --misalign-deg DEG, --rate HZ,
          --map FILE, --keep-up, --keep-sides, --units U
                           as for 'avatargo simulate'
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, SimulateCommand.OptionFlags);
        string bvh = a.String("bvh") ?? DemoCommandPaths.BundledClip();
        string outBvh = a.String("out-bvh");
        // Read by the simulation options, not demo's: its figures are those of evaluate's defaults without a controller,
        // and it scores every frame after calibration (an exercise would be scored).
        foreach (string option in new[] { "controller", "exercise-seconds" })
            if (a.String(option) != null) throw new UsageException($"demo does not take --{option} (simulate and evaluate do)");
        SimulationOptions options = SimulateCommand.Options(a);
        string mapPath = a.String("map");
        BvhReadOptions read = SimulateCommand.ReadOptions(a);
        a.ThrowOnUnknown(0);
        OutputFiles.RefuseClashes(new[] { ("--bvh", bvh), ("--map", mapPath) }, new[] { ("--out-bvh", outBvh) });

        BvhClip clip = BvhReader.ReadFile(bvh, read);
        SessionSimulator simulator;
        string note = null;
        HumanoidMap map = null;
        try
        {
            map = BoneMapFile.Detect(clip, mapPath, out note);
            simulator = new SessionSimulator(clip, options, map);
        }
        catch (ArgumentException e)
        {
            stderr.WriteLine($"avatargo demo: {Path.GetFileName(bvh)} cannot be simulated: {e.Message.Split(" (Parameter '")[0].TrimEnd('.')}{SimulateCommand.MissingNote(map, note)}");
            return 1;
        }
        var progress = new ProgressBar(stderr);
        string session = SimulateCommand.SimulateToText(simulator, stderr, "demo", p => progress.Report("simulating", p / 3));
        if (session == null) return 1;

        var solved = new List<RigidPose[]>();
        EvaluationReport exact, fixedOffsets;
        using (var reader = new SessionReader(new StringReader(session), "demo session"))
            exact = SessionEvaluator.Evaluate(reader, new PipelineSettings { Offsets = OffsetMode.Exact }, null,
                outBvh == null ? null : pipeline => solved.Add((RigidPose[])pipeline.Pose.Local.Clone()));
        progress.Report("solving", 2f / 3);
        using (var reader = new SessionReader(new StringReader(session), "demo session"))
            fixedOffsets = SessionEvaluator.Evaluate(reader, OffsetMode.Fixed);
        progress.Report("done", 1f);
        progress.Finish();

        if (exact.Profile == null)
        {
            stderr.WriteLine($"avatargo demo: calibration did not complete: {exact.CalibrationMessage}");
            return 1;
        }
        PrintTable(stdout, Path.GetFileName(bvh), clip, simulator.FrameCount, options, exact, fixedOffsets);
        SimulateCommand.PrintClipNotes(simulator, stdout);
        if (note != null) stdout.WriteLine(note);
        if (outBvh != null)
        {
            Skeleton wearer = simulator.Wearer.Skeleton; // the clip's, mirrored when the simulator mirrored it
            BvhWriter.WriteFile(outBvh, BvhClip.FromPoses(exact.Profile != null ? wearer.Scaled(exact.Profile.AvatarScale) : wearer, solved, 1f / options.Rate, 0.01f));
            stdout.WriteLine($"solved avatar written to {outBvh} (centimetres, {solved.Count} frames)");
        }
        return 0;
    }

    private static void PrintTable(TextWriter o, string name, BvhClip clip, int frames, SimulationOptions options, EvaluationReport exact, EvaluationReport fixedOffsets)
    {
        var inv = CultureInfo.InvariantCulture;
        o.WriteLine(string.Create(inv, $"AvatarGo headless demo: {name} ({clip.FrameCount} frames at {clip.FrameRate:0.#} Hz) worn as a {frames}-frame {options.Rate:0} Hz session"));
        o.WriteLine(string.Create(inv, $"devices: HMD, 2 controllers, 3 trackers; random mounting (seed {options.Seed}); noise {options.PositionNoise * 1000:0.#} mm / {options.RotationNoiseDegrees:0.##} deg"));
        o.WriteLine(string.Create(inv, $"calibration: scale {exact.Profile.AvatarScale:0.0000}, wearer eye height {exact.Profile.WearerEyeHeight:0.000} m; {exact.Frames} frames compared with the true joints"));
        o.WriteLine();
        o.WriteLine("error (median / p95)          exact offsets      fixed offsets");
        Row(o, "end effectors (mm)", exact.EndEffectorMm, fixedOffsets.EndEffectorMm);
        Row(o, "elbows & knees (mm)", exact.MidJointMm, fixedOffsets.MidJointMm);
        Row(o, "all joints (mm)", exact.AllJointsMm, fixedOffsets.AllJointsMm);
        Row(o, "knee angle (deg)", exact.KneeAngleDegrees, fixedOffsets.KneeAngleDegrees);
        o.WriteLine(string.Create(inv, $"{"MPJPE (mm)",-26} {exact.AllJointsMm.Mean,10:0.0}         {fixedOffsets.AllJointsMm.Mean,10:0.0}"));
        double ratio = fixedOffsets.EndEffectorMm.Median / Math.Max(exact.EndEffectorMm.Median, 1e-9);
        o.WriteLine();
        o.WriteLine(string.Create(inv, $"exact offsets put the end effectors {ratio:0.#}x closer to the wearer's joints than fixed offsets."));
    }

    private static void Row(TextWriter o, string name, ErrorSeries exact, ErrorSeries fixedOffsets) =>
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{name,-26} {exact.Median,6:0.0} / {exact.P95,-6:0.0}     {fixedOffsets.Median,6:0.0} / {fixedOffsets.P95,-6:0.0}"));

    /// <summary>A one-line progress bar on standard error (only when it is a terminal).</summary>
    private sealed class ProgressBar
    {
        private readonly TextWriter _err;
        private readonly bool _live;

        public ProgressBar(TextWriter err)
        {
            _err = err;
            _live = ReferenceEquals(err, Console.Error) && !Console.IsErrorRedirected;
        }

        public void Report(string stage, float fraction)
        {
            if (!_live) return;
            int filled = (int)Math.Round(Math.Clamp(fraction, 0f, 1f) * 30);
            _err.Write($"\r[{new string('#', filled)}{new string('.', 30 - filled)}] {fraction * 100,3:0}% {stage,-12}");
        }

        public void Finish()
        {
            if (_live) _err.Write("\r" + new string(' ', 60) + "\r");
        }
    }
}

/// <summary>Where the tool finds the clip it bundles.</summary>
internal static class DemoCommandPaths
{
    /// <summary>A clip shipped next to the tool (from Tests/Core/Data~, copied to the output folder's data/).</summary>
    public static string BundledClip(string name = "mocapbank_30fps.bvh")
    {
        string path = Path.Combine(AppContext.BaseDirectory, "data", name);
        if (File.Exists(path)) return path;
        throw new FileNotFoundException($"the bundled clip data/{name} is missing next to the tool; pass --bvh FILE");
    }
}
