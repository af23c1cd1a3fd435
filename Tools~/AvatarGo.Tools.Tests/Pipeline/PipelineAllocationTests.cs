using System;
using System.IO;
using AvatarGo.Core;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Pipeline;

/// <summary>
/// One frame of the whole pipeline after calibration allocates nothing, exactly: Unity's garbage collector stops the
/// world, and a stall is a dropped frame in a headset. Measured on this thread over a whole recorded motion, with finger
/// IK on both hands, analog inputs, trigger presses (which the calibrated pipeline leaves to the application) and lost
/// devices.
/// </summary>
public class PipelineAllocationTests
{
    [TestCase(false)]
    [TestCase(true)]
    public void AFrameAfterCalibrationAllocatesNothing(bool smoothing)
    {
        ControllerProfile controller = ControllerProfile.Parse(File.ReadAllText(Path.Combine(Paths.PackageRoot, "Runtime", "ControllerProfiles", "valve-index.json")));
        BvhClip clip = BvhReader.ReadFile(Paths.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Controller = controller });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);

        var settings = new PipelineSettings();
        settings.LeftHand.Controller = settings.RightHand.Controller = controller;
        settings.RightHand.Grip = GripMode.InputDriven;
        settings.Tracking.Smoothing = smoothing;
        using var reader = new SessionReader(new StringReader(text.ToString()), "allocation");
        var pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid, settings);
        SessionFrame frame = reader.CreateFrame();
        while (pipeline.State != CalibrationState.Calibrated && reader.ReadFrame(frame)) pipeline.Update(frame);
        Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);
        Assume.That(pipeline.Hand(BodySide.Left).HasFingerIk && pipeline.Hand(BodySide.Right).HasFingerIk, Is.True);

        // Keep the frames in memory so that reading the file is not measured.
        var samples = new System.Collections.Generic.List<DeviceSample[]>();
        var times = new System.Collections.Generic.List<double>();
        while (reader.ReadFrame(frame))
        {
            samples.Add((DeviceSample[])frame.Samples.Clone());
            times.Add(frame.Time);
        }
        var trigger = new float[reader.Header.Devices.Count];
        var grip = new float[reader.Header.Devices.Count];
        var press = new System.Collections.Generic.List<DeviceEvent> { new DeviceEvent(1, DeviceEventKind.TriggerPressed) };
        // Bytes are counted around each frame's Update call only (the test's own loop is not the pipeline: .NET's
        // on-stack replacement of a hot loop can allocate a few bytes on this thread).
        long RunAll()
        {
            long bytes = 0;
            for (int i = 0; i < samples.Count; i++)
            {
                for (int d = 0; d < trigger.Length; d++) { trigger[d] = (i % 30) / 30f; grip[d] = 1f - trigger[d]; }
                DeviceSample kept = samples[i][i % samples[i].Length];
                if (i % 17 == 0) samples[i][i % samples[i].Length] = DeviceSample.Lost;
                long before = GC.GetAllocatedBytesForCurrentThread();
                pipeline.Update(times[i], samples[i], trigger, grip, i % 10 == 0 ? press : null);
                bytes += GC.GetAllocatedBytesForCurrentThread() - before;
                samples[i][i % samples[i].Length] = kept;
            }
            return bytes;
        }
        RunAll(); // warm up: the JIT and every lazily filled cache
        Assert.That(RunAll(), Is.EqualTo(0), $"bytes allocated by {samples.Count} frames of the pipeline");
        Assert.That(samples.Count, Is.GreaterThan(250));
    }
}
