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
        avatargo evaluate SESSION [--mode exact|fixed] [--scale-mode uniform|fitted] [--avatar FILE [--avatar-map FILE]] [--leg-scale S] [--arm-scale S]
                         [--controller NAME|none] [--grip hold|open|point|input] [--hands palm|calibrated] [--json OUT]
                         [--knee-hint MODEL] [--elbow-hint MODEL] [--positions OUT.csv] [--bvh-out OUT.bvh] [--plot OUT.png]
                         [--refine] [--exercise-seconds S] [--smoothing]

        Replays SESSION through the whole pipeline (SelfAvatarPipeline: T-pose identification, scaling,
        walk-in offsets, body IK, hands on the controllers, finger IK) and compares the avatar (the
        wearer's own skeleton from the session) with the ground truth on every frame after calibration:
        per joint and for end effectors (hips, head, hands, feet), mid joints (elbows, knees) and all
        joints but the finger bones (MPJPE: the mean over those), the median, mean, 95th percentile and
        maximum position error in mm; end-effector rotation
        error and knee angle error in degrees; the steadiness: how much further each joint moved from one
        frame to the next than the wearer's (p95, max and the share of jumps over 10 mm; JSON: per joint
        and "jitter_mm", the joints' p95 on average); and, for an avatar with finger bones, the fingers on
        the solved body: the deepest penetration of the controller and each fingertip's gap (mm).
          --mode exact|fixed   exact offsets (the paper's method, default) or fixed offsets (its baseline)
          --controller NAME    the controller in both hands (Runtime/ControllerProfiles; default vive-wand,
                               as 'simulate' holds by default); none: no finger IK
          --grip MODE          hold (default), open, point, or input (the session's trigger and grip values)
          --hands palm|calibrated  the wrist from the palm on the controller (default, the paper's; needs
                               finger bones) or from the offset measured at the walk-in
        Disturbances injected into every frame after calibration (and what they did: the largest frame-to-frame
        jump of any end effector, also beyond the wearer's own motion and on recovery, and the end-effector
        error while a device is lost or teleported, in the second after it comes back, and otherwise):
          --dropout RATE       share of frames each device is lost, in bursts (e.g. 0.05)
          --dropout-seconds S  the longest burst (default 1)
          --noise-mm N         extra position noise per coordinate (standard deviation, mm)
          --teleport M         teleports: a device jumps M metres for a moment
          --teleport-seconds S how long a teleport lasts (default 0.1)
          --teleports-per-minute N  per device (default 1)
          --disturb-seed N     the disturbances' seed (default 1)
          --avatar FILE        use this BVH skeleton (its rest pose, any units) as the avatar instead
          --avatar-map FILE    the humanoid bones of the avatar's joints the naming rules miss ('joint name =
                               Bone' lines, as simulate's --map)
          --leg-scale S        make the avatar's legs S times as long (default 1)
          --arm-scale S        make the avatar's arms S times as long (default 1)
          --scale-mode M       uniform (default, the paper's: by eye height) or fitted (legs and arms fitted to the
                               wearer's measured proportions, Documentation~/calibration.md)
          --json OUT           also write the figures as JSON to OUT
          --knee-hint MODEL    how the knees' bend direction is chosen: outer (default: the more outward of the
                               pelvis's and the foot's planes), pelvis-foot, pelvis, foot, toes, ankle-hinge,
                               calibration (Documentation~/solver.md compares them)
          --elbow-hint MODEL   how the elbows' bend direction is chosen: hand-axis (default), down-out-back, calibration
          --smoothing          filter every device pose (TrackingSettings.Smoothing: One Euro, 2 Hz at rest, beta 30;
                               off by default; Documentation~/solver.md, "Jitter")
          --refine             the refinement from motion (Documentation~/calibration.md): the S seconds after
                               calibration are the exercise ('simulate --exercise-seconds S'), recorded and not
                               scored; at their end the arms' lengths are refined from their reach and the rest of
                               the session is scored on the refined avatar. Prints (and writes to --json, key
                               "refinement") per limb the residual and the length before and after and whether it
                               changed, and why (the legs are reported, never refined). Not with the disturbances
                               or --positions / --bvh-out / --plot
          --exercise-seconds S the exercise's length (default 8; the session's, as simulated); without --refine those
                               seconds are not scored either, so the figures compare with --refine's
        """ + "\n" + EvaluationOutputs.Help + "\n" + """
        Proportions: the wearer's true lengths (from the session's skeleton), the measured ones with their uncertainty,
        and the calibrated avatar's; the frames in which a hand could not reach its controller, and of those the ones
        in which the wearer's own arm was not fully stretched (under 98 % of its length).
        Knees and elbows: the bend-plane angle error (wearer's vs avatar's bend direction about the limb's axis),
        median / p95 / max in degrees and the share of frames beyond 90 deg ("flipped"), frames in which the
        wearer's limb bends at least 15 deg; the signed median is right-handed about each limb's root-to-end axis,
        so the same anatomical error reads with opposite signs on the left and right limbs.
        Exit codes: 0 ok, 1 unreadable session, calibration failed or nothing to compare (no frame with the true joints), 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "refine");
        string path = a.Positional0("SESSION");
        OffsetMode mode = ParseMode(a.String("mode", "exact"));
        string json = a.String("json");
        string avatarFile = a.String("avatar");
        string avatarMap = CalibrateCommand.AvatarMapArgument(a, avatarFile);
        float legScale = (float)a.Double("leg-scale", 1), armScale = (float)a.Double("arm-scale", 1);
        PipelineSettings settings = Settings(a, mode);
        settings.Calibration.Proportions.Mode = a.String("scale-mode", "uniform") switch
        {
            "uniform" => ScaleMode.Uniform,
            "fitted" => ScaleMode.Fitted,
            string other => throw new UsageException($"--scale-mode must be uniform or fitted, got '{other}'"),
        };
        DisturbanceOptions disturbance = Disturbance(a);
        EvaluationOutputs outputs = EvaluationOutputs.FromArgs(a);
        bool refine = a.Flag("refine");
        double exerciseArgument = a.Double("exercise-seconds", double.NaN);
        // With --exercise-seconds alone the exercise is not scored either, so the figures compare with --refine's (before,
        // the option was ignored and the arm circles and squats were scored).
        bool exercise = refine || !double.IsNaN(exerciseArgument);
        double exerciseSeconds = double.IsNaN(exerciseArgument) ? 8 : exerciseArgument;
        a.ThrowOnUnknown(1);
        if (exercise && (disturbance != null || outputs.IsRecording)) throw new UsageException("--refine and --exercise-seconds do not combine with disturbances or --positions / --bvh-out / --plot");
        if (exercise && !(exerciseSeconds > 0 && exerciseSeconds <= 60)) throw new UsageException("--exercise-seconds must be more than 0 and at most 60");
        if (!(legScale > 0.5f && legScale < 2f) || !(armScale > 0.5f && armScale < 2f)) throw new UsageException("limb scales must be between 0.5 and 2");
        OutputFiles.RefuseClashes(new[] { ("the session", path), ("--avatar", avatarFile), ("--avatar-map", avatarMap) }, outputs.Paths.Prepend(("--json", json)));
        // Every output written together after the evaluation, or none replaced (a plot that could not be drawn once left
        // the JSON and the positions replaced by a run that failed).
        using var files = new OutputFiles();
        AtomicFileWriter jsonFile = json != null ? files.Open(json) : null;
        outputs.Open(files);
        EvaluationReport report;
        using (SessionReader reader = SessionReader.Open(path))
        {
            HumanoidMap avatar = avatarFile != null
                ? CalibrateCommand.AvatarFrom(avatarFile, avatarMap)
                : reader.Header.TruthHumanoid ?? throw new UsageException("the session has no ground-truth skeleton (a recording from a headset has none, and nothing to compare with; 'simulate' writes sessions that do); give --avatar FILE for the avatar");
            if (legScale != 1f || armScale != 1f) avatar = Proportions.ScaleLimbs(avatar, legScale, armScale);
            report = exercise
                ? SessionEvaluator.EvaluateExercise(reader, settings, avatar, (float)exerciseSeconds, refine)
                : outputs.Evaluate(reader, settings, avatar, disturbance);
        }
        if (report.Profile == null)
        {
            stderr.WriteLine($"avatargo evaluate: calibration did not complete: {report.CalibrationMessage}");
            return 1;
        }
        if (report.Frames == 0)
        {
            // Nothing to measure (the session ends on the walk-in press, a truncated recording): every figure would be NaN.
            stderr.WriteLine("avatargo evaluate: the session ends when the calibration completes: no frame was compared");
            return 1;
        }
        if (report.AllJointsMm.Count == 0 && report.AllJointsMm.InvalidCount == 0)
        {
            // A session recorded from a headset (or with its truth lines removed) given an --avatar: it calibrated and
            // solved, but every figure was NaN and the exit code 0 (--json then failed naming a serializer setting).
            stderr.WriteLine("avatargo evaluate: no frame of the session carries the wearer's true joints (a recording from a headset has none; 'simulate' writes sessions that do): nothing to compare");
            return 1;
        }
        if (refine && report.Refinement == null)
        {
            stderr.WriteLine($"avatargo evaluate: the session ended within the {exerciseSeconds.ToString(CultureInfo.InvariantCulture)} s of the exercise: nothing was refined");
            return 1;
        }
        Print(report, stdout);
        if (report.Refinement != null) PrintRefinement(report.Refinement, stdout);
        if (jsonFile != null) OutputFiles.WriteText(jsonFile, w => w.Write(ToJson(report)));
        outputs.Write();
        files.CommitAll();
        outputs.Report(stdout);
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
        SetHintModels(a, settings);
        settings.Tracking.Smoothing = a.Flag("smoothing");
        foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
        {
            settings.Hand(side).Controller = controller;
            settings.Hand(side).Grip = grip;
            settings.Hand(side).Placement = placement;
        }
        return settings;
    }

    /// <summary>The disturbances to inject (--dropout, --noise-mm, --teleport …), or null for none.</summary>
    internal static DisturbanceOptions Disturbance(ArgReader a)
    {
        var d = new DisturbanceOptions
        {
            DropoutRate = (float)a.Double("dropout", 0),
            DropoutMaxSeconds = (float)a.Double("dropout-seconds", 1),
            NoiseMm = (float)a.Double("noise-mm", 0),
            TeleportMetres = (float)a.Double("teleport", 0),
            TeleportSeconds = (float)a.Double("teleport-seconds", 0.1),
            TeleportsPerMinute = (float)a.Double("teleports-per-minute", 1),
            Seed = a.Int("disturb-seed", 1),
        };
        if (!(d.DropoutRate >= 0 && d.DropoutRate <= 0.9)) throw new UsageException("--dropout must be between 0 and 0.9");
        if (!(d.DropoutMaxSeconds > 0 && d.DropoutMaxSeconds <= 60)) throw new UsageException("--dropout-seconds must be between 0 and 60");
        if (!(d.NoiseMm >= 0 && d.NoiseMm <= 1000)) throw new UsageException("--noise-mm must be between 0 and 1000");
        if (!(d.TeleportMetres >= 0 && d.TeleportMetres <= 1000)) throw new UsageException("--teleport must be between 0 and 1000 m");
        if (!(d.TeleportSeconds > 0 && d.TeleportSeconds <= 60)) throw new UsageException("--teleport-seconds must be between 0 and 60");
        if (!(d.TeleportsPerMinute >= 0 && d.TeleportsPerMinute <= 600)) throw new UsageException("--teleports-per-minute must be between 0 and 600");
        return d.IsActive ? d : null;
    }

    // --knee-hint / --elbow-hint: the swivel models (Documentation~/solver.md compares them).
    private static void SetHintModels(ArgReader a, PipelineSettings settings)
    {
        settings.KneeHints = a.String("knee-hint", "outer") switch
        {
            "outer" => KneeHintModel.OuterOfPelvisAndFoot,
            "pelvis-foot" => KneeHintModel.PelvisAndFoot,
            "pelvis" => KneeHintModel.Pelvis,
            "foot" => KneeHintModel.Foot,
            "toes" => KneeHintModel.Toes,
            "ankle-hinge" => KneeHintModel.AnkleHinge,
            "calibration" => KneeHintModel.CalibrationFrame,
            string other => throw new UsageException($"--knee-hint must be outer, pelvis-foot, pelvis, foot, toes, ankle-hinge or calibration, got '{other}'"),
        };
        settings.ElbowHints = a.String("elbow-hint", "hand-axis") switch
        {
            "hand-axis" => ElbowHintModel.HandAxis,
            "down-out-back" => ElbowHintModel.DownOutBack,
            "calibration" => ElbowHintModel.CalibrationFrame,
            string other => throw new UsageException($"--elbow-hint must be hand-axis, down-out-back or calibration, got '{other}'"),
        };
    }

    // A signed difference to one decimal: "+1.2", "-0.3", and "0.0" for what rounds to zero (whose sign would print as "-+0.0").
    internal static string Signed(double value)
    {
        double rounded = Math.Round(value, 1) + 0.0; // + 0.0 turns -0.0 into 0.0
        return rounded == 0.0 ? "0.0" : rounded.ToString("+0.0;-0.0", CultureInfo.InvariantCulture);
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
        if (r.AllJointsMm.InvalidCount > 0)
            o.WriteLine($"non-finite: {r.AllJointsMm.InvalidCount} joint errors were NaN or infinite and are left out of the figures above");
        foreach (BendPlaneReport b in r.BendPlanes)
            if (b.AbsoluteDegrees.InvalidCount > 0)
                o.WriteLine($"non-finite: {b.Joint}'s bend plane on {b.AbsoluteDegrees.InvalidCount} frames (a NaN or infinite avatar joint), left out of its figures");
        if (r.Disturbance != null)
        {
            DisturbanceReport d = r.Disturbance;
            o.WriteLine(string.Create(inv, $"disturbances ({d.DisturbedDeviceFrames} device-frames lost or teleported): largest end-effector jump {d.LargestJumpMm:0.0} mm per frame, {d.LargestExcessJumpMm:0.0} mm beyond the wearer's motion, {d.LargestRecoveryJumpMm:0.0} mm on recovery"));
            Row(o, "  while disturbed (mm)", d.WhileDisturbedMm);
            Row(o, "  after recovery (mm)", d.AfterRecoveryMm);
            Row(o, "  undisturbed (mm)", d.UndisturbedMm);
        }
        PrintBendPlanes(r, o);
        PrintSteadiness(r, o);
        PrintProportions(r, o);
        if (r.Fingers == null) return;
        o.WriteLine(string.Create(inv, $"fingers on the solved body ({r.Fingers.Frames} frames, {r.Fingers.OpenHandFrames} hand-frames open): deepest penetration {r.Fingers.MaxPenetrationMm:0.00} mm"));
        foreach (Finger f in Enum.GetValues<Finger>())
            if (r.Fingers.Gap(f).Count > 0) Row(o, $"  {f} tip gap (mm)", r.Fingers.Gap(f));
    }

    // The refinement from motion: per limb the residual and length before and after, refined or why not.
    internal static void PrintRefinement(RefinementReport r, TextWriter o)
    {
        var inv = CultureInfo.InvariantCulture;
        o.WriteLine(string.Create(inv, $"refinement from motion ({r.Frames} frames{(r.Truncated ? ", truncated" : "")}): proportions {r.Before} -> {r.After}"));
        o.WriteLine("limb         frames  residual before  after (mm)  length before  after (mm)  result");
        foreach (var (name, limb, leg) in RefinementLimbs(r))
            o.WriteLine(string.Create(inv,
                $"  {name,-10} {limb.Samples,6} {Signed(limb.ResidualBefore * 1000),16} {Signed(limb.ResidualAfter * 1000),11} {limb.LengthBefore * 1000,14:0.0} {limb.LengthAfter * 1000,11:0.0}  {(limb.Refined ? "refined" : leg ? "kept (legs are not identifiable)" : "kept (within the tolerance or too few frames)")}"));
        o.WriteLine("  " + r.Explanation);
    }

    private static (string name, LimbRefinement limb, bool leg)[] RefinementLimbs(RefinementReport r) => new[]
    {
        ("left arm", r.Arm(BodySide.Left), false), ("right arm", r.Arm(BodySide.Right), false),
        ("left leg", r.Leg(BodySide.Left), true), ("right leg", r.Leg(BodySide.Right), true),
    };

    internal static object RefinementJson(RefinementReport r) => r == null ? null : new
    {
        frames = r.Frames,
        truncated = r.Truncated,
        changed = r.Changed,
        before = new { left_leg = r.Before.LeftLeg, right_leg = r.Before.RightLeg, left_arm = r.Before.LeftArm, right_arm = r.Before.RightArm },
        after = new { left_leg = r.After.LeftLeg, right_leg = r.After.RightLeg, left_arm = r.After.LeftArm, right_arm = r.After.RightArm },
        limbs = RefinementLimbs(r).ToDictionary(l => l.name.Replace(' ', '_'), l => new
        {
            samples = l.limb.Samples,
            residual_before_mm = OrNull(l.limb.ResidualBefore * 1000.0),
            residual_after_mm = OrNull(l.limb.ResidualAfter * 1000.0),
            length_before_mm = l.limb.LengthBefore * 1000.0,
            length_after_mm = l.limb.LengthAfter * 1000.0,
            refined = l.limb.Refined,
            shoulder_offset_mm = OrNull(l.limb.ShoulderOffset * 1000.0),
            why = l.limb.Refined ? "refined" : l.leg ? "legs are not identifiable (leg length and pelvis strap offset trade off)" : "within the tolerance or too few frames",
        }),
        explanation = r.Explanation,
    };

    // The wearer's true lengths, the measured ones and the calibrated avatar's; the unreachable hands.
    internal static void PrintProportions(EvaluationReport r, TextWriter o)
    {
        var inv = CultureInfo.InvariantCulture;
        CalibrationProfile p = r.Profile;
        o.WriteLine(string.Create(inv, $"scale mode: {p.ScaleMode.ToString().ToLowerInvariant()}, proportions {p.Proportions}; hands unreachable in {r.UnreachedHandFrames} frames, {r.UnreachedWhileBentFrames} of them with the wearer's arm not fully stretched"));
        BodyMeasurements m = p.Measurements, t = r.TrueMeasurements, a = r.AvatarMeasurements;
        if (m == null || a == null) return;
        o.WriteLine("segment (cm)           true   measured   ±     error   avatar   error");
        var measured = m.All();
        var avatar = a.All();
        var truth = t?.All();
        for (int i = 0; i < measured.Length; i++)
        {
            double tv = truth != null ? truth[i].value.Value * 100 : double.NaN, mv = measured[i].value.Value * 100, av = avatar[i].value.Value * 100;
            o.WriteLine(string.Create(inv, $"  {measured[i].name,-18} {tv,7:0.0} {mv,8:0.0} {measured[i].value.Uncertainty * 100,5:0.0} {Signed(mv - tv),7} {av,8:0.0} {Signed(av - tv),7}"));
        }
    }

    internal static object ProportionsJson(EvaluationReport r)
    {
        CalibrationProfile p = r.Profile;
        var rows = new System.Collections.Generic.Dictionary<string, object>();
        if (p.Measurements != null && r.AvatarMeasurements != null)
        {
            var measured = p.Measurements.All();
            var avatar = r.AvatarMeasurements.All();
            var truth = r.TrueMeasurements?.All();
            for (int i = 0; i < measured.Length; i++)
                rows[measured[i].name] = new
                {
                    true_m = truth != null ? truth[i].value.Value : (double?)null,
                    measured_m = measured[i].value.Value,
                    uncertainty_m = measured[i].value.Uncertainty,
                    avatar_m = avatar[i].value.Value,
                };
        }
        return new
        {
            scale_mode = p.ScaleMode.ToString().ToLowerInvariant(),
            left_leg = p.Proportions.LeftLeg, right_leg = p.Proportions.RightLeg, left_arm = p.Proportions.LeftArm, right_arm = p.Proportions.RightArm,
            unreached_while_bent_frames = r.UnreachedWhileBentFrames,
            segments = rows,
        };
    }

    // Knees and elbows bent the wrong way: the bend-plane angle error per joint.
    internal static void PrintBendPlanes(EvaluationReport r, TextWriter o)
    {
        var inv = CultureInfo.InvariantCulture;
        o.WriteLine(string.Create(inv, $"bend plane (deg)       median      p95      max  flipped (>{BendPlaneReport.FlippedDegrees:0} deg)  signed median  straight frames"));
        foreach (BendPlaneReport b in r.BendPlanes)
            o.WriteLine(string.Create(inv,
                $"  {b.Joint,-18} {b.AbsoluteDegrees.Median,8:0.0} {b.AbsoluteDegrees.P95,8:0.0} {b.AbsoluteDegrees.Max,8:0.0}  {b.FlippedShare * 100,8:0.00} %      {b.SignedDegrees.Median,8:0.0}  {b.StraightFrames,8}"));
    }

    private static ErrorSeries MoveBeyond(EvaluationReport r, HumanoidBone bone) => r.JointMoveBeyondWearerMm.TryGetValue(bone, out ErrorSeries s) && s.Count > 0 ? s : null;

    // How much further than the wearer's the knees, elbows, chest and head moved a frame, and every joint's mean p95.
    internal static void PrintSteadiness(EvaluationReport r, TextWriter o)
    {
        var inv = CultureInfo.InvariantCulture;
        o.WriteLine(string.Create(inv, $"steadiness: a joint's move a frame beyond the wearer's (mm), p95 / max and jumps over {EvaluationReport.JumpMm:0} mm; every joint's p95 on average {r.JitterMm:0.00} mm"));
        foreach (HumanoidBone bone in new[] { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg, HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm, HumanoidBone.Chest, HumanoidBone.Head })
            if (r.JointMoveBeyondWearerMm.TryGetValue(bone, out ErrorSeries s) && s.Count > 0)
                o.WriteLine(string.Create(inv, $"  {bone,-18} {s.P95,8:0.0} {s.Max,8:0.0}  {s.ShareAbove(EvaluationReport.JumpMm) * 100,6:0.0} %"));
    }

    internal static object BendPlanesJson(EvaluationReport r) => r.BendPlanes.ToDictionary(b => b.Joint.ToString(), b => new
    {
        median_deg = OrNull(b.AbsoluteDegrees.Median),
        p95_deg = OrNull(b.AbsoluteDegrees.P95),
        max_deg = OrNull(b.AbsoluteDegrees.Max),
        signed_median_deg = OrNull(b.SignedDegrees.Median),
        flipped_share = b.FlippedShare,
        flipped_frames = b.FlippedFrames,
        frames = b.AbsoluteDegrees.Count,
        straight_frames = b.StraightFrames,
        non_finite_frames = b.AbsoluteDegrees.InvalidCount,
    });

    // JSON has no NaN: a statistic of no frames is null.
    private static double? OrNull(double v) => double.IsNaN(v) ? null : v;

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
            non_finite_joint_errors = r.AllJointsMm.InvalidCount,
            proportions = ProportionsJson(r),
            role_swaps = r.RoleSwaps,
            jitter_mm = OrNull(r.JitterMm),
            joints = r.JointPositionMm.OrderBy(p => p.Key).ToDictionary(p => p.Key.ToString(), p => new
            {
                median_mm = p.Value.Median, p95_mm = p.Value.P95, max_mm = p.Value.Max,
                move_beyond_wearer_p95_mm = OrNull(MoveBeyond(r, p.Key)?.P95 ?? double.NaN),
                jump_share = OrNull(MoveBeyond(r, p.Key)?.ShareAbove(EvaluationReport.JumpMm) ?? double.NaN),
            }),
            disturbance = r.Disturbance == null ? null : new
            {
                disturbed_device_frames = r.Disturbance.DisturbedDeviceFrames,
                largest_jump_mm = r.Disturbance.LargestJumpMm,
                largest_excess_jump_mm = r.Disturbance.LargestExcessJumpMm,
                largest_recovery_jump_mm = r.Disturbance.LargestRecoveryJumpMm,
                largest_recovery_jump_joint = r.Disturbance.LargestRecoveryJumpJoint.ToString(),
                largest_recovery_jump_time_s = double.IsNaN(r.Disturbance.LargestRecoveryJumpTime) ? (double?)null : r.Disturbance.LargestRecoveryJumpTime,
                largest_excess_jump_joint = r.Disturbance.LargestExcessJumpJoint.ToString(),
                largest_excess_jump_time_s = double.IsNaN(r.Disturbance.LargestExcessJumpTime) ? (double?)null : r.Disturbance.LargestExcessJumpTime,
                while_disturbed_mm = Stats(r.Disturbance.WhileDisturbedMm),
                after_recovery_mm = Stats(r.Disturbance.AfterRecoveryMm),
                undisturbed_mm = Stats(r.Disturbance.UndisturbedMm),
            },
            bend_plane = BendPlanesJson(r),
            refinement = RefinementJson(r.Refinement),
            fingers = r.Fingers == null ? null : new
            {
                frames = r.Fingers.Frames,
                open_hand_frames = r.Fingers.OpenHandFrames,
                max_penetration_mm = r.Fingers.MaxPenetrationMm,
                tip_gap_mm = Enum.GetValues<Finger>().Where(f => r.Fingers.Gap(f).Count > 0)
                    .ToDictionary(f => f.ToString(), f => new { median = r.Fingers.Gap(f).Median, p95 = r.Fingers.Gap(f).P95, max = r.Fingers.Gap(f).Max }),
            },
        };
        return JsonReports.Serialize(doc);
    }

    private static object Stats(ErrorSeries s) =>
        s.Count == 0 ? null : new { samples = s.Count, median = s.Median, mean = s.Mean, p95 = s.P95, max = s.Max };
}
