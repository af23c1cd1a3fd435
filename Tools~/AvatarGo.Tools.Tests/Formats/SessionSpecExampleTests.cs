using System.IO;
using System.Text.RegularExpressions;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Formats;

/// <summary>The example in Documentation~/session-format.md is a valid session and says what the text around it says.</summary>
public class SessionSpecExampleTests
{
    private static string Example()
    {
        string doc = File.ReadAllText(Path.Combine(Paths.PackageRoot, "Documentation~", "session-format.md"));
        Match m = Regex.Match(doc, @"## Example\n[^`]*```\n(.*?)```", RegexOptions.Singleline);
        Assert.That(m.Success, Is.True, "the spec has an Example section with a fenced block");
        return m.Groups[1].Value;
    }

    [Test]
    public void TheSpecExampleReads()
    {
        using var r = new SessionReader(new StringReader(Example()), "session-format.md");
        SessionHeader h = r.Header;
        Assert.That(h.Rate, Is.EqualTo(90f));
        Assert.That(h.Devices.Count, Is.EqualTo(3));
        Assert.That(h.Devices[2].RuntimeRole, Is.EqualTo(DeviceRole.Pelvis));
        Assert.That(h.TrueRole(1), Is.EqualTo(DeviceRole.LeftHand));
        Assert.That(h.TruthHumanoid.Skeleton.JointCount, Is.EqualTo(4));
        Assert.That(h.TruthHumanoid.NameOf(HumanoidBone.Spine), Is.EqualTo("Chest"));
        Assert.That(h.TruthHumanoid.Skeleton.IsEndSite(3), Is.True);
        SessionFrame f = r.CreateFrame();
        Assert.That(r.ReadFrame(f), Is.True);
        Assert.That(f.Samples[2].IsTracked, Is.False);
        Assert.That(f.Samples[2].Pose.IsValid, Is.True, "the lost zero quaternion is delivered as a valid pose");
        Assert.That(f.Grip[1], Is.EqualTo(0.95f));
        Assert.That(f.HasTruth[(int)HumanoidBone.Head], Is.True);
        Assert.That(r.ReadFrame(f), Is.True);
        Assert.That(f.Time, Is.EqualTo(1 / 90.0));
        Assert.That(f.Grip[1], Is.NaN);
        Assert.That(f.Events.Count, Is.EqualTo(1));
        Assert.That(f.Events[0].DeviceId, Is.EqualTo(1));
        Assert.That(f.HasTruth[(int)HumanoidBone.Head], Is.False);
        Assert.That(r.ReadFrame(f), Is.False);
    }
}
