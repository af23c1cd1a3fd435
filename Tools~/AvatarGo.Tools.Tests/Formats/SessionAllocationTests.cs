using System;
using System.IO;
using System.Numerics;
using System.Text;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Formats;

/// <summary>
/// A recorder writes and a replayer reads a session every frame inside a Unity app: both must allocate nothing
/// per frame (GUIDE: no GC stalls). Measured with the runtime's per-thread allocation counter, so it lives here
/// (net10) rather than in the Unity-shared core tests.
/// </summary>
public class SessionAllocationTests
{
    private static SessionHeader Header() => new(90f, new[]
    {
        new DeviceInfo(0, DeviceClass.Hmd, "HMD"), new DeviceInfo(1, DeviceClass.Controller, "L"), new DeviceInfo(2, DeviceClass.Controller, "R"),
        new DeviceInfo(3, DeviceClass.Tracker, "P"), new DeviceInfo(4, DeviceClass.Tracker, "LF"), new DeviceInfo(5, DeviceClass.Tracker, "RF"),
    });

    private static void Fill(SessionFrame f, int i)
    {
        f.Clear();
        f.Time = i / 90.0;
        for (int d = 0; d < f.Samples.Length; d++)
            f.Samples[d] = new DeviceSample(new RigidPose(new Vector3(0.1f * d, 1f + 0.001f * i, -0.3f), Rotations.AngleAxis(i * 0.7f + d, Vector3.UnitY)), d != 4 || i % 7 != 0);
        f.Trigger[1] = (i % 100) / 100f;
        f.Grip[2] = 0.25f;
        if (i % 90 == 5) f.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerPressed));
        if (i % 90 == 50) f.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerReleased));
        f.Truth[(int)HumanoidBone.Head] = f.Samples[0].Pose;
        f.HasTruth[(int)HumanoidBone.Head] = true;
    }

    // The runtime promotes hot methods to optimised code about 100 ms after they stop being new, in the background,
    // and the first calls after a promotion can allocate once (seen as a single 5 KB allocation at a varying frame
    // when other tests had just run). Waiting past that, and running the code again, keeps one-off promotions out
    // of the per-frame measurement.
    private static void SettleTieredCompilation(Action work)
    {
        for (int round = 0; round < 3; round++)
        {
            System.Threading.Thread.Sleep(150);
            work();
        }
    }

    [Test]
    public void WritingAFrameAllocatesNothing()
    {
        SessionHeader h = Header();
        using var w = new SessionWriter(new StreamWriter(Stream.Null, new UTF8Encoding(false), 1 << 16), h, ownsWriter: true);
        var f = new SessionFrame(h);
        int next = 0;
        for (; next < 200; next++) { Fill(f, next); w.WriteFrame(f); } // warm up (JIT, buffers)
        SettleTieredCompilation(() => { for (int end = next + 200; next < end; next++) { Fill(f, next); w.WriteFrame(f); } });
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int end = next + 2000; next < end; next++) { Fill(f, next); w.WriteFrame(f); }
        long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.That(bytes, Is.EqualTo(0), $"{bytes / 2000.0:0.#} bytes per written frame");
    }

    [Test]
    public void ReadingAFrameAllocatesNothing()
    {
        SessionHeader h = Header();
        var text = new StringWriter();
        using (var w = new SessionWriter(text, h))
        {
            var f = new SessionFrame(h);
            for (int i = 0; i < 3000; i++) { Fill(f, i); w.WriteFrame(f); }
        }
        using var r = new SessionReader(new StringReader(text.ToString()), "alloc");
        SessionFrame g = r.CreateFrame();
        for (int i = 0; i < 200; i++) Assert.That(r.ReadFrame(g), Is.True);
        SettleTieredCompilation(() => { for (int i = 0; i < 200; i++) r.ReadFrame(g); });
        long before = GC.GetAllocatedBytesForCurrentThread();
        int n = 0;
        while (r.ReadFrame(g)) n++;
        long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.That(n, Is.EqualTo(2200));
        Assert.That(bytes, Is.EqualTo(0), $"{bytes / 2200.0:0.#} bytes per read frame");
    }
}
