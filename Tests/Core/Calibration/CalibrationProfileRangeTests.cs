using System;
using System.Numerics;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Issue 14: "a calibration profile with an absurd scale (1e39, 1e-50) or floor height loads and then throws on
    /// restore". Every number is now range-checked where it is read, with <c>FILE:LINE: problem</c>; a profile that
    /// loads restores, solves and saves again.
    /// </summary>
    public class CalibrationProfileRangeTests
    {
        private static string _json;
        private static Wearer _wearer;

        private static string SavedProfile()
        {
            if (_json != null) return _json;
            _wearer = new Wearer("mocapbank_30fps.bvh", 31);
            var calibrator = new Calibrator(_wearer.Devices, _wearer.Map);
            _wearer.StandInTPose(new RigidPose(new Vector3(-1, 0, 0.5f), Rotations.AngleAxis(130f, Vector3.UnitY)));
            double t = 0;
            _wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            _wearer.StandInTPose(calibrator.Profile.Placement);
            _wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.Calibrated), calibrator.LastStep.Message);
            return _json = CalibrationProfileStore.ToJson(calibrator.Profile);
        }

        private static string WithNumber(string member, string value) =>
            Regex.Replace(SavedProfile(), $"\"{member}\": -?[0-9.eE+-]+", $"\"{member}\": {value}");

        private static int LineOf(string json, string member)
        {
            string[] lines = json.Split('\n');
            for (int i = 0; i < lines.Length; i++) if (lines[i].Contains("\"" + member + "\"")) return i + 1;
            throw new InvalidOperationException(member);
        }

        private static void AssertRefused(string json, string member, string contains)
        {
            var e = Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(json, "wearer.json"));
            StringAssert.StartsWith($"wearer.json:{LineOf(json, member)}: ", e.Message);
            StringAssert.Contains(contains, e.Message);
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1));
        }

        [TestCase("1e39")]
        [TestCase("1e-50")]
        [TestCase("0")]
        [TestCase("-1")]
        [TestCase("20000")]
        [TestCase("0.00009")]
        public void AnAbsurdAvatarScaleIsRefusedAtItsLine(string scale)
        {
            AssertRefused(WithNumber("avatarScale", scale), "avatarScale", "'avatarScale' is");
        }

        [TestCase("floorHeight", "1e39")]
        [TestCase("floorHeight", "-20000")]
        [TestCase("wearerEyeHeight", "1e39")]
        [TestCase("wearerEyeHeight", "-1")]
        [TestCase("avatarEyeHeight", "3e38")]
        public void AbsurdHeightsAreRefusedAtTheirLine(string member, string value)
        {
            AssertRefused(WithNumber(member, value), member, $"'{member}' is");
        }

        [TestCase("1e30")]
        [TestCase("3e38")]
        [TestCase("20000")]
        public void PositionsBeyondTenKilometresAreRefused(string value)
        {
            string json = Regex.Replace(SavedProfile(), "\"rootToHead\": \\[[^\\]]*\\]", $"\"rootToHead\": [0, {value}, 0]");
            AssertRefused(json, "rootToHead", "positions are within ±10000 m");
            var first = new Regex("\"position\": \\[[^\\]]*\\]");
            json = first.Replace(SavedProfile(), $"\"position\": [{value}, 0, 0]", 1);
            AssertRefused(json, "position", "'placement.position' has a coordinate");
        }

        [TestCase("1e10")]
        [TestCase("-1")]
        [TestCase("2.5")]
        [TestCase("2147483648")]
        public void DeviceIdsMustFitAnInt(string id)
        {
            AssertRefused(WithNumber("deviceId", id), "deviceId", "deviceId must be an integer from 0 to 2147483647");
        }

        [Test]
        public void AProfileAtTheEdgesOfTheRangesLoadsRestoresSolvesAndSavesAgain()
        {
            string json = WithNumber("avatarScale", "1000");
            json = Regex.Replace(json, "\"floorHeight\": -?[0-9.eE+-]+", "\"floorHeight\": -10000");
            CalibrationProfile p = CalibrationProfileStore.FromJson(json, "edges.json");
            Assert.That(p.AvatarScale, Is.EqualTo(1000f));
            var pipeline = new SelfAvatarPipeline(_wearer.Devices, _wearer.Map);
            Assert.That(pipeline.TryRestore(p), Is.True);
            var samples = new DeviceSample[6];
            _wearer.Sample(samples, 0, 0);
            pipeline.Update(0, samples, new float[6], new float[6], Array.Empty<DeviceEvent>());
            BodyTargets targets = pipeline.Targets;
            Assert.That(Vectors.IsFinite(targets.Hips.Position) && Vectors.IsFinite(targets.LeftHand.Goal.Position), Is.True);
            foreach (RigidPose bone in pipeline.Pose.World)
                Assert.That(Vectors.IsFinite(bone.Position) && Rotations.IsFinite(bone.Rotation), Is.True, "every bone finite");
            Assert.That(CalibrationProfileStore.FromJson(CalibrationProfileStore.ToJson(p)).AvatarScale, Is.EqualTo(1000f));
        }

        [Test]
        public void SaveRefusesAProfileItCouldNotLoadBack()
        {
            CalibrationProfile p = CalibrationProfileStore.FromJson(SavedProfile());
            Assert.Throws<ArgumentOutOfRangeException>(() => p.WithAvatarScale(float.PositiveInfinity)); // (float)1e39
            Assert.Throws<ArgumentOutOfRangeException>(() => p.WithAvatarScale(0f)); // (float)1e-50
            var empty = new CalibrationProfile(); // never calibrated: no devices (-1)
            string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "avatargo-never-" + Guid.NewGuid().ToString("N") + ".json");
            Assert.Throws<ArgumentException>(() => CalibrationProfileStore.Save(empty, path));
            Assert.That(System.IO.File.Exists(path), Is.False, "nothing written");
        }

        [Test]
        public void AHugeFileIsRefusedBeforeItIsRead()
        {
            string big = SavedProfile().Replace("\"serial\": \"", "\"serial\": \"" + new string('s', CalibrationProfileStore.MaxFileLength));
            var e = Assert.Throws<FormatException>(() => CalibrationProfileStore.FromJson(big, "big.json"));
            StringAssert.StartsWith("big.json:1: ", e.Message);
        }

        [Test]
        public void ErrorsOfLoadNameTheFileAndLine()
        {
            string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "avatargo-range-" + Guid.NewGuid().ToString("N") + ".json");
            try
            {
                System.IO.File.WriteAllText(path, WithNumber("avatarScale", "1e39"));
                var e = Assert.Throws<FormatException>(() => CalibrationProfileStore.Load(path));
                StringAssert.StartsWith($"{System.IO.Path.GetFileName(path)}:{LineOf(WithNumber("avatarScale", "1e39"), "avatarScale")}: 'avatarScale' is 1E+39", e.Message);
            }
            finally { System.IO.File.Delete(path); }
        }
    }
}
