using System;
using System.Globalization;
using System.IO;
using System.Text.Json;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo soak`: the pipeline for an hour (or as long as asked) at 90 Hz, with periodic losses.</summary>
public sealed class SoakCommand : ICommand
{
    public string Name => "soak";
    public string Summary => "Run the pipeline for a long time with periodic losses: allocation, memory, error drift";
    public string Help => """
        avatargo soak [--minutes M] [--bvh FILE] [--loss-every S] [--loss-seconds S] [--json]

        Simulates a mocap clip (default: the bundled one), calibrates, then plays its motion forward and back
        at 90 Hz for M minutes (default 60), one device after another lost for S seconds every S seconds
        (defaults: lost 1 s every 20 s). Reports the bytes allocated per frame after the first minute (counted
        around every Update; must be 0), managed memory after the first minute and at the end (must not grow),
        and the end effectors' error in the first minute after warm-up and in the last minute.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "json");
        double minutes = a.Double("minutes", 60);
        string bvh = a.String("bvh") ?? DemoCommandPaths.BundledClip();
        double every = a.Double("loss-every", 20), lossSeconds = a.Double("loss-seconds", 1);
        bool json = a.Flag("json");
        a.ThrowOnUnknown(0);
        if (!(minutes >= 2 && minutes <= 24 * 60)) throw new UsageException("--minutes must be between 2 and 1440");
        if (!(every > 0 && lossSeconds >= 0 && lossSeconds < every)) throw new UsageException("--loss-seconds must be shorter than --loss-every");
        SoakRun.Result r = new SoakRun(bvh).Run(minutes, every, lossSeconds);
        if (json)
        {
            stdout.WriteLine(JsonReports.Serialize(r));
            return 0;
        }
        var inv = CultureInfo.InvariantCulture;
        stdout.WriteLine(string.Create(inv, $"{r.Frames} frames ({r.Minutes:0.#} min at 90 Hz) solved in {r.SolveSeconds:0.0} s"));
        stdout.WriteLine(string.Create(inv, $"bytes allocated after the first minute: {r.BytesAllocated} ({(double)r.BytesAllocated / (r.Frames - 5400):0.###} per frame)"));
        stdout.WriteLine(string.Create(inv, $"managed memory after the first minute {r.MemoryAfterWarmUp / 1024.0:0} KiB, at the end {r.MemoryAtEnd / 1024.0:0} KiB ({SignedKiB(r.MemoryAtEnd - r.MemoryAfterWarmUp)} KiB)"));
        stdout.WriteLine(string.Create(inv, $"end effectors, first minute after warm-up: median {r.FirstMinuteMedianMm:0.00} p95 {r.FirstMinuteP95Mm:0.00} mm; last minute: median {r.LastMinuteMedianMm:0.00} p95 {r.LastMinuteP95Mm:0.00} mm"));
        if (r.NonFiniteFrames > 0) stdout.WriteLine($"NON-FINITE end effectors: {r.NonFiniteFrames}");
        return r.NonFiniteFrames == 0 ? 0 : 1;
    }

    // A change in whole KiB with its sign; a small negative change printed "-+0" with the format "+0;-0".
    private static string SignedKiB(long bytes)
    {
        double kib = Math.Round(bytes / 1024.0) + 0.0; // + 0.0 turns -0.0 into 0.0
        return kib == 0.0 ? "0" : kib.ToString("+0;-0", CultureInfo.InvariantCulture);
    }
}
