using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>
/// The calibrator is fed every frame while the wearer gets ready: that must not allocate (a GC stall is a
/// dropped frame). Measured here rather than in Tests/Core because it needs .NET's per-thread allocation counter.
/// </summary>
public class CalibratorAllocationTests
{
    [Test]
    public void WaitingForTheTriggerAllocatesNothing()
    {
        var devices = new[]
        {
            new DeviceInfo(0, DeviceClass.Hmd, "H"), new DeviceInfo(1, DeviceClass.Controller, "L"), new DeviceInfo(2, DeviceClass.Controller, "R"),
            new DeviceInfo(3, DeviceClass.Tracker, "P"), new DeviceInfo(4, DeviceClass.Tracker, "F1"), new DeviceInfo(5, DeviceClass.Tracker, "F2"),
        };
        var clip = BvhReader.ReadFile(Paths.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
        var calibrator = new Calibrator(devices, HumanoidNaming.Detect(clip.Skeleton));
        var samples = new DeviceSample[6];
        for (int d = 0; d < 6; d++) samples[d] = new DeviceSample(new RigidPose(new Vector3(d * 0.1f, 1, 0), Quaternion.Identity), true);
        var noEvents = new List<DeviceEvent>();
        Feed(calibrator, samples, noEvents, 0, 2000); // warm up
        long best = long.MaxValue;
        for (int window = 0; window < 5; window++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            Feed(calibrator, samples, noEvents, 2000 + window * 1000, 1000);
            best = Math.Min(best, GC.GetAllocatedBytesForCurrentThread() - before);
        }
        Assert.That(best, Is.EqualTo(0), "bytes allocated over 1000 waiting frames");
        Assert.That(calibrator.State, Is.EqualTo(CalibrationState.WaitingForTPose));
    }

    private static void Feed(Calibrator c, DeviceSample[] samples, List<DeviceEvent> events, int start, int count)
    {
        for (int i = start; i < start + count; i++) c.Update(i / 90.0, samples, events);
    }
}
