using System.Collections.Generic;
using System.IO;
using System.Linq;
using AvatarGo.UnityGate;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// Each defect the gate exists to catch, planted in a temporary copy of the package; the gate must fail with that
/// defect's own diagnostic (code, file and member), so no test can pass for the wrong reason. Each compiles only the
/// configurations and assemblies the defect concerns, in-process; what the copy shares with the package unchanged was
/// compiled earlier in the run and is reused.
/// </summary>
[TestFixture]
public class PlantedDefectTests
{
    private const string Bridge = "Runtime/Bridge/UnityConversions.cs";
    private PackageCopy _copy;

    [SetUp]
    public void CopyPackage() => _copy = new PackageCopy();

    [TearDown]
    public void DeleteCopy() => _copy.Dispose();

    private GateResult Gate(string[] configurations, params string[] assemblies)
    {
        GateResult result = GateBuild.Run(_copy.Root, AvatarGo.UnityGate.Program.NuGetPackageRoot, configurations.Select(UnityConfiguration.Named), _copy.OutDir,
            assemblies.Length > 0 ? assemblies : null);
        TestContext.Out.WriteLine(result.Output + result.Describe()); // what was compiled and what reused, in the test's output
        return result;
    }

    private static GateDiagnostic AssertSingleError(GateResult result, string code, string file, params string[] fragments)
    {
        Assert.That(result.Succeeded, Is.False, "the planted defect compiled: " + result.Describe());
        List<GateDiagnostic> matching = result.Errors.Where(e => e.Code == code && e.File == file && fragments.All(f => e.Message.Contains(f))).ToList();
        Assert.That(matching, Is.Not.Empty, $"expected {code} in {file} mentioning {string.Join(", ", fragments)}; got " + result.Describe());
        return matching[0];
    }

    [Test]
    public void MisspelledUnityMemberInARuntimeFileFails()
    {
        _copy.Replace(Bridge, "transform.localPosition = pose.Position.ToUnity();", "transform.localPositon = pose.Position.ToUnity();");
        GateResult result = Gate(new[] { "player-2021.3" }, "AvatarGo");
        AssertSingleError(result, "CS1061", Bridge, "'Transform' does not contain a definition for 'localPositon'");
        Assert.That(result.Errors.Select(e => e.Code).Distinct(), Is.EqualTo(new[] { "CS1061" }), result.Describe());
    }

    [Test]
    public void ASampleUsingAMemberTheSurfaceLacksFails()
    {
        // Samples~/NAME is compiled as Unity compiles it once imported into Assets: against the package and the surface.
        const string demo = "Samples~/HeadsetFree/Scripts/HeadsetFreeDemo.cs";
        _copy.Replace(demo, "GUILayout.EndArea();\n        }\n\n        private void Fail", "GUILayout.EndAreaNow();\n        }\n\n        private void Fail");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo.Samples.HeadsetFree");
        AssertSingleError(result, "CS0117", demo, "'GUILayout' does not contain a definition for 'EndAreaNow'");
    }

    [Test]
    public void CallToAMemberUnityLacksFails()
    {
        _copy.Write("Runtime/Bridge/PlantedGlobalPose.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedGlobalPose\n    {\n" +
            "        internal static void Apply(UnityEngine.Transform t, UnityEngine.Vector3 p, UnityEngine.Quaternion q) => t.SetGlobalPose(p, q);\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo");
        AssertSingleError(result, "CS1061", "Runtime/Bridge/PlantedGlobalPose.cs", "'Transform' does not contain a definition for 'SetGlobalPose'");
    }

    [Test]
    public void EditorApiInARuntimeFileWithoutTheGuardFailsInThePlayerBuild()
    {
        // The package's runtime uses no EditorApplication (only Editor/ uses UnityEditor), so the copy's surface gets one
        // real member for the plant, declared (with its source) as Unity declares it.
        _copy.Write("Tools~/UnitySurface/UnityEditor/EditorApplication.cs",
            "namespace UnityEditor\n{\n    // UnityCsReference@2021.3 Editor/Mono/EditorApplication.bindings.cs\n" +
            "    public sealed class EditorApplication\n    {\n        public static bool isPlaying { get => throw null; set => throw null; }\n    }\n}\n");
        _copy.Write("Runtime/Bridge/PlantedEditorCall.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedEditorCall\n    {\n" +
            "        internal static bool Playing() => UnityEditor.EditorApplication.isPlaying;\n    }\n}\n");
        _copy.Write("Runtime/Bridge/PlantedGuardedEditorCall.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedGuardedEditorCall\n    {\n" +
            "#if UNITY_EDITOR\n        internal static bool Playing() => UnityEditor.EditorApplication.isPlaying;\n#else\n        internal static bool Playing() => true;\n#endif\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3", "player-2021.3" }, "AvatarGo");
        GateDiagnostic error = AssertSingleError(result, "CS0103", "Runtime/Bridge/PlantedEditorCall.cs", "The name 'UnityEditor' does not exist in the current context");
        Assert.That(error.Configuration, Is.EqualTo("player-2021.3"), "the Editor references UnityEditor from every assembly: only the player build catches it");
        Assert.That(result.Errors.Where(e => e.File == "Runtime/Bridge/PlantedGuardedEditorCall.cs"), Is.Empty, "the #if UNITY_EDITOR guard keeps the player build clean");
        Assert.That(result.Errors, Has.Count.EqualTo(1), result.Describe());
    }

    [Test]
    public void AnimatePhysicsFailsFromUnity2023()
    {
        // The plant uses the 2021.3 name that 2023.1 made an error, against the surface's AnimatorUpdateMode (declared as
        // both versions declare it: Tools~/UnitySurface/UnityEngine/AnimationModule/AnimatorUpdateMode.cs).
        _copy.Write("Runtime/Bridge/PlantedUpdateMode.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedUpdateMode\n    {\n" +
            "        internal static UnityEngine.AnimatorUpdateMode Physics => UnityEngine.AnimatorUpdateMode.AnimatePhysics;\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3", "editor-6000.5" }, "AvatarGo");
        GateDiagnostic error = AssertSingleError(result, "CS0619", "Runtime/Bridge/PlantedUpdateMode.cs", "'AnimatorUpdateMode.AnimatePhysics' is obsolete");
        Assert.That(error.Configuration, Is.EqualTo("editor-6000.5"), "2021.3 has AnimatePhysics; only the current editor rejects it");
        Assert.That(result.Errors, Has.Count.EqualTo(1), result.Describe());
    }

    [Test]
    public void TestUsingACoreInternalWithoutInternalsVisibleToFails()
    {
        _copy.Replace("Runtime/Core/AssemblyInfo.cs", "[assembly: InternalsVisibleTo(\"AvatarGo.Core.Tests\")]", "");
        _copy.Write("Tests/Core/Planted/PlantedInternalTests.cs",
            "using NUnit.Framework;\n\nnamespace AvatarGo.Core.Tests\n{\n    public class PlantedInternalTests\n    {\n" +
            "        [Test]\n        public void UsesAnInternal() => Assert.That(AvatarGo.Core.BvhClip.ToUnity(System.Numerics.Vector3.UnitX).X, Is.EqualTo(-1f));\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo.Core.Tests");
        // Against a compiled AvatarGo.Core (as Unity builds it), internals without InternalsVisibleTo are simply not there: CS0117.
        AssertSingleError(result, "CS0117", "Tests/Core/Planted/PlantedInternalTests.cs", "'BvhClip' does not contain a definition for 'ToUnity'");
    }

    [Test]
    public void DotNetApiBeyondNetStandard21InATestFails()
    {
        _copy.Write("Tests/Core/Planted/PlantedApiTests.cs",
            "using NUnit.Framework;\n\nnamespace AvatarGo.Core.Tests\n{\n    public class PlantedApiTests\n    {\n" +
            "        [Test]\n        public void UsesANet6Api() => Assert.That(System.Math.Clamp(System.Random.Shared.Next(), 0, 1), Is.LessThanOrEqualTo(1));\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo.Core.Tests");
        AssertSingleError(result, "CS0117", "Tests/Core/Planted/PlantedApiTests.cs", "'Random' does not contain a definition for 'Shared'");
    }

    [TestCase("\"Unity.Mathematics\"", "Runtime/AvatarGo.asmdef: reference 'Unity.Mathematics' is no assembly")]
    [TestCase("\"GUID:0123456789abcdef0123456789abcdef\"", "Runtime/AvatarGo.asmdef: reference GUID:0123456789abcdef0123456789abcdef is the GUID of no asmdef")]
    public void AsmdefReferenceToAnAssemblyThatDoesNotExistFails(string reference, string message)
    {
        _copy.Replace("Runtime/AvatarGo.asmdef", "\"AvatarGo.Core\"", "\"AvatarGo.Core\",\n        " + reference);
        var e = Assert.Throws<GateException>(() => Gate(new[] { "editor-2021.3" }));
        Assert.That(e.Message, Does.Contain(message));
    }

    [Test]
    public void UsingAModuleWithoutItsPackageDependencyIsReported()
    {
        // The package's Animator code needs com.unity.modules.animation; take the dependency out of the copy.
        const string dependency = "\"com.unity.modules.animation\": \"1.0.0\",";
        Assert.That(File.ReadAllText(Path.Combine(_copy.Root, "package.json")), Does.Contain(dependency));
        _copy.Replace("package.json", dependency, "");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo");
        Assert.That(result.Succeeded, Is.True, result.Describe());
        List<string> problems = ModuleDependencies.Check(_copy.Root, result);
        Assert.That(problems, Has.Some.StartsWith("package.json: the package uses UnityEngine.AnimationModule (")
            .And.EndsWith("but \"dependencies\" lacks \"com.unity.modules.animation\": \"1.0.0\""), string.Join("\n", problems));
        _copy.Replace("package.json", "\"dependencies\": {", "\"dependencies\": {\n    " + dependency);
        Assert.That(ModuleDependencies.Check(_copy.Root, result), Is.Empty);
    }

    [Test]
    public void AnOptionalPackageUsedOutsideItsGatedAssemblyFails()
    {
        // The Input System's surface is built (the package is in the project), but only AvatarGo.InputSystem references it.
        _copy.Write("Runtime/Tracking/PlantedInputAction.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedInputAction\n    {\n" +
            "        internal static object Make() => new UnityEngine.InputSystem.InputAction(\"x\");\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3" }, "AvatarGo");
        AssertSingleError(result, "CS0234", "Runtime/Tracking/PlantedInputAction.cs", "'InputSystem' does not exist in the namespace 'UnityEngine'");
    }

    [Test]
    public void AnXri2ControllerUsedWithoutItsVersionGuardFailsWithXri3()
    {
        // ActionBasedController is obsolete from XRI 3.0.0: the surface declares it so under XRI_3_OR_NEWER, which the gate
        // defines from the configuration's XRI version (2.0.0 in editor-2021.3, 3.5.1 in editor-6000.5).
        _copy.Write("Runtime/XRInteractionToolkit/PlantedController.cs",
            "namespace AvatarGo\n{\n    internal static class PlantedController\n    {\n" +
            "        internal static object Action(UnityEngine.XR.Interaction.Toolkit.ActionBasedController c) => c.positionAction;\n    }\n}\n");
        GateResult result = Gate(new[] { "editor-2021.3", "editor-6000.5" }, "AvatarGo.XRInteractionToolkit");
        GateDiagnostic error = AssertSingleError(result, "CS0618", "Runtime/XRInteractionToolkit/PlantedController.cs", "'ActionBasedController' is obsolete");
        Assert.That(error.Configuration, Is.EqualTo("editor-6000.5"), "XRI 2.x has it; only XRI 3 deprecates it");
        Assert.That(result.Errors.Select(e => e.Configuration).Distinct(), Is.EqualTo(new[] { "editor-6000.5" }), result.Describe());
    }

    [Test]
    public void OpenVRApiWithoutTheOpenVRXRGuardFailsWithoutThePlugin()
    {
        // Without the OpenVR XR plug-in, openvr_api.cs's types live in the SteamVR assembly, which AvatarGo does not use:
        // the serial lookup must stay under AVATARGO_OPENVR_XR, or the SteamVR-only configuration fails.
        _copy.Replace("Runtime/SteamVR/SteamVRTrackingSource.cs", "#if AVATARGO_OPENVR_XR\n", "#if true\n");
        GateResult result = Gate(new[] { "editor-2021.3", "editor-2021.3-partial" }, "AvatarGo.SteamVR");
        Assert.That(result.Succeeded, Is.False, result.Describe());
        Assert.That(result.Errors.Select(e => e.Configuration).Distinct(), Is.EqualTo(new[] { "editor-2021.3-partial" }), result.Describe());
        Assert.That(result.Errors.Any(e => e.File == "Runtime/SteamVR/SteamVRTrackingSource.cs" && e.Message.Contains("ETrackedDeviceProperty")), Is.True, result.Describe());
    }
    [Test]
    public void OpenXRFeatureAttributeWithoutItsEditorGuardFailsInThePlayerBuild()
    {
        // OpenXR declares OpenXRFeatureAttribute (namespace UnityEditor.XR.OpenXR.Features) in its runtime assembly, but
        // only under #if UNITY_EDITOR: the Editor compiles the unguarded attribute, a player build does not.
        const string feature = "Runtime/OpenXR/ViveTrackerFeature.cs";
        _copy.Replace(feature, "#if UNITY_EDITOR\n    [UnityEditor.XR.OpenXR.Features.OpenXRFeature(", "#if true\n    [UnityEditor.XR.OpenXR.Features.OpenXRFeature(");
        GateResult result = Gate(new[] { "editor-2021.3", "player-2021.3" }, "AvatarGo.OpenXR");
        GateDiagnostic error = AssertSingleError(result, "CS0246", feature, "'UnityEditor' could not be found");
        Assert.That(error.Configuration, Is.EqualTo("player-2021.3"));
        Assert.That(result.Errors.Select(e => e.Configuration).Distinct(), Is.EqualTo(new[] { "player-2021.3" }), result.Describe());
        Assert.That(result.Errors.All(e => e.File == feature && e.Message.Contains("UnityEditor")), Is.True, result.Describe());
    }

    [Test]
    public void FindObjectOfTypeWithoutItsVersionGuardFailsFromUnity2023()
    {
        // Object.FindObjectOfType is obsolete (a warning, an error here as in a warnings-as-errors project) from 2023.1;
        // the XR Origin setup uses FindAnyObjectByType there.
        const string setup = "Runtime/XRInteractionToolkit/XROriginTrackingSetup.cs";
        _copy.Replace(setup, "#if UNITY_2023_1_OR_NEWER\n            if (m_Origin == null) m_Origin = FindAnyObjectByType<XROrigin>();\n#else\n", "#if false\n#else\n");
        GateResult result = Gate(new[] { "editor-2021.3", "editor-6000.5" }, "AvatarGo.XRInteractionToolkit");
        GateDiagnostic error = AssertSingleError(result, "CS0618", setup, "FindObjectOfType");
        Assert.That(error.Configuration, Is.EqualTo("editor-6000.5"));
        Assert.That(result.Errors.Select(e => e.Configuration).Distinct(), Is.EqualTo(new[] { "editor-6000.5" }), result.Describe());
    }
}
