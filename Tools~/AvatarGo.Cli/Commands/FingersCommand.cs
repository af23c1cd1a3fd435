using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text.Json;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo fingers`: finger IK on every controller profile, under a moving controller, at 72/90/144 Hz.</summary>
public sealed class FingersCommand : ICommand
{
    public string Name => "fingers";
    public string Summary => "Finger IK on each controller profile: penetration, fingertip gaps, cost, frame-rate independence";
    public string Help => """
        avatargo fingers [--profile NAME] [--hand reference|BVH] [--json]

        Holds each controller profile (Runtime/ControllerProfiles/*.json) in both hands of each avatar
        hand (default: the reference hand built in code, ReferenceHandRig, and the Mixamo hand of the
        clip mixamo_fingers_30fps.bvh the package ships in Tests/Core/Data~; a BVH rig's hand opened as the
        pipeline opens it, from its calibration T-pose) while the controller wobbles in
        the hand for two seconds (2 mm, 3 deg), solving at 72, 90 and 144 Hz, and reports per profile and
        hand: the deepest penetration of a finger into the surface at the three points the IK keeps out
        (mm); the deepest skin anywhere along the fingers, knuckle to tip (skin depth, mm: a straight
        phalanx between two of those points can cross the handle); the median and largest fingertip gap
        (mm), iterations and microseconds per frame for both hands, bytes allocated per frame, and the
        largest difference in the final joint parameters t between the three frame rates. Fingertip gaps
        are of the four fingers; the thumb tip's gap is reported apart (thumb_gap_median_mm; with --json
        every fingertip's median and largest gap too, thumb first: tip_gap_median_mm_by_finger,
        tip_gap_max_mm_by_finger), with how far (median) the thumb's and the index's pads are from resting
        on the profile's thumb rest and trigger (FingerSolver.GoalDistance).
          --profile NAME   only this profile (file name without .json)
          --hand WHICH     only this hand: "reference", or a BVH file of a rig with finger bones
          --json           print JSON
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "json");
        string only = a.String("profile");
        string handFile = a.String("hand");
        bool json = a.Flag("json");
        a.ThrowOnUnknown(0);

        var profiles = ControllerProfiles.All().Where(p => only == null || p.Name == only).ToList();
        if (profiles.Count == 0) throw new UsageException($"no controller profile named '{only}' in {ControllerProfiles.Folder()}");
        var rigs = new List<(string Name, HumanoidMap Map)>();
        if (handFile == null || handFile == "reference") rigs.Add(("reference", ReferenceHandRig.Build()));
        if (handFile == null) handFile = FindMixamoHand();
        if (handFile != null && handFile != "reference")
            rigs.Add((Path.GetFileName(handFile), HumanoidNaming.Detect(BvhReader.ReadFile(handFile, new BvhReadOptions { ToMetres = true }).Skeleton)));

        // Warm up for a second so that .NET's tiered JIT has optimised the solver before anything is timed.
        var warm = Stopwatch.StartNew();
        while (warm.ElapsedMilliseconds < 1000) Measure(rigs[0].Map, true, profiles[0]);
        var rows = new List<Dictionary<string, object>>();
        foreach (var rig in rigs)
            foreach (ControllerProfile profile in profiles)
                foreach (bool left in new[] { true, false })
                {
                    var row = new Dictionary<string, object> { ["rig"] = rig.Name };
                    foreach (var pair in Measure(rig.Map, left, profile)) row[pair.Key] = pair.Value;
                    rows.Add(row);
                }
        if (json)
        {
            stdout.WriteLine(JsonReports.Serialize(new { machine = BenchCommand.Machine(), results = rows }));
            return 0;
        }
        stdout.WriteLine("controller wobbling 2 mm / 3 deg in the hand for 2 s; fingertip gaps of the four fingers; the thumb's apart");
        stdout.WriteLine("rig                        profile       hand   penetration  skin depth  tip gap median/max   thumb gap  thumb-rest  index-trigger  iterations  us/frame  bytes/frame  max dt(72,90,144 Hz)");
        foreach (var r in rows)
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{r["rig"],-26} {r["profile"],-13} {r["hand"],-6} {r["max_penetration_mm"],8:0.00} mm {r["max_skin_depth_mm"],7:0.0} mm   {r["tip_gap_median_mm"],6:0.0} / {r["tip_gap_max_mm"],-6:0.0} mm {r["thumb_gap_median_mm"],6:0.0} mm {r["thumb_to_rest_median_mm"],7:0.0} mm {r["index_to_trigger_median_mm"],9:0.0} mm  {r["iterations_per_frame"],9:0.0} {r["us_per_frame"],9:0.0} {r["bytes_per_frame"],10:0} {r["max_t_difference"],12:0.000}"));
        return 0;
    }

    private static Dictionary<string, object> Measure(HumanoidMap rig, bool left, ControllerProfile profile)
    {
        // The open hand the pipeline uses: a humanoid's calibration T-pose (its relaxed fingers); a hand-only rig's rest.
        var pose = new SkeletonPose(rig.Skeleton);
        if (rig.IsComplete) TPoser.Apply(rig, pose, RigidPose.Identity);
        else pose.ResetToRest();
        var hand = new HandModel(rig, left ? BodySide.Left : BodySide.Right, pose);
        RigidPose inHand = hand.ControllerInHand(profile);
        int[] rates = { 72, 90, 144 };
        var finals = new float[rates.Length][];
        double penetration = 0, skinDepth = 0;
        long bytes = 0;
        int frames = 0, iterations = 0;
        var gaps = new List<double>();
        var byFinger = new List<double>[5];
        for (int f = 0; f < 5; f++) byFinger[f] = new List<double>();
        var thumbGaps = new List<double>();
        var thumbToRest = new List<double>();
        var indexToTrigger = new List<double>();
        for (int r = 0; r < rates.Length; r++)
        {
            var solver = new FingerSolver(hand, profile);
            int n = rates[r] * 2;
            for (int i = 0; i <= n; i++)
            {
                float t = i / (float)rates[r];
                var wobble = new RigidPose(new Vector3(0.002f * MathF.Sin(5 * t), 0.002f * MathF.Cos(3 * t), 0.001f * MathF.Sin(7 * t)), Rotations.AngleAxis(3f * MathF.Sin(4 * t), Vector3.UnitY));
                RigidPose controller = inHand * wobble;
                long before = GC.GetAllocatedBytesForCurrentThread();
                solver.Solve(RigidPose.Identity, controller, GripMode.Hold);
                bytes += GC.GetAllocatedBytesForCurrentThread() - before;
                frames++;
                iterations += solver.LastIterations;
                for (int f = 0; f < 5; f++)
                {
                    if (!hand.Has((Finger)f)) continue;
                    for (int p = 0; p < 3; p++) penetration = Math.Max(penetration, -solver.SurfaceGap((Finger)f, (FingerPoint)p));
                    skinDepth = Math.Max(skinDepth, solver.SkinDepth((Finger)f));
                    byFinger[f].Add(Math.Abs(solver.SurfaceGap((Finger)f, FingerPoint.Tip)) * 1000.0); // a tip inside the surface is off it too
                    if (f > 0) gaps.Add(solver.SurfaceGap((Finger)f, FingerPoint.Tip) * 1000.0);
                    else thumbGaps.Add(solver.SurfaceGap((Finger)f, FingerPoint.Tip) * 1000.0);
                }
                if (hand.Has(Finger.Thumb)) thumbToRest.Add(solver.GoalDistance(Finger.Thumb) * 1000.0);
                indexToTrigger.Add(solver.GoalDistance(Finger.Index) * 1000.0);
            }
            finals[r] = solver.Parameters.ToArray();
        }
        gaps.Sort();
        foreach (var list in byFinger) list.Sort();
        thumbGaps.Sort();
        thumbToRest.Sort();
        indexToTrigger.Sort();
        double maxDiff = 0;
        for (int i = 0; i < FingerParameters.Count; i++)
            for (int r = 1; r < rates.Length; r++) maxDiff = Math.Max(maxDiff, Math.Abs(finals[r][i] - finals[0][i]));
        // Timing: the 90 Hz sequence replayed 7 times, keeping the fastest pass (the machine may be busy with
        // other work; the fastest pass is the solver's own cost).
        var timed = new FingerSolver(hand, profile);
        var poses = new RigidPose[181];
        for (int i = 0; i < poses.Length; i++)
        {
            float t = i / 90f;
            poses[i] = inHand * new RigidPose(new Vector3(0.002f * MathF.Sin(5 * t), 0.002f * MathF.Cos(3 * t), 0.001f * MathF.Sin(7 * t)), Rotations.AngleAxis(3f * MathF.Sin(4 * t), Vector3.UnitY));
        }
        double best = double.MaxValue;
        for (int pass = 0; pass < 7; pass++)
        {
            long t0 = Stopwatch.GetTimestamp();
            for (int i = 0; i < poses.Length; i++) timed.Solve(RigidPose.Identity, poses[i], GripMode.Hold);
            best = Math.Min(best, (Stopwatch.GetTimestamp() - t0) / (double)poses.Length);
        }
        double usPerHand = best * 1e6 / Stopwatch.Frequency;
        return new Dictionary<string, object>
        {
            ["profile"] = profile.Name,
            ["hand"] = left ? "left" : "right",
            ["max_penetration_mm"] = penetration * 1000.0,
            ["max_skin_depth_mm"] = skinDepth * 1000.0,
            ["tip_gap_median_mm"] = gaps[gaps.Count / 2],
            ["tip_gap_max_mm"] = gaps[^1],
            // Per fingertip, thumb first (null for a finger the rig does not have).
            ["tip_gap_median_mm_by_finger"] = byFinger.Select(l => l.Count > 0 ? l[l.Count / 2] : (double?)null).ToArray(),
            ["tip_gap_max_mm_by_finger"] = byFinger.Select(l => l.Count > 0 ? l[^1] : (double?)null).ToArray(),
            ["thumb_gap_median_mm"] = thumbGaps.Count > 0 ? thumbGaps[thumbGaps.Count / 2] : (object)null,
            ["thumb_to_rest_median_mm"] = thumbToRest.Count > 0 ? thumbToRest[thumbToRest.Count / 2] : (object)null,
            ["index_to_trigger_median_mm"] = indexToTrigger[indexToTrigger.Count / 2],
            ["iterations_per_frame"] = iterations / (double)frames,
            ["us_per_frame"] = usPerHand * 2, // both hands
            ["bytes_per_frame"] = bytes / (double)frames,
            ["max_t_difference"] = maxDiff,
        };
    }

    private static string FindMixamoHand()
    {
        for (string dir = AppContext.BaseDirectory; dir != null; dir = Path.GetDirectoryName(dir))
        {
            string candidate = Path.Combine(dir, "Tests", "Core", "Data~", "mixamo_fingers_30fps.bvh");
            if (File.Exists(candidate)) return Path.GetFullPath(candidate);
        }
        return null;
    }
}
