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
        avatargo evaluate SESSION [--mode exact|fixed] [--avatar FILE] [--leg-scale S] [--arm-scale S] [--json OUT]

        Replays SESSION through calibration (T-pose identification, scaling, walk-in offsets), the
        per-frame body solver and the IK, and compares the avatar (the wearer's own skeleton from the
        session) with the ground truth on every frame after calibration: per joint and for end
        effectors (hips, head, hands, feet), mid joints (elbows, knees) and all joints, the median,
        mean, 95th percentile and maximum position error in mm; end-effector rotation error and knee
        angle error in degrees.
          --mode exact|fixed   exact offsets (the paper's method, default) or fixed offsets (its baseline)
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
        a.ThrowOnUnknown(1);
        if (!(legScale > 0.5f && legScale < 2f) || !(armScale > 0.5f && armScale < 2f)) throw new UsageException("limb scales must be between 0.5 and 2");
        EvaluationReport report;
        using (SessionReader reader = SessionReader.Open(path))
        {
            HumanoidMap avatar = avatarFile != null
                ? CalibrateCommand.AvatarFrom(avatarFile)
                : reader.Header.TruthHumanoid ?? throw new UsageException("the session has no ground-truth skeleton; give --avatar FILE");
            if (legScale != 1f || armScale != 1f) avatar = Proportions.ScaleLimbs(avatar, legScale, armScale);
            report = SessionEvaluator.Evaluate(reader, mode, avatar);
        }
        if (report.Profile == null)
        {
            stderr.WriteLine($"avatargo evaluate: calibration did not complete: {report.CalibrationMessage}");
            return 1;
        }
        Print(report, stdout);
        if (json != null) AtomicFileWriter.WriteAllText(json, ToJson(report)); // whole or not at all: a failure leaves an older OUT as it was
        return 0;
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
        };
        return JsonSerializer.Serialize(doc, new JsonSerializerOptions { WriteIndented = true });
    }
}
