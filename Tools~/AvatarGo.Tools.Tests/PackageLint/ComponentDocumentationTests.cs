using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// Like Unity's own DocumentationTests: every MonoBehaviour and ScriptableObject of the package is in the Add Component
/// menu under XR/AvatarGo, has a HelpURL naming a page (and heading) of Documentation~ that exists, an XML summary, and
/// a tooltip on every serialized field. The checker is shown to fail on each planted defect.
/// </summary>
public class ComponentDocumentationTests
{
    [Test]
    public void EveryComponentAndScriptableObjectOfThePackageIsDocumented()
    {
        List<(string Path, string Text)> sources = ComponentDocumentation.PackageSources(Paths.PackageRoot).ToList();
        List<string> problems = ComponentDocumentation.Check(sources, Path.Combine(Paths.PackageRoot, "Documentation~"));
        Assert.That(problems, Is.Empty, string.Join("\n", problems));
        // The check saw the components (not an empty or misread tree).
        string all = string.Join("\n", sources.Select(s => s.Path));
        foreach (string component in new[]
                 {
                     "Runtime/Calibration/AvatarGoCalibrator.cs", "Runtime/Drivers/AvatarGoAnimatorIKDriver.cs", "Runtime/Drivers/AvatarGoTransformDriver.cs",
                     "Runtime/Hands/AvatarGoFingers.cs", "Runtime/Hands/AvatarGoHeldController.cs", "Runtime/Recording/AvatarGoRecorder.cs",
                     "Runtime/Tracking/RecordedSessionTrackingSource.cs", "Runtime/Tracking/TransformTrackingSource.cs",
                 })
            Assert.That(all, Does.Contain(component));
    }

    private const string Good = @"
namespace AvatarGo
{
    /// <summary>A base.</summary>
    public abstract class SourceBase : MonoBehaviour { }

    /// <summary>A component.</summary>
    [AddComponentMenu(""XR/AvatarGo/Thing"")]
    [HelpURL(AvatarGoDocs.Manual + ""thing.md#the-thing-component"")]
    public sealed class Thing : SourceBase
    {
        [SerializeField, Tooltip(""Why."")]
        private float m_Value;

        public const int NotSerialized = 1;
    }

    /// <summary>Not a Unity object.</summary>
    public sealed class Helper { }
}";

    private static List<string> CheckPlanted(string source)
    {
        string docs = Path.Combine(Path.GetTempPath(), "avatargo-doc-test-" + System.Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(docs);
        try
        {
            File.WriteAllText(Path.Combine(docs, "thing.md"), "# Thing\n\n## The Thing component\n");
            return ComponentDocumentation.Check(new[] { ("Runtime/Thing.cs", source) }, docs);
        }
        finally
        {
            Directory.Delete(docs, true);
        }
    }

    [Test]
    public void AWellDocumentedComponentPasses() => Assert.That(CheckPlanted(Good), Is.Empty);

    [TestCase("[AddComponentMenu(\"XR/AvatarGo/Thing\")]", "", "has no [AddComponentMenu")]
    [TestCase("\"XR/AvatarGo/Thing\"", "\"AvatarGo/Thing\"", "is not under XR/AvatarGo/")]
    [TestCase("[HelpURL(AvatarGoDocs.Manual + \"thing.md#the-thing-component\")]", "", "has no [HelpURL")]
    [TestCase("thing.md#the-thing-component", "missing.md", "Documentation~/missing.md, which does not exist")]
    [TestCase("#the-thing-component", "#no-such-heading", "a heading that page does not have")]
    [TestCase("AvatarGoDocs.Manual + \"thing.md#the-thing-component\"", "\"https://example.com/thing\"", "is not AvatarGoDocs.Manual")]
    [TestCase("/// <summary>A component.</summary>", "// A component.", "Thing has no /// <summary>")]
    [TestCase("[SerializeField, Tooltip(\"Why.\")]", "[SerializeField]", "m_Value is serialized without a [Tooltip]")]
    [TestCase("private float m_Value;", "public float m_Value;", null)]
    public void EachPlantedDefectIsFound(string replace, string with, string expected)
    {
        string source = Good.Replace(replace, with);
        Assert.That(source, Is.Not.EqualTo(Good), "the defect was planted");
        if (replace == "private float m_Value;")
        {
            // A public field is serialized too: with its tooltip it passes, without it fails.
            Assert.That(CheckPlanted(source), Is.Empty);
            List<string> untipped = CheckPlanted(source.Replace("[SerializeField, Tooltip(\"Why.\")]", ""));
            Assert.That(untipped, Has.Some.Contains("m_Value is serialized without a [Tooltip]"));
            return;
        }
        List<string> problems = CheckPlanted(source);
        Assert.That(problems, Has.Some.Contains(expected), string.Join("\n", problems));
    }

    [Test]
    public void AScriptableObjectNeedsAHelpUrlButNoMenu()
    {
        const string so = @"
/// <summary>An asset.</summary>
[HelpURL(AvatarGoDocs.Manual + ""thing.md"")]
public sealed class Profile : ScriptableObject { }";
        Assert.That(CheckPlanted(so), Is.Empty);
        Assert.That(CheckPlanted(so.Replace("[HelpURL(AvatarGoDocs.Manual + \"thing.md\")]", "")), Has.Some.Contains("Profile has no [HelpURL"));
    }

    [TestCase("The Thing component (v2)", "the-thing-component-v2")]
    [TestCase("XR Input Devices Tracking Source", "xr-input-devices-tracking-source")]
    [TestCase("OpenXR VIVE trackers", "openxr-vive-trackers")]
    public void AnchorsAreGitHubs(string heading, string anchor) => Assert.That(ComponentDocumentation.Anchor(heading), Is.EqualTo(anchor));
}
