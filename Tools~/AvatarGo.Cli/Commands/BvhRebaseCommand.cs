using System.Globalization;
using System.IO;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo bvh rebase IN OUT`: the same motion in another rest convention (BvhRebaser).</summary>
public sealed class BvhRebaseCommand : ICommand
{
    public string Name => "bvh rebase";
    public string Summary => "Rewrite a BVH clip in another rest convention (bones along +X, random axes), same motion";
    public string Help => """
        avatargo bvh rebase IN OUT --rest x-along|random [--seed N] [--twist DEG]

        Writes OUT with the motion of IN re-expressed in another rest convention: every joint gets new
        local axes, its children's OFFSETs and every frame's rotations are rewritten to match, and every
        joint's world position in every frame stays the same (to well under 0.01 mm). BVH's rest is the
        OFFSETs with no rotation, so the rest pose changes with the axes.
          --rest x-along   every bone along its joint's local +X (the bone to the child leading the largest
                           part of the skeleton): the rest is a straight line, not a T-pose
          --rest random    every joint's local frame a random rotation: the rest is crumpled
          --twist DEG      x-along: turn every joint's axes by DEG about its bone (default 0)
          --seed N         random: the seed of the rotations (default 1)
        Lengths stay in the file's units; joints with position channels keep all three; rotation channels
        keep the file's order.
        Exit codes: 0 ok, 1 unreadable or malformed file, 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args);
        if (a.Positional.Count < 2) throw new UsageException("missing IN and OUT");
        string input = a.Positional[0], output = a.Positional[1];
        string rest = a.String("rest") ?? throw new UsageException("missing --rest x-along|random");
        bool seedGiven = a.String("seed") != null;
        int seed = a.Int("seed", 1);
        double twist = a.Double("twist", 0);
        a.ThrowOnUnknown(2);
        if (rest != "x-along" && rest != "random") throw new UsageException($"--rest must be x-along or random, got '{rest}'");
        if (rest == "random" && twist != 0) throw new UsageException("--twist applies to --rest x-along only");
        if (rest == "x-along" && seedGiven) throw new UsageException("--seed applies to --rest random only");

        BvhClip clip = BvhReader.ReadFile(input);
        BvhClip rebased = rest == "x-along" ? BvhRebaser.AlongX(clip, (float)twist) : BvhRebaser.RandomAxes(clip, seed);
        BvhWriter.WriteFile(output, rebased);
        string how = rest == "x-along" ? string.Create(CultureInfo.InvariantCulture, $"bones along +X, twist {twist:0.##} deg") : $"random axes, seed {seed}";
        stdout.WriteLine($"wrote {output}: {rebased.FrameCount} frames, {how}");
        return 0;
    }
}
