using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo bvh info FILE`: joints, frames, rate, humanoid mapping and missing required bones.</summary>
public sealed class BvhInfoCommand : ICommand
{
    public string Name => "bvh info";
    public string Summary => "Joints, frame count, rate and humanoid mapping of a BVH file";
    public string Help => """
        avatargo bvh info FILE [--map FILE]

        Prints the joints of a BVH file (with their channels), its frame count, frame rate and
        duration, the guessed length unit, the humanoid bone found for each joint, and the required
        humanoid bones that could not be found (none for a usable rig); for a usable rig also the
        optional bones it lacks, whether each hand's fingers were found (else the hand takes the
        walk-in offset), its up axis and how its knees bend (a mirrored clip bends them backward).
          --map FILE   the humanoid bones of joints the naming rules miss ('joint name = Bone' lines,
                       as for 'avatargo simulate')
        Exit codes: 0 ok, 1 unreadable or malformed file (one-line message), 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args);
        string path = a.Positional0("FILE");
        string mapPath = a.String("map");
        a.ThrowOnUnknown(1);
        BvhClip clip = BvhReader.ReadFile(path);
        HumanoidMap map = BoneMapFile.Detect(clip, mapPath, out string note);
        Skeleton s = clip.Skeleton;
        var inv = CultureInfo.InvariantCulture;
        float unit = clip.GuessMetresPerUnit();
        stdout.WriteLine($"file: {Path.GetFileName(path)}");
        stdout.WriteLine($"frames: {clip.FrameCount}");
        stdout.WriteLine(string.Create(inv, $"rate: {clip.FrameRate:0.###} Hz (frame time {clip.FrameTime:0.######} s), duration {clip.FrameCount * clip.FrameTime:0.###} s"));
        string unitName = unit == 1f ? "metres" : unit == 0.01f ? "centimetres" : unit == 0.001f ? "millimetres" : unit == 0.0254f ? "inches"
            : string.Create(inv, $"{unit:0.######} m (the CMU database's BVH unit)");
        stdout.WriteLine($"units: {unitName} (guessed from the longest chain of bones; simulate and demo take --units when it is another)");
        stdout.WriteLine($"joints: {s.Names.Count(n => !s.IsEndSite(s.IndexOf(n)))} (+{s.Names.Count(n => s.IsEndSite(s.IndexOf(n)))} end sites), channels per frame: {clip.ChannelCount}");
        for (int j = 0; j < s.JointCount; j++)
        {
            int depth = 0;
            for (int p = s.GetParent(j); p >= 0; p = s.GetParent(p)) depth++;
            HumanoidBone bone = map.BoneOf(j);
            string channels = s.IsEndSite(j) ? "end site" : string.Join(" ", clip.GetChannels(j));
            stdout.WriteLine($"  {new string(' ', depth * 2)}{s.GetName(j)}  [{channels}]{(bone != HumanoidBone.LastBone ? "  -> " + bone : "")}");
        }
        var missing = map.MissingRequired();
        stdout.WriteLine($"humanoid: {map.Count} bones mapped; missing required: {(missing.Count == 0 ? "none" : string.Join(", ", missing))}");
        if (note != null) stdout.WriteLine($"  {note}");
        if (missing.Count == 0)
        {
            var optional = OptionalBodyBones.Where(b => !map.Has(b)).ToList();
            stdout.WriteLine($"optional bones missing: {(optional.Count == 0 ? "none" : string.Join(", ", optional) + " (what each costs: Documentation~/skeletons.md)")}");
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                string hand = side == BodySide.Left ? "left hand" : "right hand";
                bool anyFinger = Enumerable.Range(0, HumanoidBones.Count).Any(b => HumanoidBones.IsFinger((HumanoidBone)b)
                    && HumanoidBones.IsLeft((HumanoidBone)b) == (side == BodySide.Left) && map.Has((HumanoidBone)b));
                stdout.WriteLine(HandModel.CanModel(map, side, out string reason)
                    ? $"{hand}: fingers found (the controller in the palm, the fingers closed on it)"
                    : $"{hand}: {(anyFinger ? reason : "no finger bones")}; the hand takes the walk-in offset, without finger IK");
            }
            Quaternion upright = ClipConventions.UprightTurn(clip, map);
            stdout.WriteLine(upright == Quaternion.Identity ? "up: +Y"
                : string.Create(inv, $"up: {AxisName(Vector3.Transform(Vector3.UnitY, Quaternion.Conjugate(upright)))} (not +Y: simulate turns the motion {Rotations.AngleDegrees(Quaternion.Identity, upright):0} deg to stand it up)"));
            bool mirrored = ClipConventions.LooksMirrored(clip, map, out int forward, out int backward);
            stdout.WriteLine($"knees bent 20 deg or more: {forward} bend forward, {backward} backward{(mirrored ? " (its sides look mirrored: a left-handed export, or Left and Right named the wrong way round; simulate mirrors it)" : "")}");
        }
        return 0;
    }

    // The humanoid bones the body solve uses when a rig has them (the fingers are summed up per hand).
    private static readonly HumanoidBone[] OptionalBodyBones =
    {
        HumanoidBone.Chest, HumanoidBone.UpperChest, HumanoidBone.Neck, HumanoidBone.LeftShoulder, HumanoidBone.RightShoulder,
        HumanoidBone.LeftToes, HumanoidBone.RightToes, HumanoidBone.LeftEye, HumanoidBone.RightEye,
    };

    // "+X" … "-Z": the axis a unit vector lies along (the clip's up is always one of them).
    private static string AxisName(Vector3 v)
    {
        float x = MathF.Abs(v.X), y = MathF.Abs(v.Y), z = MathF.Abs(v.Z);
        return x >= y && x >= z ? (v.X > 0 ? "+X" : "-X") : y >= z ? (v.Y > 0 ? "+Y" : "-Y") : (v.Z > 0 ? "+Z" : "-Z");
    }
}
