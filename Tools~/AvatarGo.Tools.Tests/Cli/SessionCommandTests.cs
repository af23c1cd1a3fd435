using System;
using System.IO;
using System.Numerics;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class SessionCommandTests
{
    private static string WriteSession(int frames, bool complete = true)
    {
        string path = Path.Combine(Path.GetTempPath(), "avatargo-info-" + Guid.NewGuid().ToString("N") + ".agsession");
        var h = new SessionHeader(72f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H"), new DeviceInfo(2, DeviceClass.Controller, "C") },
            new[] { DeviceRole.Head, DeviceRole.RightHand });
        var text = new StringWriter();
        using (var w = new SessionWriter(text, h))
        {
            var f = new SessionFrame(h);
            for (int i = 0; i < frames; i++)
            {
                f.Clear();
                f.Time = i / 72.0;
                f.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 1.6f, 0), Quaternion.Identity), true);
                f.Samples[1] = new DeviceSample(new RigidPose(new Vector3(0.3f, 1.1f, 0.2f), Quaternion.Identity), i % 4 != 0);
                if (i < 3) f.Trigger[1] = 0.5f;
                if (i == 10) f.Events.Add(new DeviceEvent(2, DeviceEventKind.TriggerPressed));
                w.WriteFrame(f);
            }
            if (!complete) { File.WriteAllText(path, text.ToString()); return path; }
        }
        File.WriteAllText(path, text.ToString());
        return path;
    }

    [Test]
    public void InfoCountsFramesAndEvents()
    {
        string path = WriteSession(145);
        try
        {
            var r = CliRunner.Run("session", "info", path);
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
            StringAssert.Contains("frames: 145, duration 2 s", r.Stdout);
            StringAssert.Contains("1 trigger presses", r.Stdout);
            StringAssert.Contains("true role RightHand; tracked 74.5% of frames, analog input in 3 frames", r.Stdout); // lost when i % 4 == 0: 37 of 145 frames, 108/145 = 74.48%
            StringAssert.Contains("true role Head; tracked 100% of frames", r.Stdout);
        }
        finally { File.Delete(path); }
    }

    [Test]
    public void TruncatedSessionIsAOneLineErrorWithExitCode1()
    {
        string path = WriteSession(20, complete: false);
        try
        {
            var r = CliRunner.Run("session", "info", path);
            Assert.That(r.ExitCode, Is.EqualTo(1));
            Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1));
            StringAssert.Contains("truncated", r.Stderr);
        }
        finally { File.Delete(path); }
    }

    [TestCase("avatargo-session 2.0", "x.agsession:1: format version 2.0 is not supported")]
    [TestCase("HIERARCHY", "x.agsession:1: not an AvatarGo session")]
    [TestCase("", "x.agsession:1: the file is empty")]
    public void BadFilesGiveExitCode1AndOneLineNamingTheLine(string firstLine, string expected)
    {
        string dir = Path.Combine(Path.GetTempPath(), "avatargo-info-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        string path = Path.Combine(dir, "x.agsession");
        try
        {
            File.WriteAllText(path, firstLine.Length == 0 ? "" : firstLine + "\nunits m s\n");
            var r = CliRunner.Run("session", "info", path);
            Assert.That(r.ExitCode, Is.EqualTo(1));
            Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1), r.Stderr);
            StringAssert.Contains(expected, r.Stderr);
            Assert.That(r.Stdout, Is.Empty, "nothing printed for a bad file");
        }
        finally { Directory.Delete(dir, true); }
    }

    [Test]
    public void InfoReportsGroundTruth()
    {
        string path = Path.Combine(Path.GetTempPath(), "avatargo-info-" + Guid.NewGuid().ToString("N") + ".agsession");
        try
        {
            var names = new[] { "Hips", "Spine", "Head" };
            var rest = new[] { new RigidPose(new Vector3(0, 1, 0), Quaternion.Identity), new RigidPose(new Vector3(0, 0.2f, 0), Quaternion.Identity), new RigidPose(new Vector3(0, 0.5f, 0), Quaternion.Identity) };
            var skeleton = new Skeleton(names, new[] { -1, 0, 1 }, rest);
            var map = new HumanoidMap(skeleton, new[]
            {
                new System.Collections.Generic.KeyValuePair<HumanoidBone, string>(HumanoidBone.Hips, "Hips"),
                new System.Collections.Generic.KeyValuePair<HumanoidBone, string>(HumanoidBone.Head, "Head"),
            });
            var h = new SessionHeader(90f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "H") }, new[] { DeviceRole.Head }, map);
            using (var w = SessionWriter.Create(path, h))
            {
                var f = new SessionFrame(h);
                for (int i = 0; i < 10; i++)
                {
                    f.Clear();
                    f.Time = i / 90.0;
                    f.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 1.7f, 0), Quaternion.Identity), true);
                    if (i < 4) { f.Truth[(int)HumanoidBone.Head] = new RigidPose(new Vector3(0, 1.7f, 0), Quaternion.Identity); f.HasTruth[(int)HumanoidBone.Head] = true; }
                    w.WriteFrame(f);
                }
            }
            var r = CliRunner.Run("session", "info", path);
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
            StringAssert.Contains("ground truth: skeleton of 3 joints (2 humanoid bones), 4 frames with joint poses", r.Stdout);
            StringAssert.Contains("true role Head", r.Stdout);
        }
        finally { File.Delete(path); }
    }
}
