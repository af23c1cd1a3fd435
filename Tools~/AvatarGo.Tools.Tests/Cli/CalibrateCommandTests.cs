using System.IO;
using System.Text.Json;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class CalibrateCommandTests
{
    [Test]
    public void CalibratesASimulatedSessionAndSavesAProfile()
    {
        string session = Path.Combine(Path.GetTempPath(), "avatargo-cal-" + System.Guid.NewGuid().ToString("N") + ".agsession");
        string profile = session + ".profile.json";
        try
        {
            Assert.That(CliRunner.Run("simulate", "--bvh", Paths.Mocap("mixamo_fingers_30fps.bvh"), "--out", session, "--seed", "9").ExitCode, Is.EqualTo(0));
            var r = CliRunner.Run("calibrate", session, "--save", profile);
            Assert.That(r.ExitCode, Is.EqualTo(0), r.Stdout + r.Stderr);
            StringAssert.Contains("status: calibrated after 2 trigger press(es)", r.Stdout);
            // The simulator's devices 0..5 are head, right hand, left hand, left foot, pelvis, right foot.
            StringAssert.Contains("RightHand  device 1 ", r.Stdout);
            StringAssert.Contains("Pelvis     device 4 ", r.Stdout);
            Assert.That(CalibrationProfileStore.Load(profile).DeviceId(DeviceRole.LeftFoot), Is.EqualTo(3));

            var j = CliRunner.Run("calibrate", session, "--json");
            using var doc = JsonDocument.Parse(j.Stdout);
            Assert.That(doc.RootElement.GetProperty("status").GetString(), Is.EqualTo("calibrated"));
            Assert.That(doc.RootElement.GetProperty("profile").GetProperty("roles").GetProperty("head").GetProperty("deviceId").GetInt32(), Is.EqualTo(0));
        }
        finally { File.Delete(session); File.Delete(profile); }
    }
}
