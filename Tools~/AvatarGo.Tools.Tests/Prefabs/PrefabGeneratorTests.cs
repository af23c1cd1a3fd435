using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using AvatarGo.Tools.Tests.AssetLint;
using AvatarGo.Tools.Tests.PackageLint;
using NUnit.Framework;
using YamlDotNet.RepresentationModel;

namespace AvatarGo.Tools.Tests.Prefabs;

/// <summary>
/// The committed <c>AvatarGo.prefab</c> is what <see cref="PrefabGenerator"/> makes from the components' sources, byte for
/// byte; the asset lint accepts it; its components are wired as documented; and a wrong field name or an unknown script
/// GUID planted in a copy of the package fails the lint. To regenerate after a component's fields changed:
/// <c>AVATARGO_REGENERATE=1 dotnet test "Tools~/AvatarGo.Tools.Tests" -c Release --filter FullyQualifiedName~PrefabGenerator</c>.
/// </summary>
[TestFixture]
public class PrefabGeneratorTests
{
    private static string Committed => Path.Combine(Paths.PackageRoot, PrefabGenerator.PrefabPath);

    [Test, Order(0)]
    public void CommittedPrefabIsTheGeneratedOne()
    {
        string generated = new PrefabGenerator(Paths.PackageRoot).Generate();
        if (Environment.GetEnvironmentVariable("AVATARGO_REGENERATE") == "1")
        {
            Directory.CreateDirectory(Path.GetDirectoryName(Committed));
            File.WriteAllText(Committed, generated);
        }
        Assert.That(File.Exists(Committed), Is.True, $"{PrefabGenerator.PrefabPath} is missing: regenerate it (AVATARGO_REGENERATE=1)");
        Assert.That(File.ReadAllText(Committed), Is.EqualTo(generated),
            $"{PrefabGenerator.PrefabPath} is not what the components' fields give: regenerate it (AVATARGO_REGENERATE=1) and commit it");
    }

    [Test]
    public void GeneratingTwiceGivesTheSameBytes() =>
        Assert.That(new PrefabGenerator(Paths.PackageRoot).Generate(), Is.EqualTo(new PrefabGenerator(Paths.PackageRoot).Generate()));

    [Test]
    public void AssetLintChecksThePrefabAndAcceptsIt()
    {
        var linter = new AssetLinter(Paths.PackageRoot);
        Assert.That(linter.Assets, Does.Contain(PrefabGenerator.PrefabPath));
        List<string> problems = linter.Check();
        Assert.That(problems.Where(p => p.StartsWith(PrefabGenerator.PrefabPath, StringComparison.Ordinal)), Is.Empty, string.Join("\n", problems));
    }

    [Test]
    public void ComponentsAreWiredAndTheAvatarSlotIsEmpty()
    {
        List<UnityYamlObject> objects = UnityYaml.Parse(File.ReadAllText(Committed));
        UnityYamlObject Script(string name) => objects.Single(o => o.ClassId == 114 && Scalar(o.Body, "m_Script", "guid") == ScriptGuid(name));
        UnityYamlObject calibrator = Script("Calibration/AvatarGoCalibrator.cs");
        UnityYamlObject fingers = Script("Hands/AvatarGoFingers.cs");
        UnityYamlObject source = Script("Tracking/XRInputDevicesTrackingSource.cs");

        Assert.That(Scalar(calibrator.Body, "m_Source", "fileID"), Is.EqualTo(source.FileId.ToString()), "the calibrator reads the prefab's tracking source");
        Assert.That(Scalar(fingers.Body, "m_Calibrator", "fileID"), Is.EqualTo(calibrator.FileId.ToString()), "the fingers follow the prefab's calibrator");
        Assert.That(Scalar(calibrator.Body, "m_Animator", "fileID"), Is.EqualTo("0"), "the avatar slot is empty");
        Assert.That(Scalar(calibrator.Body, "m_AvatarRoot", "fileID"), Is.EqualTo("0"));
        Assert.That(Scalar(calibrator.Body, "m_Driver"), Is.EqualTo("0"), "Animator IK (DriverKind.AnimatorIK = 0): the calibrator adds the IK driver to the avatar");
        string quest = MetaGuid(PrefabGenerator.DefaultControllerProfile);
        Assert.That(Scalar(fingers.Body, "m_LeftController", "guid"), Is.EqualTo(quest));
        Assert.That(Scalar(fingers.Body, "m_RightController", "guid"), Is.EqualTo(quest));
        // Every component sits on a GameObject of the prefab, and exactly one root.
        var gameObjects = objects.Where(o => o.ClassId == 1).Select(o => o.FileId.ToString()).ToHashSet();
        Assert.That(objects.Where(o => o.ClassId == 114).Select(o => Scalar(o.Body, "m_GameObject", "fileID")), Is.All.Matches<string>(gameObjects.Contains));
        Assert.That(objects.Count(o => o.ClassId == 4 && Scalar(o.Body, "m_Father", "fileID") == "0"), Is.EqualTo(1));
    }

    /// <summary>
    /// The calibrator's serialized tuning fields start at the core's defaults (the generator evaluates literals only, so the
    /// component repeats them): a default changed in <c>FullBodyIk</c> and not in the component would give Unity users
    /// another solver than the one measured.
    /// </summary>
    [Test]
    public void TheCalibratorsTuningStartsAtTheCoresDefaults()
    {
        List<UnityYamlObject> objects = UnityYaml.Parse(File.ReadAllText(Committed));
        UnityYamlObject calibrator = objects.Single(o => o.ClassId == 114 && Scalar(o.Body, "m_Script", "guid") == ScriptGuid("Calibration/AvatarGoCalibrator.cs"));
        float Field(string name) => float.Parse(Scalar(calibrator.Body, name), System.Globalization.CultureInfo.InvariantCulture);
        Assert.That(Field("m_ShrugReleaseSeconds"), Is.EqualTo(AvatarGo.Core.FullBodyIk.DefaultShrugReleaseSeconds));
        Assert.That(Field("m_StraightLegCutoffHz"), Is.EqualTo(AvatarGo.Core.FullBodyIk.DefaultStraightLegCutoffHz));
        Assert.That(Field("m_SpineChordNoiseMetres"), Is.EqualTo(AvatarGo.Core.FullBodyIk.DefaultChordNoiseMetres));
        Assert.That(Field("m_StraightArmCutoffHz"), Is.EqualTo(AvatarGo.Core.FullBodyIk.DefaultStraightArmCutoffHz));
        Assert.That(Field("m_SpineChordCutoffHz"), Is.EqualTo(AvatarGo.Core.FullBodyIk.DefaultChordCutoffHz));
    }

    [Test]
    public void WrongFieldNamePlantedInACopyFailsTheLint()
    {
        string copy = CopyPackage();
        try
        {
            string prefab = Path.Combine(copy, PrefabGenerator.PrefabPath);
            string text = File.ReadAllText(prefab);
            Assert.That(new AssetLinter(copy).Check(), Is.Empty, "the unplanted copy is clean");
            Assert.That(text, Does.Contain("  m_MirrorDistance:"));
            File.WriteAllText(prefab, text.Replace("  m_MirrorDistance:", "  m_MirorDistance:"));
            List<string> problems = new AssetLinter(copy).Check();
            Assert.That(problems, Has.Some.Contains("sets 'm_MirorDistance', but AvatarGoCalibrator has no such field"), string.Join("\n", problems));
        }
        finally
        {
            Directory.Delete(copy, recursive: true);
        }
    }

    [Test]
    public void UnknownScriptGuidPlantedInACopyFailsTheLint()
    {
        string copy = CopyPackage();
        try
        {
            string prefab = Path.Combine(copy, PrefabGenerator.PrefabPath);
            string guid = ScriptGuid("Hands/AvatarGoFingers.cs");
            File.WriteAllText(prefab, File.ReadAllText(prefab).Replace(guid, "0123456789abcdef0123456789abcdef"));
            List<string> problems = new AssetLinter(copy).Check();
            Assert.That(problems, Has.Some.Contains("m_Script guid 0123456789abcdef0123456789abcdef is no script of the package"), string.Join("\n", problems));
        }
        finally
        {
            Directory.Delete(copy, recursive: true);
        }
    }

    [Test]
    public void WiringAFieldTheComponentLacksStopsTheGenerator()
    {
        string copy = CopyPackage();
        try
        {
            // Rename the calibrator's source field in the copy: the generator refuses rather than write a stale name.
            string script = Path.Combine(copy, "Runtime", "Calibration", "AvatarGoCalibrator.cs");
            File.WriteAllText(script, File.ReadAllText(script).Replace("m_Source", "m_TrackingSource"));
            var e = Assert.Throws<InvalidOperationException>(() => new PrefabGenerator(copy).Generate());
            Assert.That(e.Message, Does.Contain("AvatarGoCalibrator has no serialized field m_Source"));
        }
        finally
        {
            Directory.Delete(copy, recursive: true);
        }
    }

    private static string ScriptGuid(string underRuntime) => MetaGuid("Runtime/" + underRuntime);

    private static string MetaGuid(string file) =>
        File.ReadLines(Path.Combine(Paths.PackageRoot, file + ".meta")).First(l => l.StartsWith("guid:", StringComparison.Ordinal)).Substring(5).Trim();

    private static string Scalar(YamlMappingNode body, params string[] keys)
    {
        YamlNode node = body;
        foreach (string k in keys) node = ((YamlMappingNode)node).Children[new YamlScalarNode(k)];
        return ((YamlScalarNode)node).Value;
    }

    // package.json and Runtime/ (scripts, metas, profiles, the prefab): what the asset lint reads for the prefab.
    private static string CopyPackage()
    {
        string copy = Path.Combine(Path.GetTempPath(), "avatargo-prefab-" + Guid.NewGuid().ToString("N"));
        foreach (string file in new PackageLinter(Paths.PackageRoot).Files)
        {
            if (file != "package.json" && file != "package.json.meta" && !file.StartsWith("Runtime/", StringComparison.Ordinal)) continue;
            string to = Path.Combine(copy, file);
            Directory.CreateDirectory(Path.GetDirectoryName(to));
            File.Copy(Path.Combine(Paths.PackageRoot, file), to);
        }
        return copy;
    }
}
