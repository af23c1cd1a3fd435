using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli;

/// <summary>
/// A long run of the pipeline at 90 Hz: a recorded motion played forward and back (so it never jumps) for as long as
/// asked, one device after another lost for a while at a regular interval. Measures what only a long run shows: bytes
/// allocated per frame (counted around every Update), managed memory after warm-up and at the end, and the end effectors'
/// error in the first and the last minute.
/// </summary>
internal sealed class SoakRun
{
    public sealed record Result(long Frames, double Minutes, long BytesAllocated, long MemoryAfterWarmUp, long MemoryAtEnd,
        double FirstMinuteMedianMm, double FirstMinuteP95Mm, double LastMinuteMedianMm, double LastMinuteP95Mm, int NonFiniteFrames, double SolveSeconds);

    private readonly List<DeviceSample[]> _samples = new();
    private readonly List<RigidPose[]> _truth = new();
    private readonly SelfAvatarPipeline _pipeline;
    private readonly double _rate;

    public SoakRun(string clipPath)
    {
        BvhClip clip = BvhReader.ReadFile(clipPath, new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Controller = null });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        using var reader = new SessionReader(new StringReader(text.ToString()), "soak");
        _rate = reader.Header.Rate;
        _pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid);
        SessionFrame frame = reader.CreateFrame();
        double last = 0;
        while (reader.ReadFrame(frame))
        {
            if (_pipeline.State != CalibrationState.Calibrated) { _pipeline.Update(frame); last = frame.Time; continue; }
            _samples.Add((DeviceSample[])frame.Samples.Clone());
            _truth.Add((RigidPose[])frame.Truth.Clone());
        }
        if (_pipeline.State != CalibrationState.Calibrated) throw new InvalidDataException("calibration did not complete: " + _pipeline.LastCalibrationStep.Message);
        StartTime = last;
    }

    private double StartTime { get; }

    /// <summary>Runs for <paramref name="minutes"/>, losing device (frame / interval) % 6 for <paramref name="lossSeconds"/> every <paramref name="lossEverySeconds"/>.</summary>
    public Result Run(double minutes, double lossEverySeconds, double lossSeconds)
    {
        long total = (long)Math.Round(minutes * 60 * _rate);
        long warmUp = (long)Math.Min(total, 60 * _rate);
        int n = _samples.Count, devices = _samples[0].Length;
        var buffer = new DeviceSample[devices];
        // The errors go to arrays sized before the warm-up ends, so that the measurement does not grow the memory it measures.
        int perMinute = (int)(60 * _rate) * BodyRoles.Count;
        var firstErrors = new double[perMinute];
        var lastErrors = new double[perMinute];
        int firstCount = 0, lastCount = 0;
        long bytes = 0, memoryAfterWarmUp = 0;
        int nonFinite = 0;
        int[] effectors = new int[BodyRoles.Count];
        HumanoidMap avatar = _pipeline.ScaledAvatar;
        for (int r = 0; r < BodyRoles.Count; r++) effectors[r] = avatar[BodyRoles.JointOf(BodyRoles.All[r])];
        var watch = System.Diagnostics.Stopwatch.StartNew();
        for (long i = 0; i < total; i++)
        {
            // Forward then back through the recorded frames: the motion never jumps.
            long cycle = i % (2L * n - 2);
            int k = (int)(cycle < n ? cycle : 2L * n - 2 - cycle);
            Array.Copy(_samples[k], buffer, devices);
            double time = StartTime + (i + 1) / _rate;
            double inCycle = (i / _rate) % lossEverySeconds;
            if (inCycle < lossSeconds)
            {
                int lost = (int)((long)(i / _rate / lossEverySeconds) % devices);
                buffer[lost] = new DeviceSample(buffer[lost].Pose, false);
            }
            long before = GC.GetAllocatedBytesForCurrentThread();
            _pipeline.Update(time, buffer, default, default, null);
            bytes += GC.GetAllocatedBytesForCurrentThread() - before;
            if (i == warmUp - 1)
            {
                memoryAfterWarmUp = GC.GetTotalMemory(true);
                bytes = 0; // what warm-up allocated is the JIT's and the caches', not the frames'
            }
            bool inFirst = i >= warmUp && i < warmUp + 60 * _rate, inLast = i >= total - 60 * _rate;
            if (!inFirst && !inLast) continue;
            for (int r = 0; r < effectors.Length; r++)
            {
                Vector3 solved = _pipeline.Pose.World[effectors[r]].Position;
                if (!Vectors.IsFinite(solved)) { nonFinite++; continue; }
                double mm = Vector3.Distance(solved, _truth[k][(int)BodyRoles.JointOf(BodyRoles.All[r])].Position) * 1000.0;
                if (inFirst && firstCount < perMinute) firstErrors[firstCount++] = mm;
                if (inLast && lastCount < perMinute) lastErrors[lastCount++] = mm;
            }
        }
        double seconds = watch.Elapsed.TotalSeconds;
        long memoryAtEnd = GC.GetTotalMemory(true);
        var first = new ErrorSeries();
        var lastMinute = new ErrorSeries();
        for (int j = 0; j < firstCount; j++) first.Add(firstErrors[j]);
        for (int j = 0; j < lastCount; j++) lastMinute.Add(lastErrors[j]);
        return new Result(total, minutes, bytes, memoryAfterWarmUp, memoryAtEnd, first.Median, first.P95, lastMinute.Median, lastMinute.P95, nonFinite, seconds);
    }
}
