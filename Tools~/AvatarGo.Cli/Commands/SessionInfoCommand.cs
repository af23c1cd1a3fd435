using System.Globalization;
using System.IO;
using AvatarGo.Core;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo session info FILE`: devices, rate, frames, duration, events, ground truth.</summary>
public sealed class SessionInfoCommand : ICommand
{
    public string Name => "session info";
    public string Summary => "Devices, rate, frames, duration and events of a session file";
    public string Help => """
        avatargo session info FILE

        Reads a session (AvatarGo session format v1, Documentation~/session-format.md) from start to
        end, streaming, and prints its devices (id, class, serial, runtime role and, for synthetic
        sessions, true role) with the share of frames each is tracked, nominal rate, frame count,
        duration, trigger events and whether it carries ground truth.
        Exit codes: 0 ok, 1 unreadable or malformed file (one-line message naming the line), 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args);
        string path = a.Positional0("FILE");
        a.ThrowOnUnknown(1);
        using SessionReader reader = SessionReader.Open(path);
        SessionHeader h = reader.Header;
        SessionFrame frame = reader.CreateFrame();
        int presses = 0, releases = 0, truthFrames = 0;
        var tracked = new int[h.Devices.Count];
        var analog = new int[h.Devices.Count];
        double first = double.NaN, last = double.NaN;
        while (reader.ReadFrame(frame))
        {
            if (double.IsNaN(first)) first = frame.Time;
            last = frame.Time;
            foreach (DeviceEvent e in frame.Events)
                if (e.Kind == DeviceEventKind.TriggerPressed) presses++; else releases++;
            if (System.Array.IndexOf(frame.HasTruth, true) >= 0) truthFrames++;
            for (int i = 0; i < tracked.Length; i++)
            {
                if (frame.Samples[i].IsTracked) tracked[i]++;
                if (!float.IsNaN(frame.Trigger[i]) || !float.IsNaN(frame.Grip[i])) analog[i]++;
            }
        }
        var inv = CultureInfo.InvariantCulture;
        stdout.WriteLine($"file: {Path.GetFileName(path)}");
        stdout.WriteLine(string.Create(inv, $"rate: {h.Rate:0.###} Hz"));
        stdout.WriteLine(string.Create(inv, $"frames: {reader.FrameCount}, duration {(reader.FrameCount > 0 ? last - first : 0):0.###} s"));
        stdout.WriteLine($"devices: {h.Devices.Count}");
        for (int i = 0; i < h.Devices.Count; i++)
        {
            DeviceInfo d = h.Devices[i];
            string share = reader.FrameCount > 0 ? string.Create(inv, $"{100.0 * tracked[i] / reader.FrameCount:0.#}% of frames") : "no frames";
            stdout.WriteLine($"  {d.Id}: {d.Class} serial '{d.Serial}' runtime role {d.RuntimeRole}{(h.HasTrueRoles ? ", true role " + h.TrueRole(i) : "")}; tracked {share}{(analog[i] > 0 ? $", analog input in {analog[i]} frames" : "")}");
        }
        stdout.WriteLine($"events: {presses} trigger presses, {releases} releases");
        stdout.WriteLine($"ground truth: {(h.TruthHumanoid != null ? $"skeleton of {h.TruthHumanoid.Skeleton.JointCount} joints ({h.TruthHumanoid.Count} humanoid bones), " : "no skeleton, ")}{truthFrames} frames with joint poses");
        return 0;
    }
}
