using System;
using System.Text.Json;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class FingersCommandTests : TempFolderTests
{
    [Test]
    public void ReportsEveryProfileAndHandWithoutAllocatingPerFrame()
    {
        var r = CliRunner.Run("fingers", "--json", "--hand", "reference");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        using var doc = JsonDocument.Parse(r.Stdout);
        int rows = 0;
        foreach (var row in doc.RootElement.GetProperty("results").EnumerateArray())
        {
            rows++;
            string what = row.GetProperty("profile").GetString() + " " + row.GetProperty("hand").GetString();
            Assert.That(row.GetProperty("bytes_per_frame").GetDouble(), Is.EqualTo(0.0), what);
            // The grip is a function of the controller pose alone: identical at 72, 90 and 144 Hz.
            Assert.That(row.GetProperty("max_t_difference").GetDouble(), Is.LessThanOrEqualTo(0.02), what);
            // The bounds: fingertip gap median within 3 mm, the thumb's too; penetration within 1 mm.
            Assert.That(row.GetProperty("tip_gap_median_mm").GetDouble(), Is.LessThanOrEqualTo(3.0), what);
            Assert.That(row.GetProperty("thumb_gap_median_mm").GetDouble(), Is.LessThanOrEqualTo(3.0), what);
            Assert.That(row.GetProperty("max_penetration_mm").GetDouble(), Is.LessThanOrEqualTo(1.0), what);
            // The skin between the points sees at least what the points see, and no bone lies inside (the reference hand's
            // finger radius is 8.5 mm).
            double skin = row.GetProperty("max_skin_depth_mm").GetDouble();
            Assert.That(skin, Is.GreaterThanOrEqualTo(row.GetProperty("max_penetration_mm").GetDouble() - 1e-3).And.LessThan(8.5), what + ": skin depth");
            var medians = row.GetProperty("tip_gap_median_mm_by_finger");
            Assert.That(medians.GetArrayLength(), Is.EqualTo(5), what);
            foreach (var m in medians.EnumerateArray()) Assert.That(m.GetDouble(), Is.LessThanOrEqualTo(3.0), what + ": every fingertip");
            // Thumb first (thumb_gap_median_mm is signed, the per-finger figures are distances).
            Assert.That(medians[0].GetDouble(), Is.EqualTo(Math.Abs(row.GetProperty("thumb_gap_median_mm").GetDouble())).Within(0.05), what + ": thumb first");
            // The thumb's pad lies on the controller's head, within 25 mm of the thumb rest (the heads' top faces are
            // 40-52 mm deep); the index's pad is on the trigger's side, within 30 mm of the trigger.
            Assert.That(row.GetProperty("thumb_to_rest_median_mm").GetDouble(), Is.LessThanOrEqualTo(25.0), what);
            Assert.That(row.GetProperty("index_to_trigger_median_mm").GetDouble(), Is.LessThanOrEqualTo(30.0), what);
        }
        Assert.That(rows, Is.EqualTo(6), "three profiles, two hands");
    }

    /// <summary>
    /// A BVH rig's hand is measured as the pipeline opens it, from its calibration T-pose: the same clip with every joint's
    /// rest frame at random gives the same figures (found in review: the command measured the rest pose's hand, whose thumb
    /// lay 8.2 mm from the VIVE wand's rest where the pipeline's lies 1.2 mm, and which a rest convention changes).
    /// </summary>
    [Test]
    public void ABvhHandIsMeasuredInItsTPoseWhateverItsRest()
    {
        string clip = Paths.Mocap("mixamo_fingers_30fps.bvh"), random = System.IO.Path.Combine(Dir, "random.bvh");
        Assert.That(CliRunner.Run("bvh", "rebase", clip, random, "--rest", "random", "--seed", "2").ExitCode, Is.EqualTo(0));
        JsonElement Rows(string file)
        {
            var r = CliRunner.Run("fingers", "--json", "--profile", "vive-wand", "--hand", file);
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
            return JsonDocument.Parse(r.Stdout).RootElement.GetProperty("results").Clone();
        }
        JsonElement own = Rows(clip), rebased = Rows(random);
        Assert.That(rebased.GetArrayLength(), Is.EqualTo(own.GetArrayLength()));
        for (int i = 0; i < own.GetArrayLength(); i++)
            foreach (string figure in new[] { "thumb_to_rest_median_mm", "index_to_trigger_median_mm", "tip_gap_median_mm", "thumb_gap_median_mm", "max_penetration_mm" })
                Assert.That(rebased[i].GetProperty(figure).GetDouble(), Is.EqualTo(own[i].GetProperty(figure).GetDouble()).Within(0.1), figure + " " + own[i].GetProperty("hand").GetString());
    }

    [Test]
    public void ByDefaultMeasuresTheReferenceHandAndTheMixamoHand()
    {
        Paths.Mocap("mixamo_fingers_30fps.bvh");
        var r = CliRunner.Run("fingers", "--json", "--profile", "vive-wand");
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        using var doc = JsonDocument.Parse(r.Stdout);
        var rigs = new System.Collections.Generic.List<string>();
        foreach (var row in doc.RootElement.GetProperty("results").EnumerateArray())
        {
            rigs.Add(row.GetProperty("rig").GetString());
            string what = row.GetProperty("rig").GetString() + " " + row.GetProperty("hand").GetString();
            Assert.That(row.GetProperty("max_penetration_mm").GetDouble(), Is.LessThanOrEqualTo(1.0), what);
            Assert.That(row.GetProperty("tip_gap_median_mm").GetDouble(), Is.LessThanOrEqualTo(3.0), what);
            Assert.That(row.GetProperty("thumb_gap_median_mm").GetDouble(), Is.LessThanOrEqualTo(3.0), what);
        }
        Assert.That(rigs, Is.EqualTo(new[] { "reference", "reference", "mixamo_fingers_30fps.bvh", "mixamo_fingers_30fps.bvh" }));
    }
}
