using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Text.Json;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo bench`: per-frame cost of the whole pipeline and of its parts, in nanoseconds and bytes.</summary>
public sealed class BenchCommand : ICommand
{
    /// <summary>A 90 Hz frame, in nanoseconds: the budget of everything an application does in it.</summary>
    private const double FrameNs90Hz = 1e9 / 90.0;

    public string Name => "bench";
    public string Summary => "Time the whole pipeline per frame (body + both hands' fingers) and its parts (ns/frame, bytes/frame)";
    public string Help => """
        avatargo bench [--json] [--runs N] [--frames N] [--bvh FILE] [--controller NAME] [--warmup S]
        avatargo bench --calibration [--runs N] [--bvh FILE] [--controller NAME] [--warmup S]

        Simulates a real mocap clip as a 90 Hz session (default: the bundled Mixamo clip, whose avatar has
        finger bones), calibrates it through the pipeline, then times the per-frame work on every frame of
        the motion, played forward and back with the clock running on (so that one run continues the last
        without a jump): the whole pipeline (SelfAvatarPipeline.Update: targets, body IK, hands on the
        controllers, both hands' finger IK) as the headline case; the body alone (the same pipeline
        without finger IK); both hands' fingers alone (FingerSolver on the poses the pipeline produced,
        where a hand that follows its controller keeps its grip without a descent), and again with each
        wrist moved 2.5 micrometres in its controller every other frame, so that every frame descends (the
        worst case: a hand sliding in its controller, an arm out of reach); and the body's two stages (devices -> targets, targets -> posed skeleton). Reports nanoseconds per
        frame (median over N runs, with min and max), bytes allocated per frame on this thread (must be 0),
        how many avatars one core could solve in a 90 Hz frame, and the machine. Run it in Release:
        dotnet run --project Tools~/AvatarGo.Cli -c Release -- bench
          --runs N          timed runs per case (default 15)
          --frames N        time only the first N frames of the motion (default: all)
          --controller NAME the controller in both hands (default vive-wand)
          --warmup S        seconds of warm-up per case, for .NET's tiered JIT (default 1)
          --json            print JSON instead of a table
          --calibration     time the calibration's two trigger presses instead (the frame that handles each,
                            from a fresh pipeline, uniform and fitted, avatar legs +10 % / arms -10 %) and
                            one ProportionFitter.Fit alone; milliseconds, median with min and max over N runs
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "json", "calibration");
        bool json = a.Flag("json");
        bool calibration = a.Flag("calibration");
        int runs = a.Int("runs", 15);
        string bvh = a.String("bvh");
        bool framesGiven = a.String("frames") != null;
        int frames = a.Int("frames", int.MaxValue);
        double warmup = a.Double("warmup", 1);
        ControllerProfile controller = ControllerProfiles.Named(a.String("controller", ControllerProfiles.Default))
            ?? throw new UsageException("bench needs a controller profile (the fingers are part of the pipeline)");
        a.ThrowOnUnknown(0);
        if (runs < 1) throw new UsageException("--runs must be at least 1");
        if (frames < 1) throw new UsageException("--frames must be at least 1");
        if (!(warmup >= 0 && warmup <= 60)) throw new UsageException("--warmup must be between 0 and 60 seconds");

        if (calibration && (json || framesGiven)) throw new UsageException("--json and --frames do not go with --calibration");
        if (calibration) return RunCalibration(bvh, runs, warmup, controller, stdout);
        var fixture = BenchFixture.Create(bvh ?? DemoCommandPaths.BundledClip("mixamo_fingers_30fps.bvh"), frames, controller);
        var warm = TimeSpan.FromSeconds(warmup);
        var results = new List<BenchResult>
        {
            Measure(fixture.HasFingers ? "whole pipeline (body + both hands' fingers)" : "whole pipeline (this avatar has no finger bones)", fixture, runs, warm, f => f.RunPipeline()),
            Measure("body only (pipeline without finger IK)", fixture, runs, warm, f => f.RunBodyOnly()),
        };
        if (fixture.HasFingers)
        {
            results.Add(Measure("fingers only (both hands)", fixture, runs, warm, f => f.RunFingers()));
            results.Add(Measure("  fingers, descended every frame", fixture, runs, warm, f => f.RunFingersMoving()));
        }
        results.Add(Measure("  body: devices -> targets", fixture, runs, warm, f => f.RunTargets()));
        results.Add(Measure("  body: targets -> posed skeleton (IK)", fixture, runs, warm, f => f.RunIk()));
        double avatars = Math.Floor(FrameNs90Hz / results[0].Median);
        var machine = Machine();
        if (json)
        {
            stdout.WriteLine(JsonReports.Serialize(new
            {
                machine,
                clip = Path.GetFileName(fixture.Clip),
                controller = controller.Name,
                frames = fixture.MotionFrames,
                frames_per_pass = fixture.Frames,
                joints = fixture.Joints,
                runs,
                avatars_per_core_at_90hz = avatars,
                cases = results.Select(r => new { name = r.Name.Trim(), ns_per_frame_median = r.Median, ns_per_frame_min = r.Min, ns_per_frame_max = r.Max, bytes_per_frame = r.BytesPerFrame }),
            }));
            return 0;
        }
        stdout.WriteLine($"machine: {machine["cpu"]}, {machine["cores"]} cores, {machine["os"]}, .NET {machine["dotnet"]}, {machine["configuration"]}");
        stdout.WriteLine($"motion: {Path.GetFileName(fixture.Clip)} as {fixture.MotionFrames} frames at 90 Hz played forward and back ({fixture.Frames} a pass), avatar of {fixture.Joints} joints, {controller.Name} in both hands; {runs} runs per case");
        stdout.WriteLine("case                                          median ns/frame   min     max   bytes/frame");
        foreach (var r in results)
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{r.Name,-45} {r.Median,10:0} {r.Min,9:0} {r.Max,7:0} {r.BytesPerFrame,9:0.###}"));
        stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"one core could solve {avatars:0} avatars in a 90 Hz frame (11.1 ms) doing nothing else"));
        return 0;
    }

    private static int RunCalibration(string bvh, int runs, double warmup, ControllerProfile controller, TextWriter stdout)
    {
        string clip = bvh ?? DemoCommandPaths.BundledClip("mixamo_fingers_30fps.bvh");
        var bench = CalibrationBench.Create(clip, controller, 1.1f, 0.9f);
        var machine = Machine();
        stdout.WriteLine($"machine: {machine["cpu"]}, {machine["cores"]} cores, {machine["os"]}, .NET {machine["dotnet"]}, {machine["configuration"]}");
        stdout.WriteLine($"load average: {LoadAverage()}");
        stdout.WriteLine($"calibration of {Path.GetFileName(clip)} (avatar of {bench.Joints} joints, legs +10 %, arms -10 %), {controller.Name}; {runs} runs per case");
        stdout.WriteLine("case                                          median ms     min      max    first   KiB (median run)");
        // Fitted first: its "first" column is then the first calibration of the process (JIT included).
        foreach (ScaleMode mode in new[] { ScaleMode.Fitted, ScaleMode.Uniform })
        {
            double first1 = double.NaN, first2 = double.NaN;
            var t1 = new double[runs];
            var t2 = new double[runs];
            long b1 = 0, b2 = 0;
            var warm = Stopwatch.StartNew();
            for (int r = -1; r < runs; r++)
            {
                var (a1, a2, k1, k2) = bench.Run(mode, controller);
                if (r < 0)
                {
                    first1 = a1; first2 = a2; // the first press of the process: JIT included, as in a headset's first calibration
                    while (warm.Elapsed.TotalSeconds < warmup) bench.Run(mode, controller);
                    continue;
                }
                t1[r] = a1; t2[r] = a2; b1 = k1; b2 = k2;
            }
            Array.Sort(t1);
            Array.Sort(t2);
            string name = mode.ToString().ToLowerInvariant();
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name + ": T-pose press",-45} {t1[runs / 2],9:0.00} {t1[0],8:0.00} {t1[^1],8:0.00} {first1,8:0.00} {b1 / 1024.0,10:0}"));
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name + ": walk-in press (with solver setup)",-45} {t2[runs / 2],9:0.00} {t2[0],8:0.00} {t2[^1],8:0.00} {first2,8:0.00} {b2 / 1024.0,10:0}"));
        }
        foreach (ScaleMode mode in new[] { ScaleMode.Uniform, ScaleMode.Fitted })
        {
            var t = new double[runs];
            for (int r = 0; r < runs; r++) t[r] = bench.FitOnce(mode);
            Array.Sort(t);
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{"ProportionFitter.Fit alone, " + mode.ToString().ToLowerInvariant(),-45} {t[runs / 2],9:0.00} {t[0],8:0.00} {t[^1],8:0.00}"));
        }
        return 0;
    }

    private static string LoadAverage()
    {
        try { return File.ReadAllText("/proc/loadavg").Trim(); }
        catch (IOException) { return "unknown"; }
        catch (UnauthorizedAccessException) { return "unknown"; }
    }

    private sealed record BenchResult(string Name, double Median, double Min, double Max, double BytesPerFrame);

    private static BenchResult Measure(string name, BenchFixture f, int runs, TimeSpan warmup, Action<BenchFixture> solveAll)
    {
        // Warm up: .NET compiles hot methods again, optimised, only after they have run for a while (tiered
        // compilation), and a short clip would otherwise be timed in its first, unoptimised tier.
        var warm = Stopwatch.StartNew();
        do { solveAll(f); System.Threading.Thread.Sleep(1); } while (warm.Elapsed < warmup);
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

/// <summary>Calibrated pipelines and the device samples of a whole motion, ready to be timed.</summary>
internal sealed class BenchFixture
{
    private DeviceSample[][] _samples;
    private double[] _times;
    private SelfAvatarPipeline _pipeline, _bodyOnly;
    private BodyTargetMapper _mapper;
    private FullBodyIk _ik;
    private SkeletonPose _pose;
    private BodyTargets[] _targets;
    private BodyTargets _scratch;
    private readonly FingerSolver[] _fingers = new FingerSolver[2];
    private RigidPose[][] _wrists, _controllers, _movedWrists;

    public string Clip { get; private set; }
    public int Frames => _samples.Length;
    public int MotionFrames { get; private set; }
    private double _passSeconds, _pipelineOffset, _bodyOnlyOffset;
    public int Joints => _pose.Skeleton.JointCount;
    public bool HasFingers => _fingers[0] != null && _fingers[1] != null;

    public static BenchFixture Create(string clipPath, int maxFrames, ControllerProfile controller)
    {
        BvhClip clip = BvhReader.ReadFile(clipPath, new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 1, Controller = controller });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        using var reader = new SessionReader(new StringReader(text.ToString()), "bench");
        var withFingers = new PipelineSettings();
        withFingers.LeftHand.Controller = withFingers.RightHand.Controller = controller;
        var f = new BenchFixture
        {
            Clip = clipPath,
            _pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid, withFingers),
            _bodyOnly = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid),
        };
        var frame = reader.CreateFrame();
        var samples = new List<DeviceSample[]>();
        var times = new List<double>();
        while (reader.ReadFrame(frame))
        {
            if (f._pipeline.State != CalibrationState.Calibrated)
            {
                f._pipeline.Update(frame);
                f._bodyOnly.Update(frame);
                continue;
            }
            if (samples.Count >= maxFrames) continue;
            samples.Add((DeviceSample[])frame.Samples.Clone());
            times.Add(frame.Time);
        }
        if (f._pipeline.State != CalibrationState.Calibrated) throw new InvalidDataException("calibration did not complete: " + f._pipeline.LastCalibrationStep.Message);
        // Played forward and back, the clock running on: every pass continues the last without a jump. (Replayed from its
        // start, each pass began with every device jumping back to the clip's first pose and the clock going back, so the
        // whole pipeline timed the glitch filter rejecting them and half a second of lost devices on every pass.)
        f.MotionFrames = samples.Count;
        for (int i = samples.Count - 2; i >= 1; i--) samples.Add(samples[i]);
        double step = 1.0 / 90.0;
        for (int i = times.Count; i < samples.Count; i++) times.Add(times[0] + i * step);
        f._samples = samples.ToArray();
        f._times = times.ToArray();
        f._passSeconds = f._samples.Length * step;

        // The body's stages on their own, from the same calibration.
        HumanoidMap scaled = f._pipeline.ScaledAvatar;
        f._mapper = new BodyTargetMapper(f._pipeline.ActiveProfile, reader.Header.Devices, scaled, f._pipeline.Pose);
        f._ik = new FullBodyIk(scaled, f._pipeline.Pose);
        f._pose = new SkeletonPose(scaled.Skeleton);
        f._pose.CopyFrom(f._pipeline.Pose);
        f._targets = new BodyTargets[f.Frames];
        for (int i = 0; i < f.Frames; i++) f._mapper.Compute(f._samples[i], ref f._targets[i]);

        // The fingers on their own: the wrist and controller poses the whole pipeline produced, frame by frame.
        f._wrists = new[] { new RigidPose[f.Frames], new RigidPose[f.Frames] };
        f._controllers = new[] { new RigidPose[f.Frames], new RigidPose[f.Frames] };
        foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            if (f._pipeline.Hand(side).HasFingerIk) f._fingers[(int)side] = new FingerSolver(new HandModel(scaled, side, f._pipeline.Pose), controller);
        int leftHand = scaled[HumanoidBone.LeftHand], rightHand = scaled[HumanoidBone.RightHand];
        for (int i = 0; i < f.Frames; i++)
        {
            f._pipeline.Update(f._times[i], f._samples[i], default, default, null);
            f._wrists[0][i] = f._pipeline.Pose.World[leftHand];
            f._wrists[1][i] = f._pipeline.Pose.World[rightHand];
            f._controllers[0][i] = f._pipeline.Hand(BodySide.Left).ControllerPose;
            f._controllers[1][i] = f._pipeline.Hand(BodySide.Right).ControllerPose;
        }
        // Every other frame's wrist moved by more than FingerSolver.ResolveDistance in its own frame, so that no frame
        // keeps the grip of the one before.
        var moved = new RigidPose(new Vector3(2.5f * FingerSolver.ResolveDistance, 0f, 0f), Quaternion.Identity);
        f._movedWrists = new[] { new RigidPose[f.Frames], new RigidPose[f.Frames] };
        for (int s = 0; s < 2; s++)
            for (int i = 0; i < f.Frames; i++)
                f._movedWrists[s][i] = i % 2 == 0 ? f._wrists[s][i] : f._wrists[s][i] * moved;
        return f;
    }

    public void RunPipeline()
    {
        _pipelineOffset += _passSeconds;
        for (int i = 0; i < _samples.Length; i++) _pipeline.Update(_pipelineOffset + _times[i], _samples[i], default, default, null);
    }

    public void RunBodyOnly()
    {
        _bodyOnlyOffset += _passSeconds;
        for (int i = 0; i < _samples.Length; i++) _bodyOnly.Update(_bodyOnlyOffset + _times[i], _samples[i], default, default, null);
    }

    public void RunFingers()
    {
        if (!HasFingers) return;
        for (int i = 0; i < _samples.Length; i++)
        {
            _fingers[0].Solve(_wrists[0][i], _controllers[0][i], GripMode.Hold);
            _fingers[1].Solve(_wrists[1][i], _controllers[1][i], GripMode.Hold);
        }
    }

    public void RunFingersMoving()
    {
        if (!HasFingers) return;
        for (int i = 0; i < _samples.Length; i++)
        {
            _fingers[0].Solve(_movedWrists[0][i], _controllers[0][i], GripMode.Hold);
            _fingers[1].Solve(_movedWrists[1][i], _controllers[1][i], GripMode.Hold);
        }
    }

    public void RunTargets()
    {
        for (int i = 0; i < _samples.Length; i++) _mapper.Compute(_samples[i], ref _scratch);
    }

    public void RunIk()
    {
        for (int i = 0; i < _targets.Length; i++) _ik.Solve(in _targets[i], _pose, 1f / 90f); // per frame, as the pipeline solves: the held shrugs included
    }
}
