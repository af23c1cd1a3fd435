using System;
using System.IO;
using System.Linq;
using AvatarGo.Core;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Formats;

/// <summary>
/// What <see cref="AtomicFileWriter"/> keeps where the runtime can (.NET 7+ here; Unity's Mono and IL2CPP cannot,
/// see Documentation~/robustness.md): the target's Unix permissions, and a symbolic link, whose final target is replaced
/// while the link stays a link. Linux and macOS only (Windows keeps attributes and access rights through its file
/// replace, and symbolic links need privileges there).
/// </summary>
[System.Runtime.Versioning.UnsupportedOSPlatform("windows")]
public class AtomicFileWriterPlatformTests
{
    private string _dir;

    [SetUp]
    public void MakeFolder()
    {
        if (OperatingSystem.IsWindows()) Assert.Ignore("Unix permissions and symbolic links: Linux and macOS");
        _dir = Path.Combine(Path.GetTempPath(), "avatargo-platform-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void RemoveFolder()
    {
        if (_dir != null && Directory.Exists(_dir)) Directory.Delete(_dir, true);
    }

    private string[] AllFiles(string dir) => Directory.GetFiles(dir).Select(Path.GetFileName).OrderBy(n => n, StringComparer.Ordinal).ToArray();

    [TestCase(UnixFileMode.UserRead | UnixFileMode.UserWrite)]
    [TestCase(UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead)]
    [TestCase(UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute | UnixFileMode.GroupRead | UnixFileMode.OtherRead)]
    public void SavingKeepsTheTargetsPermissions(UnixFileMode mode)
    {
        Assert.That(FileSystemFeaturesProbe.CanKeepUnixMode, Is.True, "this runtime can keep modes");
        string path = Path.Combine(_dir, "wearer.json");
        File.WriteAllText(path, "old");
        File.SetUnixFileMode(path, mode);
        AtomicFileWriter.WriteAllText(path, "new");
        Assert.That(File.ReadAllText(path), Is.EqualTo("new"));
        Assert.That(File.GetUnixFileMode(path), Is.EqualTo(mode));
    }

    [Test]
    public void SavingThroughASymbolicLinkReplacesItsTargetAndKeepsTheLink()
    {
        string real = Path.Combine(_dir, "profiles", "wearer.json");
        Directory.CreateDirectory(Path.GetDirectoryName(real));
        File.WriteAllText(real, "old");
        File.SetUnixFileMode(real, UnixFileMode.UserRead | UnixFileMode.UserWrite);
        string link = Path.Combine(_dir, "current.json");
        File.CreateSymbolicLink(link, Path.Combine("profiles", "wearer.json")); // relative, as users make them
        string chain = Path.Combine(_dir, "chain.json");
        File.CreateSymbolicLink(chain, "current.json");

        AtomicFileWriter.WriteAllText(link, "through the link");
        Assert.That(new FileInfo(link).LinkTarget, Is.EqualTo(Path.Combine("profiles", "wearer.json")), "still a link, to the same place");
        Assert.That(File.ReadAllText(real), Is.EqualTo("through the link"));
        Assert.That(File.GetUnixFileMode(real), Is.EqualTo(UnixFileMode.UserRead | UnixFileMode.UserWrite));

        AtomicFileWriter.WriteAllText(chain, "through two links");
        Assert.That(new FileInfo(chain).LinkTarget, Is.EqualTo("current.json"));
        Assert.That(File.ReadAllText(real), Is.EqualTo("through two links"));
        Assert.That(AllFiles(_dir), Is.EqualTo(new[] { "chain.json", "current.json" }));
        Assert.That(AllFiles(Path.GetDirectoryName(real)), Is.EqualTo(new[] { "wearer.json" }), "the temporary file was beside the real target");
    }

    [Test]
    public void ADanglingLinkGetsItsTargetCreated()
    {
        string link = Path.Combine(_dir, "latest.agsession");
        File.CreateSymbolicLink(link, "session-2.agsession");
        AtomicFileWriter.WriteAllText(link, "x");
        Assert.That(new FileInfo(link).LinkTarget, Is.EqualTo("session-2.agsession"));
        Assert.That(File.ReadAllText(Path.Combine(_dir, "session-2.agsession")), Is.EqualTo("x"));
    }

    [Test]
    public void CalibrationProfileStoreSaveFollowsLinksAndKeepsModes()
    {
        string real = Path.Combine(_dir, "real.json");
        string link = Path.Combine(_dir, "link.json");
        File.WriteAllText(real, "old");
        File.SetUnixFileMode(real, UnixFileMode.UserRead | UnixFileMode.UserWrite);
        File.CreateSymbolicLink(link, "real.json");
        var profile = CalibrationProfileStore.FromJson(ValidProfile());
        CalibrationProfileStore.Save(profile, link);
        Assert.That(new FileInfo(link).LinkTarget, Is.EqualTo("real.json"));
        Assert.That(CalibrationProfileStore.Load(real).AvatarScale, Is.EqualTo(profile.AvatarScale));
        Assert.That(File.GetUnixFileMode(real), Is.EqualTo(UnixFileMode.UserRead | UnixFileMode.UserWrite));
    }

    private static string ValidProfile()
    {
        string pose = "{\"position\": [0, 1, 0], \"rotation\": [0, 0, 0, 1]}";
        string Role(string name, int id) => $"\"{name}\": {{\"deviceId\": {id}, \"serial\": \"S{id}\", \"deviceAtCalibration\": {pose}, \"jointAtCalibration\": {pose}, \"jointInDevice\": {pose}}}";
        return "{\"format\": \"avatargo-calibration-profile\", \"version\": 1, \"mode\": \"exact\", \"avatarScale\": 1.05, \"wearerEyeHeight\": 1.6, " +
               "\"avatarEyeHeight\": 1.52, \"floorHeight\": 0, \"placement\": " + pose + ", \"rootToHead\": [0, 0.7, 0], \"roles\": {" +
               string.Join(", ", new[] { Role("head", 0), Role("leftHand", 1), Role("rightHand", 2), Role("pelvis", 3), Role("leftFoot", 4), Role("rightFoot", 5) }) + "}}";
    }

    /// <summary>What the core sees of this runtime (the same reflection the core uses).</summary>
    private static class FileSystemFeaturesProbe
    {
        public static bool CanKeepUnixMode =>
            typeof(File).GetMethod("GetUnixFileMode", new[] { typeof(string) }) != null && !OperatingSystem.IsWindows();
    }
}
