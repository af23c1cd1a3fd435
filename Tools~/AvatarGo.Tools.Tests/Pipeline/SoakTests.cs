using AvatarGo.Cli;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Pipeline;

/// <summary>
/// The pipeline over a long run at 90 Hz with periodic losses: no allocation per frame, managed memory flat, and the error
/// at the end no worse than at the start. Five minutes in the default suite; the whole hour is a slow test.
/// </summary>
public class SoakTests
{
    private static void AssertHolds(SoakRun.Result r)
    {
        Assert.That(r.NonFiniteFrames, Is.EqualTo(0), "never a NaN");
        Assert.That(r.BytesAllocated, Is.EqualTo(0), $"bytes allocated by {r.Frames} frames after the first minute");
        Assert.That(r.MemoryAtEnd - r.MemoryAfterWarmUp, Is.LessThan(1024 * 1024), "managed memory flat within 1 MB");
        Assert.That(r.LastMinuteMedianMm, Is.LessThanOrEqualTo(r.FirstMinuteMedianMm + 0.1), "no drift: median (mm)");
        Assert.That(r.LastMinuteP95Mm, Is.LessThanOrEqualTo(r.FirstMinuteP95Mm * 1.1 + 0.5), "no drift: p95 (mm)");
    }

    [Test]
    public void FiveMinutesWithPeriodicLosses() => AssertHolds(new SoakRun(Paths.Mocap("mocapbank_30fps.bvh")).Run(5, 20, 1));

    [Test, Category("Slow")]
    public void AnHourWithPeriodicLosses() => AssertHolds(new SoakRun(Paths.Mocap("mocapbank_30fps.bvh")).Run(60, 20, 1));
}
