using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>
/// `avatargo bench --calibration`: what each trigger press of the calibration costs (the frame in which the pipeline
/// handles it), and <see cref="ProportionFitter.Fit"/> alone. A press is not per-frame work, but the headset shows nothing
/// new while it runs: its time is a hitch the wearer sees.
/// </summary>
internal sealed class CalibrationBench
{
    private readonly List<double> _times = new();
    private readonly List<DeviceSample[]> _samples = new();
    private readonly List<float[]> _trigger = new(), _grip = new();
    private readonly List<DeviceEvent[]> _events = new();
    private IReadOnlyList<DeviceInfo> _devices;
    private HumanoidMap _avatar;

    public int Joints => _avatar.Skeleton.JointCount;

    /// <summary>The session's frames up to the one that completes calibration, with the avatar scaled by legs/arms.</summary>
    public static CalibrationBench Create(string clipPath, ControllerProfile controller, float legScale, float armScale)
    {
        BvhClip clip = BvhReader.ReadFile(clipPath, new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 1, Controller = controller });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        using var reader = new SessionReader(new StringReader(text.ToString()), "bench");
        var b = new CalibrationBench { _devices = reader.Header.Devices, _avatar = reader.Header.TruthHumanoid };
        if (legScale != 1f || armScale != 1f) b._avatar = Proportions.ScaleLimbs(b._avatar, legScale, armScale);
        var check = b.NewPipeline(ScaleMode.Fitted, controller);
        var frame = reader.CreateFrame();
        while (check.State != CalibrationState.Calibrated && reader.ReadFrame(frame))
        {
            b._times.Add(frame.Time);
            b._samples.Add((DeviceSample[])frame.Samples.Clone());
            b._trigger.Add((float[])frame.Trigger.Clone());
            b._grip.Add((float[])frame.Grip.Clone());
            b._events.Add(frame.Events.ToArray());
            check.Update(frame);
        }
        if (check.State != CalibrationState.Calibrated) throw new InvalidDataException("calibration did not complete: " + check.LastCalibrationStep.Message);
        return b;
    }

    private SelfAvatarPipeline NewPipeline(ScaleMode mode, ControllerProfile controller)
    {
        var settings = new PipelineSettings();
        settings.LeftHand.Controller = settings.RightHand.Controller = controller;
        settings.Calibration.Proportions.Mode = mode;
        return new SelfAvatarPipeline(_devices, _avatar, settings);
    }

    /// <summary>
    /// Calibrates once from scratch, timing every frame; returns the two press frames' times (ms): the T-pose press and
    /// the walk-in press (which also builds the solver), with the bytes each allocated.
    /// </summary>
    public (double tpose, double walkIn, long tposeBytes, long walkInBytes) Run(ScaleMode mode, ControllerProfile controller)
    {
        SelfAvatarPipeline p = NewPipeline(mode, controller);
        double t1 = 0, t2 = 0;
        long b1 = 0, b2 = 0;
        for (int i = 0; i < _times.Count; i++)
        {
            CalibrationState before = p.State;
            long bytes = GC.GetAllocatedBytesForCurrentThread();
            long t0 = Stopwatch.GetTimestamp();
            p.Update(_times[i], _samples[i], _trigger[i], _grip[i], _events[i]);
            double ms = (Stopwatch.GetTimestamp() - t0) * 1e3 / Stopwatch.Frequency;
            bytes = GC.GetAllocatedBytesForCurrentThread() - bytes;
            if (before != p.State && p.State == CalibrationState.WalkIn) { t1 = ms; b1 = bytes; }
            else if (before != p.State && p.State == CalibrationState.Calibrated) { t2 = ms; b2 = bytes; }
        }
        if (p.State != CalibrationState.Calibrated) throw new InvalidOperationException("calibration did not complete");
        return (t1, t2, b1, b2);
    }

    /// <summary>One <see cref="ProportionFitter.Fit"/> of this avatar to its own T-pose features scaled by 1.05 (ms).</summary>
    public double FitOnce(ScaleMode mode)
    {
        var settings = new ProportionSettings { Mode = mode };
        // The avatar's own eye height 5 % taller with its hips and reach unchanged: both legs and arms are refitted.
        _own ??= ProportionFitter.MeasureSkeleton(_avatar);
        float reach = 0.5f * _own.ArmSpan.Value + 0.05f;
        var f = new BodyFeatures(1.05f * _own.EyeHeight.Value, _own.HipHeight.Value, reach, reach, _own.ShoulderHeight.Value, _own.ShoulderHeight.Value);
        long t0 = Stopwatch.GetTimestamp();
        ProportionFitter.Fit(_avatar, f, settings);
        return (Stopwatch.GetTimestamp() - t0) * 1e3 / Stopwatch.Frequency;
    }

    private BodyMeasurements _own;
}
