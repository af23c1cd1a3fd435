using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using AvatarGo.Tools.Tests.PackageLint;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.AssetLint;

/// <summary>
/// The asset lint on this package (which has no prefab, scene or asset yet, so it passes trivially and will check
/// them when they come) and on a fake package whose prefab is clean and then carries one planted defect at a time.
/// </summary>
[TestFixture]
public class AssetLintTests
{
    private const string ScriptGuid = "4d1f2c3b5a6e47f8a9b0c1d2e3f40516";

    private const string Script = @"using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Serialization;

namespace AvatarGo
{
    public sealed class AvatarRig : RigBase
    {
        public Transform head;
        [SerializeField] private float scale = 1f;
        [SerializeField, FormerlySerializedAs(""legacyOffsets"")] private List<Offset> offsets;
        public Mode mode;
        public static int instances;
        public const float Epsilon = 1e-4f;
        public readonly int frozen = 1;
        private float hidden;
        [NonSerialized] public float transient;
        public Dictionary<string, float> lookup;
        public float[,] grid;

        public enum Mode { Exact, Fixed }
    }

    public abstract class RigBase : MonoBehaviour
    {
        [SerializeField] protected bool autoCalibrate;
    }

    [Serializable]
    public struct Offset
    {
        public Vector3 position;
        public Quaternion rotation;
    }

    public sealed class NotAComponent { }
}
";

    private const string Prefab = @"%YAML 1.1
%TAG !u! tag:unity3d.com,2011:
--- !u!1 &100
GameObject:
  m_ObjectHideFlags: 0
  m_Component:
  - component: {fileID: 400}
  - component: {fileID: 11400}
  m_Name: AvatarGo
--- !u!4 &400
Transform:
  m_GameObject: {fileID: 100}
  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}
  m_LocalPosition: {x: 0, y: 0, z: 0}
  m_Children: []
  m_Father: {fileID: 0}
--- !u!114 &11400
MonoBehaviour:
  m_ObjectHideFlags: 0
  m_CorrespondingSourceObject: {fileID: 0}
  m_PrefabInstance: {fileID: 0}
  m_PrefabAsset: {fileID: 0}
  m_GameObject: {fileID: 100}
  m_Enabled: 1
  m_EditorHideFlags: 0
  m_Script: {fileID: 11500000, guid: " + ScriptGuid + @", type: 3}
  m_Name:
  m_EditorClassIdentifier:
  head: {fileID: 400}
  scale: 1
  autoCalibrate: 1
  legacyOffsets:
  - position: {x: 0, y: 0.1, z: 0}
    rotation: {x: 0, y: 0, z: 0, w: 1}
  mode: 0
";

    private string _root;

    [SetUp]
    public void CreatePackage()
    {
        _root = Path.Combine(Path.GetTempPath(), "avatargo-assets-" + Guid.NewGuid().ToString("N"));
        Write("package.json", "{ \"name\": \"com.avatargo.selfavatar\" }");
        Write("Runtime/Rig/AvatarRig.cs", Script);
        Write("Runtime/Rig/AvatarRig.cs.meta", $"fileFormatVersion: 2\nguid: {ScriptGuid}\nMonoImporter:\n");
        Write("Runtime/Rig/NotAComponent.cs", "namespace AvatarGo { public sealed class NotAComponent { } }\n");
        Write("Runtime/Rig/NotAComponent.cs.meta", "fileFormatVersion: 2\nguid: 5e2f3d4c6b7f48a9b0c1d2e3f4051627\nMonoImporter:\n");
        Write("Runtime/Rig/Misnamed.cs", "namespace AvatarGo { public sealed class Other : UnityEngine.MonoBehaviour { } }\n");
        Write("Runtime/Rig/Misnamed.cs.meta", "fileFormatVersion: 2\nguid: 6f3a4e5d7c8a49b0c1d2e3f405162738\nMonoImporter:\n");
        Write("Runtime/Prefabs/AvatarGo.prefab", Prefab);
    }

    [TearDown]
    public void DeletePackage() => Directory.Delete(_root, recursive: true);

    private void Write(string relative, string text)
    {
        string path = Path.Combine(_root, relative);
        Directory.CreateDirectory(Path.GetDirectoryName(path));
        File.WriteAllText(path, text.Replace("\r\n", "\n"));
    }

    private List<string> Lint() => new AssetLinter(_root).Check();

    private void PlantInPrefab(string old, string replacement)
    {
        string text = Prefab.Replace("\r\n", "\n");
        Assert.That(text, Does.Contain(old), "the clean prefab lacks the text to replace");
        Write("Runtime/Prefabs/AvatarGo.prefab", text.Replace(old, replacement));
    }

    private static void AssertOnly(List<string> problems, string fragment)
    {
        Assert.That(problems, Has.Count.EqualTo(1), string.Join("\n", problems));
        Assert.That(problems[0], Does.Contain(fragment));
    }

    [Test]
    public void ThePackagesAssetsAreClean()
    {
        var linter = new AssetLinter(Paths.PackageRoot);
        List<string> problems = linter.Check();
        Assert.That(problems, Is.Empty, string.Join("\n", problems));
        TestContext.Progress.WriteLine($"asset lint: {linter.Assets.Count} asset(s) in the package: {string.Join(", ", linter.Assets)}");
    }

    [Test]
    public void EverySerializedFieldOfThePackagesComponentsIsOneUnitySerializes()
    {
        // A [SerializeField] the catalog cannot type (an alias it did not resolve, a type it does not know) would be left
        // out of the generated prefab and refused in assets without anyone noticing.
        var scripts = new PackageLint.PackageLinter(Paths.PackageRoot).Files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal) && PackageLint.PackageLinter.IsImported(f));
        var catalog = new ScriptCatalog(Paths.PackageRoot, scripts);
        var problems = new List<string>();
        foreach (ScriptType type in catalog.Types.Where(catalog.IsUnityScript))
            foreach (ScriptField field in type.Fields)
                if (!field.Serialized && field.WhyNot != null && !field.WhyNot.StartsWith("neither public", StringComparison.Ordinal)
                    && field.WhyNot is not ("static" or "const" or "readonly" or "[NonSerialized]"))
                    problems.Add($"{type.File}: {type.Name}.{field.Name}: {field.WhyNot}");
        Assert.That(problems, Is.Empty, string.Join("\n", problems));
    }

    [Test]
    public void CleanFakePrefabHasNoProblems()
    {
        var linter = new AssetLinter(_root);
        Assert.That(linter.Assets, Is.EqualTo(new[] { "Runtime/Prefabs/AvatarGo.prefab" }));
        Assert.That(linter.Check(), Is.Empty, string.Join("\n", linter.Check()));
    }

    [Test]
    public void InvalidYamlIsReported()
    {
        PlantInPrefab("  scale: 1\n", "  scale: [1\n");
        AssertOnly(Lint(), "Runtime/Prefabs/AvatarGo.prefab: not Unity YAML: line ");
    }

    [Test]
    public void MissingUnityHeaderIsReported()
    {
        PlantInPrefab("%TAG !u! tag:unity3d.com,2011:\n", "");
        AssertOnly(Lint(), "a Unity YAML file starts with '%YAML 1.1' and '%TAG !u! tag:unity3d.com,2011:'");
    }

    [Test]
    public void FileIdThatIsNoObjectOfTheFileIsReported()
    {
        PlantInPrefab("  head: {fileID: 400}", "  head: {fileID: 401}");
        AssertOnly(Lint(), "MonoBehaviour &11400: head refers to fileID 401, which is no object of this file");
    }

    [Test]
    public void GuidThatIsNoAssetIsReported()
    {
        PlantInPrefab("  head: {fileID: 400}", "  head: {fileID: 400, guid: 99999999999999999999999999999999, type: 2}");
        AssertOnly(Lint(), "head refers to guid 99999999999999999999999999999999, which is no asset of the package");
    }

    [Test]
    public void UnknownScriptGuidIsReported()
    {
        PlantInPrefab(ScriptGuid, "0123456789abcdef0123456789abcdef");
        List<string> problems = Lint();
        Assert.That(problems, Has.Count.EqualTo(1), string.Join("\n", problems));
        Assert.That(problems, Has.Member("Runtime/Prefabs/AvatarGo.prefab:17 MonoBehaviour &11400: m_Script guid 0123456789abcdef0123456789abcdef is no script of the package nor a documented Unity script"),
            string.Join("\n", problems));
    }

    [Test]
    public void DocumentedUnityScriptIsAccepted()
    {
        PlantInPrefab(ScriptGuid, "0123456789abcdef0123456789abcdef");
        var documented = new Dictionary<string, string> { ["0123456789abcdef0123456789abcdef"] = "a Unity script (test entry)" };
        Assert.That(new AssetLinter(_root, documented).Check(), Is.Empty);
    }

    [Test]
    public void ScriptWhoseClassIsNotNamedAfterTheFileIsReported()
    {
        PlantInPrefab(ScriptGuid, "6f3a4e5d7c8a49b0c1d2e3f405162738");
        AssertOnly(Lint(), "m_Script is Runtime/Rig/Misnamed.cs, which declares no class named Misnamed");
    }

    [Test]
    public void ScriptThatIsNoComponentIsReported()
    {
        PlantInPrefab(ScriptGuid, "5e2f3d4c6b7f48a9b0c1d2e3f4051627");
        AssertOnly(Lint(), "whose class NotAComponent derives from neither MonoBehaviour nor ScriptableObject");
    }

    [Test]
    public void ASamplesAssetsAreLintedAsTheyWouldBeImported()
    {
        // The Package Manager copies Samples~/NAME into Assets when the user imports it: its scenes are checked like the
        // package's own assets (here a field the script lacks), while a `~` folder inside the sample is still skipped.
        string scene = Prefab.Replace("\r\n", "\n").Replace("  mode: 0\n", "  mode: 0\n  headTarget: {fileID: 400}\n");
        Write("Samples~/Demo/Demo.unity", scene);
        Write("Samples~/Demo/Extra~/Ignored.unity", "not yaml at all");
        var linter = new AssetLinter(_root);
        Assert.That(linter.Assets, Is.EqualTo(new[] { "Runtime/Prefabs/AvatarGo.prefab", "Samples~/Demo/Demo.unity" }));
        AssertOnly(Lint(), "Samples~/Demo/Demo.unity");
        Assert.That(Lint()[0], Does.Contain("sets 'headTarget', but AvatarRig has no such field"));
    }

    [Test]
    public void FieldTheClassLacksIsReported()
    {
        PlantInPrefab("  mode: 0\n", "  mode: 0\n  headTarget: {fileID: 400}\n");
        AssertOnly(Lint(), "sets 'headTarget', but AvatarRig has no such field");
    }

    [TestCase("instances: 2", "Unity does not serialize AvatarRig.instances (static)")]
    [TestCase("Epsilon: 0.1", "Unity does not serialize AvatarRig.Epsilon (const)")]
    [TestCase("frozen: 2", "Unity does not serialize AvatarRig.frozen (readonly)")]
    [TestCase("hidden: 2", "Unity does not serialize AvatarRig.hidden (neither public nor [SerializeField])")]
    [TestCase("transient: 2", "Unity does not serialize AvatarRig.transient ([NonSerialized])")]
    [TestCase("lookup: {}", "Unity does not serialize AvatarRig.lookup (Dictionary<...> is not a type Unity serializes)")]
    [TestCase("grid: []", "Unity does not serialize AvatarRig.grid (a multidimensional or jagged array is not serialized)")]
    public void FieldUnityDoesNotSerializeIsReported(string line, string fragment)
    {
        PlantInPrefab("  mode: 0\n", "  mode: 0\n  " + line + "\n");
        AssertOnly(Lint(), fragment);
    }

    [Test]
    public void FieldInsideASerializableValueIsChecked()
    {
        PlantInPrefab("    rotation: {x: 0, y: 0, z: 0, w: 1}\n", "    rotation: {x: 0, y: 0, z: 0, w: 1}\n    scale: {x: 1, y: 1, z: 1}\n");
        AssertOnly(Lint(), "legacyOffsets: sets 'scale', but Offset has no such field");
    }

    [Test]
    public void InputActionsMustBeJsonWithMaps()
    {
        Write("Runtime/Input/Avatar.inputactions", "{ \"name\": \"Avatar\", \"maps\": [] }");
        Assert.That(Lint(), Is.Empty);
        Write("Runtime/Input/Avatar.inputactions", "{ \"name\": \"Avatar\", ");
        AssertOnly(Lint(), "Runtime/Input/Avatar.inputactions: not valid JSON");
    }
}
