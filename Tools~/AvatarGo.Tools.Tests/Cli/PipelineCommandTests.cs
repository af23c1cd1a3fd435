using System.IO;
using System.Text.Json;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class PipelineCommandTests
{
    [Test]
    public void BenchAllocatesNothingPerFrame()
    {
        var r = CliRunner.Run("bench", "--json", "--runs", "3", "--warmup", "0.2");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        using var doc = JsonDocument.Parse(r.Stdout);
        Assert.That(doc.RootElement.GetProperty("frames").GetInt32(), Is.GreaterThan(250), "every frame of the Mixamo clip after calibration");
        Assert.That(doc.RootElement.GetProperty("avatars_per_core_at_90hz").GetDouble(), Is.GreaterThan(0));
        var cases = doc.RootElement.GetProperty("cases");
        Assert.That(cases[0].GetProperty("name").GetString(), Does.StartWith("whole pipeline"), "the headline case");
        Assert.That(cases.GetArrayLength(), Is.EqualTo(6), "whole, body only, fingers, fingers descended every frame, targets, IK");
        foreach (var c in cases.EnumerateArray())
        {
            // Exactly zero: per-frame paths must not allocate (a GC stall is a dropped frame in VR).
            Assert.That(c.GetProperty("bytes_per_frame").GetDouble(), Is.EqualTo(0.0), c.GetProperty("name").GetString());
            Assert.That(c.GetProperty("ns_per_frame_median").GetDouble(), Is.GreaterThan(0.0));
        }
    }

    [Test]
    public void BenchWithFewFramesAllocatesNothingPerFrame()
    {
        var r = CliRunner.Run("bench", "--frames", "200", "--json", "--runs", "3", "--warmup", "0.2", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--controller", "quest-touch");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        using var doc = JsonDocument.Parse(r.Stdout);
        Assert.That(doc.RootElement.GetProperty("frames").GetInt32(), Is.EqualTo(200));
        Assert.That(doc.RootElement.GetProperty("frames_per_pass").GetInt32(), Is.EqualTo(398), "played forward and back: 200 + 198");
        Assert.That(doc.RootElement.GetProperty("cases").GetArrayLength(), Is.EqualTo(4), "no finger case for an avatar without finger bones");
        foreach (var c in doc.RootElement.GetProperty("cases").EnumerateArray())
            Assert.That(c.GetProperty("bytes_per_frame").GetDouble(), Is.EqualTo(0.0), c.GetProperty("name").GetString());
    }

    [Test]
    public void DemoComparesExactAndFixedOffsetsAndWritesTheSolvedAvatar()
    {
        string bvh = Path.Combine(Path.GetTempPath(), "avatargo-demo-test-" + System.Guid.NewGuid().ToString("N") + ".bvh");
        try
        {
            var r = CliRunner.Run("demo", "--out-bvh", bvh);
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
            StringAssert.Contains("exact offsets", r.Stdout);
            StringAssert.Contains("fixed offsets", r.Stdout);
            var info = CliRunner.Run("bvh", "info", bvh);
            Assert.That(info.ExitCode, Is.EqualTo(0), info.Stderr);
            StringAssert.Contains("missing required: none", info.Stdout);
        }
        finally { File.Delete(bvh); }
    }

    [Test]
    public void SimulateThenEvaluateWritesTheIssuesJsonKeys()
    {
        string session = Path.Combine(Path.GetTempPath(), "avatargo-sim-" + System.Guid.NewGuid().ToString("N") + ".agsession");
        string json = session + ".json";
        try
        {
            var s = CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", session, "--seed", "5");
            Assert.That(s.ExitCode, Is.EqualTo(0), s.Stderr);
            var e = CliRunner.Run("evaluate", session, "--mode", "fixed", "--json", json);
            Assert.That(e.ExitCode, Is.EqualTo(0), e.Stderr);
            using var doc = JsonDocument.Parse(File.ReadAllText(json));
            var root = doc.RootElement;
            foreach (string key in new[] { "mode", "frames", "end_effector_median_mm", "end_effector_p95_mm", "mid_median_mm", "mpjpe_mm", "knee_angle_error_deg", "joints" })
                Assert.That(root.TryGetProperty(key, out _), Is.True, key);
            Assert.That(root.GetProperty("mode").GetString(), Is.EqualTo("fixed"));
            Assert.That(root.GetProperty("joints").GetProperty("Hips").GetProperty("median_mm").GetDouble(), Is.GreaterThan(50), "fixed offsets put the hips at the tracker, centimetres away");
        }
        finally { File.Delete(session); File.Delete(json); }
    }

    /// <summary>
    /// simulate --exercise-seconds, then evaluate --refine: mocapbank's hands have no finger bones (wrists placed by the
    /// walk-in's offset), the avatar's arms are 10 % short under uniform scaling; the report shows the arms' residual
    /// before (the centimetres they lack), refines them, and reports the legs without refining them.
    /// </summary>
    [Test]
    public void SimulateWithTheExerciseThenEvaluateRefinedPrintsTheRefinement()
    {
        string session = Path.Combine(Path.GetTempPath(), "avatargo-refine-" + System.Guid.NewGuid().ToString("N") + ".agsession");
        string json = session + ".json";
        try
        {
            var s = CliRunner.Run("simulate", "--bvh", Paths.Mocap("mocapbank_30fps.bvh"), "--out", session, "--exercise-seconds", "8");
            Assert.That(s.ExitCode, Is.EqualTo(0), s.Stderr);
            var e = CliRunner.Run("evaluate", session, "--refine", "--exercise-seconds", "8", "--arm-scale", "0.9", "--leg-scale", "1.1", "--json", json);
            Assert.That(e.ExitCode, Is.EqualTo(0), e.Stderr);
            StringAssert.Contains("refinement from motion", e.Stdout);
            StringAssert.Contains("left arm", e.Stdout);
            StringAssert.Contains("kept (legs are not identifiable)", e.Stdout);
            using var doc = JsonDocument.Parse(File.ReadAllText(json));
            int refinedFrames = doc.RootElement.GetProperty("frames").GetInt32();
            var r = doc.RootElement.GetProperty("refinement");
            Assert.That(r.GetProperty("changed").GetBoolean(), Is.True);
            Assert.That(r.GetProperty("frames").GetInt32(), Is.GreaterThan(600), "8 s at 90 Hz");
            foreach (string arm in new[] { "left_arm", "right_arm" })
            {
                var l = r.GetProperty("limbs").GetProperty(arm);
                Assert.That(l.GetProperty("refined").GetBoolean(), Is.True, arm);
                Assert.That(l.GetProperty("residual_before_mm").GetDouble(), Is.GreaterThan(40.0), arm + ": the arm was short");
                Assert.That(System.Math.Abs(l.GetProperty("residual_after_mm").GetDouble()), Is.LessThan(10.0), arm + ": reachable after");
                Assert.That(l.GetProperty("length_after_mm").GetDouble(), Is.GreaterThan(l.GetProperty("length_before_mm").GetDouble() + 40.0), arm);
            }
            foreach (string leg in new[] { "left_leg", "right_leg" })
                Assert.That(r.GetProperty("limbs").GetProperty(leg).GetProperty("refined").GetBoolean(), Is.False, leg);
            // Without --refine the same session has no refinement.
            var plain = CliRunner.Run("evaluate", session, "--json", json);
            Assert.That(plain.ExitCode, Is.EqualTo(0), plain.Stderr);
            using var doc2 = JsonDocument.Parse(File.ReadAllText(json));
            Assert.That(doc2.RootElement.GetProperty("refinement").ValueKind, Is.EqualTo(JsonValueKind.Null));
            Assert.That(doc2.RootElement.GetProperty("frames").GetInt32(), Is.GreaterThan(refinedFrames + 600), "plain: the exercise is scored");
            // With --exercise-seconds alone the exercise is not scored, and the same frames as --refine's are (found in
            // review: the option was ignored without --refine, and the frame the refinement ends on was scored only then).
            var unrefined = CliRunner.Run("evaluate", session, "--exercise-seconds", "8", "--json", json);
            Assert.That(unrefined.ExitCode, Is.EqualTo(0), unrefined.Stderr);
            using var doc3 = JsonDocument.Parse(File.ReadAllText(json));
            Assert.That(doc3.RootElement.GetProperty("frames").GetInt32(), Is.EqualTo(refinedFrames), "the frames --refine scores");
            Assert.That(doc3.RootElement.GetProperty("refinement").ValueKind, Is.EqualTo(JsonValueKind.Null));
            var bad = CliRunner.Run("evaluate", session, "--refine", "--dropout", "0.1");
            Assert.That(bad.ExitCode, Is.EqualTo(2), "--refine with disturbances is refused");
        }
        finally { File.Delete(session); File.Delete(json); }
    }
}
