using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text.Json;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo bench`: per-frame cost of the body solve, in nanoseconds and bytes.</summary>
public sealed class BenchCommand : ICommand
{
    public string Name => "bench";
    public string Summary => "Time the per-frame body solve (ns/frame, bytes allocated/frame)";
    public string Help => """
        avatargo bench [--json] [--runs N] [--frames N] [--bvh FILE]

        Simulates a real mocap clip (default: the bundled one), calibrates, then times the per-frame
        work on every frame of the motion: the body solver (device poses -> targets) and the full-body
        IK (targets -> posed skeleton), alone and together. Reports nanoseconds per frame (median over
        N runs, with min and max) and bytes allocated per frame on this thread (must be 0), and the
        machine. Run it in Release: dotnet run --project Tools~/AvatarGo.Cli -c Release -- bench
          --runs N   timed runs per case (default 15)
          --frames N time only the first N frames of the motion (default: all)
          --json     print JSON instead of a table
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "json");
        bool json = a.Flag("json");
        int runs = a.Int("runs", 15);
        string bvh = a.String("bvh");
        int frames = a.Int("frames", int.MaxValue);
        a.ThrowOnUnknown(0);
        if (runs < 1) throw new UsageException("--runs must be at least 1");
        if (frames < 1) throw new UsageException("--frames must be at least 1");

        var fixture = BenchFixture.Create(bvh ?? DemoCommandPaths.BundledClip(), frames);
        var results = new List<BenchResult>
        {
            Measure("body solver (devices -> targets)", fixture, runs, f => f.SolveTargets()),
            Measure("full-body IK (targets -> pose)", fixture, runs, f => f.SolveIk()),
            Measure("body solve total (solver + IK)", fixture, runs, f => f.SolveBoth()),
        };
        var machine = Machine();
        if (json)
        {
            stdout.WriteLine(JsonSerializer.Serialize(new
            {
                machine,
                frames = fixture.Frames,
                runs,
                cases = results.Select(r => new { name = r.Name, ns_per_frame_median = r.Median, ns_per_frame_min = r.Min, ns_per_frame_max = r.Max, bytes_per_frame = r.BytesPerFrame }),
            }, new JsonSerializerOptions { WriteIndented = true }));
            return 0;
        }
        stdout.WriteLine($"machine: {machine["cpu"]}, {machine["cores"]} cores, {machine["os"]}, .NET {machine["dotnet"]}, {machine["configuration"]}");
        stdout.WriteLine($"motion: {Path.GetFileName(fixture.Clip)} as {fixture.Frames} frames at 90 Hz, avatar of {fixture.Joints} joints; {runs} runs per case");
        stdout.WriteLine("case                                 median ns/frame   min     max   bytes/frame");
        foreach (var r in results)
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{r.Name,-36} {r.Median,10:0} {r.Min,9:0} {r.Max,7:0} {r.BytesPerFrame,9:0.###}"));
        return 0;
    }

    private sealed record BenchResult(string Name, double Median, double Min, double Max, double BytesPerFrame);

    private static BenchResult Measure(string name, BenchFixture f, int runs, Action<BenchFixture> solveAll)
    {
        // Warm up for a second: .NET compiles hot methods again, optimised, only after they have run for a while
        // (tiered compilation), and a short clip would otherwise be timed in its first, unoptimised tier.
        var warm = Stopwatch.StartNew();
        do { solveAll(f); System.Threading.Thread.Sleep(1); } while (warm.ElapsedMilliseconds < 1000);
        var times = new double[runs];
        long bytes = 0;
        for (int r = 0; r < runs; r++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            long t0 = Stopwatch.GetTimestamp();
            solveAll(f);
            long t1 = Stopwatch.GetTimestamp();
            bytes += GC.GetAllocatedBytesForCurrentThread() - before;
            times[r] = (t1 - t0) * 1e9 / Stopwatch.Frequency / f.Frames;
        }
        Array.Sort(times);
        return new BenchResult(name, times[runs / 2], times[0], times[^1], bytes / (double)runs / f.Frames);
    }

    internal static Dictionary<string, string> Machine()
    {
        string cpu = "unknown";
        try
        {
            string line = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name", StringComparison.Ordinal));
            if (line != null) cpu = line.Substring(line.IndexOf(':') + 1).Trim();
        }
        catch (IOException) { }
        catch (UnauthorizedAccessException) { }
        return new Dictionary<string, string>
        {
            ["cpu"] = cpu,
            ["cores"] = Environment.ProcessorCount.ToString(CultureInfo.InvariantCulture),
            ["os"] = RuntimeInformation.OSDescription,
            ["dotnet"] = Environment.Version.ToString(),
#if DEBUG
            ["configuration"] = "Debug (numbers not meaningful)",
#else
            ["configuration"] = "Release",
#endif
        };
    }
}

/// <summary>A calibrated solver and the device samples of a whole motion, ready to be timed.</summary>
internal sealed class BenchFixture
{
    private DeviceSample[][] _samples;
    private BodyTargets[] _targets;
    private BodyTargetMapper _solver;
    private FullBodyIk _ik;
    private SkeletonPose _pose;
    private BodyTargets _scratch;

    public string Clip { get; private set; }
    public int Frames => _samples.Length;
    public int Joints => _pose.Skeleton.JointCount;

    public static BenchFixture Create(string clipPath, int maxFrames = int.MaxValue)
    {
        BvhClip clip = BvhReader.ReadFile(clipPath, new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 1 });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        using var reader = new SessionReader(new StringReader(text.ToString()), "bench");
        var calibrator = new Calibrator(reader.Header.Devices, reader.Header.TruthHumanoid);
        var frame = reader.CreateFrame();
        var samples = new List<DeviceSample[]>();
        while (reader.ReadFrame(frame))
        {
            if (calibrator.State != CalibrationState.Calibrated) { calibrator.Update(frame.Time, frame.Samples, frame.Events); continue; }
            if (samples.Count < maxFrames) samples.Add((DeviceSample[])frame.Samples.Clone());
        }
        if (calibrator.State != CalibrationState.Calibrated) throw new InvalidDataException("calibration did not complete: " + calibrator.LastStep.Message);
        var f = new BenchFixture
        {
            Clip = clipPath,
            _samples = samples.ToArray(),
            _solver = new BodyTargetMapper(calibrator.Profile, reader.Header.Devices, calibrator.ScaledAvatar, calibrator.AvatarPose),
            _ik = new FullBodyIk(calibrator.ScaledAvatar, calibrator.AvatarPose),
            _pose = new SkeletonPose(calibrator.ScaledAvatar.Skeleton),
        };
        f._pose.CopyFrom(calibrator.AvatarPose);
        f._targets = new BodyTargets[f._samples.Length];
        for (int i = 0; i < f._samples.Length; i++) f._solver.Compute(f._samples[i], ref f._targets[i]);
        return f;
    }

    public void SolveTargets()
    {
        for (int i = 0; i < _samples.Length; i++) _solver.Compute(_samples[i], ref _scratch);
    }

    public void SolveIk()
    {
        for (int i = 0; i < _targets.Length; i++) _ik.Solve(in _targets[i], _pose);
    }

    public void SolveBoth()
    {
        for (int i = 0; i < _samples.Length; i++)
        {
            _solver.Compute(_samples[i], ref _scratch);
            _ik.Solve(in _scratch, _pose);
        }
    }
}
