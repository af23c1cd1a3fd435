using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo evaluate`: calibrate and solve a synthetic session, compare with the ground truth.</summary>
public sealed class EvaluateCommand : ICommand
{
    public string Name => "evaluate";
    public string Summary => "Replay a synthetic session and measure how closely the avatar follows";
    public string Help => """
        avatargo evaluate SESSION [--mode exact|fixed] [--avatar FILE] [--leg-scale S] [--arm-scale S]
                         [--controller NAME|none] [--grip hold|open|point|input] [--hands palm|calibrated] [--json OUT]

        Replays SESSION through the whole pipeline (SelfAvatarPipeline: T-pose identification, scaling,
        walk-in offsets, body IK, hands on the controllers, finger IK) and compares the avatar (the
        wearer's own skeleton from the session) with the ground truth on every frame after calibration:
        per joint and for end effectors (hips, head, hands, feet), mid joints (elbows, knees) and all
        joints, the median, mean, 95th percentile and maximum position error in mm; end-effector rotation
        error and knee angle error in degrees; and, for an avatar with finger bones, the fingers on the
        solved body: the deepest penetration of the controller and each fingertip's gap (mm).
          --mode exact|fixed   exact offsets (the paper's method, default) or fixed offsets (its baseline)
          --controller NAME    the controller in both hands (Runtime/ControllerProfiles; default vive-wand,
                               as 'simulate' holds by default); none: no finger IK
          --grip MODE          hold (default), open, point, or input (the session's trigger and grip values)
          --hands palm|calibrated  the wrist from the palm on the controller (default, the paper's; needs
                               finger bones) or from the offset measured at the walk-in
          --avatar FILE        use this BVH skeleton (its rest pose, any units) as the avatar instead
          --leg-scale S        make the avatar's legs S times as long (default 1)
          --arm-scale S        make the avatar's arms S times as long (default 1)
          --json OUT           also write the figures as JSON to OUT
        Exit codes: 0 ok, 1 unreadable session or calibration failed, 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args);
        string path = a.Positional0("SESSION");
        OffsetMode mode = ParseMode(a.String("mode", "exact"));
        string json = a.String("json");
        string avatarFile = a.String("avatar");
        float legScale = (float)a.Double("leg-scale", 1), armScale = (float)a.Double("arm-scale", 1);
        PipelineSettings settings = Settings(a, mode);
        a.ThrowOnUnknown(1);
        if (!(legScale > 0.5f && legScale < 2f) || !(armScale > 0.5f && armScale < 2f)) throw new UsageException("limb scales must be between 0.5 and 2");
        EvaluationReport report;
        using (SessionReader reader = SessionReader.Open(path))
        {
            HumanoidMap avatar = avatarFile != null
                ? HumanoidNaming.Detect(BvhReader.ReadFile(avatarFile, new BvhReadOptions { ToMetres = true }).Skeleton)
                : reader.Header.TruthHumanoid ?? throw new UsageException("the session has no ground-truth skeleton; give --avatar FILE");
            if (legScale != 1f || armScale != 1f) avatar = Proportions.ScaleLimbs(avatar, legScale, armScale);
            report = SessionEvaluator.Evaluate(reader, settings, avatar);
        }
        if (report.Profile == null)
        {
            stderr.WriteLine($"avatargo evaluate: calibration did not complete: {report.CalibrationMessage}");
            return 1;
        }
        Print(report, stdout);
        if (json != null) File.WriteAllText(json, ToJson(report));
        return 0;
    }

    /// <summary>The pipeline settings of evaluate and demo: offset mode, both hands' controller, grip and placement.</summary>
    internal static PipelineSettings Settings(ArgReader a, OffsetMode mode)
    {
        var settings = new PipelineSettings { Offsets = mode };
        ControllerProfile controller = ControllerProfiles.Named(a.String("controller", ControllerProfiles.Default));
        GripMode grip = a.String("grip", "hold") switch
        {
            "hold" => GripMode.Hold,
            "open" => GripMode.Open,
            "point" => GripMode.Point,
            "input" => GripMode.InputDriven,
            string other => throw new UsageException($"--grip must be hold, open, point or input, got '{other}'"),
        };
        HandPlacement placement = a.String("hands", "palm") switch
        {
            "palm" => HandPlacement.PalmOnController,
            "calibrated" => HandPlacement.CalibratedOffset,
            string other => throw new UsageException($"--hands must be palm or calibrated, got '{other}'"),
        };
        foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
        {
            settings.Hand(side).Controller = controller;
            settings.Hand(side).Grip = grip;
            settings.Hand(side).Placement = placement;
        }
        return settings;
    }

    internal static OffsetMode ParseMode(string mode) => mode switch
    {
        "exact" => OffsetMode.Exact,
        "fixed" => OffsetMode.Fixed,
        _ => throw new UsageException($"--mode must be exact or fixed, got '{mode}'"),
    };

    internal static void Print(EvaluationReport r, TextWriter o)
    {
        var inv = CultureInfo.InvariantCulture;
        o.WriteLine($"mode: {r.Mode.ToString().ToLowerInvariant()}, frames compared: {r.Frames}, avatar scale {r.Profile.AvatarScale.ToString("0.0000", inv)}");
        o.WriteLine("                       median     mean      p95      max");
        Row(o, "end effectors (mm)", r.EndEffectorMm);
        Row(o, "mid joints (mm)", r.MidJointMm);
        Row(o, "all joints (mm)", r.AllJointsMm);
        Row(o, "end eff. rot. (deg)", r.EndEffectorDegrees);
        Row(o, "knee angle (deg)", r.KneeAngleDegrees);
        foreach (var (bone, s) in r.JointPositionMm.OrderBy(p => p.Key))
            Row(o, "  " + bone, s);
        if (r.Fingers == null) return;
        o.WriteLine(string.Create(inv, $"fingers on the solved body ({r.Fingers.Frames} frames, {r.Fingers.OpenHandFrames} hand-frames open): deepest penetration {r.Fingers.MaxPenetrationMm:0.00} mm"));
        foreach (Finger f in Enum.GetValues<Finger>())
            if (r.Fingers.Gap(f).Count > 0) Row(o, $"  {f} tip gap (mm)", r.Fingers.Gap(f));
    }

    private static void Row(TextWriter o, string name, ErrorSeries s) =>
        o.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name,-20} {s.Median,8:0.0} {s.Mean,8:0.0} {s.P95,8:0.0} {s.Max,8:0.0}"));

    internal static string ToJson(EvaluationReport r)
    {
        var doc = new
        {
            mode = r.Mode.ToString().ToLowerInvariant(),
            frames = r.Frames,
            avatar_scale = r.Profile.AvatarScale,
            end_effector_median_mm = r.EndEffectorMm.Median,
            end_effector_p95_mm = r.EndEffectorMm.P95,
            end_effector_rotation_median_deg = r.EndEffectorDegrees.Median,
            mid_median_mm = r.MidJointMm.Median,
            mpjpe_mm = r.AllJointsMm.Mean,
            knee_angle_error_deg = r.KneeAngleDegrees.Median,
            unreached_hand_frames = r.UnreachedHandFrames,
            joints = r.JointPositionMm.OrderBy(p => p.Key).ToDictionary(p => p.Key.ToString(), p => new { median_mm = p.Value.Median, p95_mm = p.Value.P95, max_mm = p.Value.Max }),
            fingers = r.Fingers == null ? null : new
            {
                frames = r.Fingers.Frames,
                open_hand_frames = r.Fingers.OpenHandFrames,
                max_penetration_mm = r.Fingers.MaxPenetrationMm,
                tip_gap_mm = Enum.GetValues<Finger>().Where(f => r.Fingers.Gap(f).Count > 0)
                    .ToDictionary(f => f.ToString(), f => new { median = r.Fingers.Gap(f).Median, p95 = r.Fingers.Gap(f).P95, max = r.Fingers.Gap(f).Max }),
            },
        };
        return JsonSerializer.Serialize(doc, new JsonSerializerOptions { WriteIndented = true });
    }
}
