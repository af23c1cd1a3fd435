using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using AvatarGo.UnityGate;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// The compile gate on this repository's package: every standard configuration (see
/// <see cref="UnityConfiguration.Standard"/>) is planned from the asmdefs, written as MSBuild projects under
/// Tools~/out/gate and compiled once in-process; the tests then check the outcome, what each configuration compiled, and that the
/// surface declares nothing the package does not use. <see cref="PlantedDefectTests"/> proves the gate can fail, and
/// <see cref="CompilerAgreementTests"/> that MSBuild builds the generated projects with the same outcome.
/// </summary>
[TestFixture]
public class UnityGateTests
{
    private GateResult _gate;

    [OneTimeSetUp]
    public void BuildEveryConfiguration()
    {
        _gate = GateBuild.Run(Paths.PackageRoot, AvatarGo.UnityGate.Program.NuGetPackageRoot, UnityConfiguration.Standard);
        TestContext.Progress.WriteLine($"unity gate: {UnityConfiguration.Standard.Count} configurations, {_gate.Projects.Graph.Assemblies.Count} distinct assemblies " +
                                       $"({_gate.Reused} compiled earlier in this run), in-process " +
                                       $"{_gate.Seconds:0.0} s wall, {_gate.CpuSeconds:0.0} s processor ({_gate.Errors.Count} errors)");
    }

    private ConfigurationPlan Plan(string name) => _gate.Plans.Single(p => p.Configuration.Name == name);

    [Test]
    public void EveryConfigurationCompiles() => Assert.That(_gate.Succeeded, Is.True, _gate.Describe());

    [Test]
    public void TheEditorCompilesTheCoreTestsTheUnityWay()
    {
        foreach (string name in new[] { "editor-2021.3", "editor-6000.5" })
        {
            AssemblyPlan tests = Plan(name).Assemblies.Single(a => a.Name == "AvatarGo.Core.Tests");
            Assert.That(tests.References, Is.EquivalentTo(new[] { "UnityEngine", "UnityEditor", "AvatarGo.Core", "AvatarGo.Simulation", "UnityEngine.TestRunner", "UnityEditor.TestRunner" }), name);
            Assert.That(tests.PrecompiledReferences.Single(), Does.Contain("/nunit/3.6.0/lib/"), name);
            Assert.That(tests.Sources, Has.Count.GreaterThan(10), name);
        }
        Assert.That(Plan("editor-2021.3").Assemblies.Single(a => a.Name == "AvatarGo.Core.Tests").PrecompiledReferences.Single(), Does.Contain("/net35/"),
            "Unity 2021.3's ext.nunit 1.0.6 is a net35 build");
        string project = File.ReadAllText(Directory.GetFiles(_gate.OutDir, "AvatarGo.Core.Tests.*.csproj", SearchOption.AllDirectories).First());
        Assert.That(project, Does.Contain("<TargetFramework>netstandard2.1</TargetFramework>").And.Contain("<LangVersion>9.0</LangVersion>")
            .And.Contain("<TreatWarningsAsErrors>true</TreatWarningsAsErrors>")
            .And.Contain("<DisableImplicitConfigurationDefines>true</DisableImplicitConfigurationDefines>")
            .And.Contain("<DisableImplicitFrameworkDefines>true</DisableImplicitFrameworkDefines>"),
            "Unity defines no RELEASE and no NETSTANDARD2_1_OR_GREATER: the SDK must not add them");
    }

    [Test]
    public void WithoutOptionalPackagesTestAssembliesAreSkippedAndTheRestCompiles()
    {
        ConfigurationPlan bare = Plan("editor-2021.3-bare");
        Assert.That(bare.Skipped.Single(s => s.Name == "AvatarGo.Core.Tests").Reason, Is.EqualTo("define constraint \"UNITY_INCLUDE_TESTS\" does not hold"));
        Assert.That(bare.Assemblies.Select(a => a.Name), Does.Contain("AvatarGo").And.Contain("AvatarGo.Core").And.Not.Contain("UnityEngine.TestRunner"));
    }

    [Test]
    public void EachIntegrationCompilesExactlyWhereItsPackageIs()
    {
        string[] integrations = { "AvatarGo.InputSystem", "AvatarGo.OpenXR", "AvatarGo.SteamVR", "AvatarGo.XRInteractionToolkit" };
        foreach (string name in new[] { "editor-2021.3", "editor-6000.5", "player-2021.3", "player-6000.5" })
            Assert.That(Plan(name).Assemblies.Select(a => a.Name), Is.SupersetOf(integrations), name);
        ConfigurationPlan bare = Plan("editor-2021.3-bare");
        Assert.That(bare.Assemblies.Select(a => a.Name), Has.None.AnyOf(integrations));
        Assert.That(bare.Skipped.Single(s => s.Name == "AvatarGo.SteamVR").Reason, Is.EqualTo("define constraint \"AVATARGO_STEAMVR\" does not hold"));
        ConfigurationPlan partial = Plan("editor-2021.3-partial");
        Assert.That(partial.Assemblies.Select(a => a.Name), Does.Contain("AvatarGo.XRInteractionToolkit").And.Contain("AvatarGo.SteamVR")
            .And.Not.Contain("AvatarGo.InputSystem").And.Not.Contain("AvatarGo.OpenXR"));
        AssemblyPlan xri = partial.Assemblies.Single(a => a.Name == "AvatarGo.XRInteractionToolkit");
        Assert.That(xri.References, Does.Not.Contain("Unity.InputSystem").And.Not.Contain("Unity.XR.Interaction.Toolkit"), "references to absent packages are dropped");
        Assert.That(xri.Defines, Does.Contain("AVATARGO_XR_CORE_UTILS").And.Not.Contain("AVATARGO_XRI_2"));
        Assert.That(partial.Assemblies.Single(a => a.Name == "AvatarGo.SteamVR").Defines, Does.Not.Contain("AVATARGO_OPENVR_XR"));
        Assert.That(Plan("editor-2021.3").Assemblies.Single(a => a.Name == "AvatarGo.SteamVR").Defines, Does.Contain("AVATARGO_OPENVR_XR"));
        // XRI 2.0.0 in the oldest editor, 3.5.1 in the current one: each compiles its own side of the XRI version guards.
        Assert.That(Plan("editor-2021.3").Assemblies.Single(a => a.Name == "AvatarGo.XRInteractionToolkit").Defines,
            Does.Contain("AVATARGO_XRI_2").And.Not.Contain("AVATARGO_XRI_2_4_OR_NEWER"));
        Assert.That(Plan("editor-6000.5").Assemblies.Single(a => a.Name == "AvatarGo.XRInteractionToolkit").Defines,
            Does.Contain("AVATARGO_XRI_2_4_OR_NEWER").And.Not.Contain("AVATARGO_XRI_2"));
        Assert.That(Plan("editor-2021.3").Assemblies.Single(a => a.Name == "AvatarGo.OpenXR").Defines, Does.Not.Contain("AVATARGO_OPENXR_1_9_OR_NEWER"));
        Assert.That(Plan("editor-6000.5").Assemblies.Single(a => a.Name == "AvatarGo.OpenXR").Defines, Does.Contain("AVATARGO_OPENXR_1_9_OR_NEWER"));
    }

    [Test]
    public void PlayersCompileTheRuntimeWithoutTheEditor()
    {
        foreach (string name in new[] { "player-2021.3", "player-6000.5" })
        {
            ConfigurationPlan player = Plan(name);
            Assert.That(player.Assemblies.Select(a => a.Name), Is.EquivalentTo(new[]
            {
                "UnityEngine", "AvatarGo.Core", "AvatarGo",
                "Unity.InputSystem", "Unity.XR.OpenXR", "Unity.XR.CoreUtils", "Unity.XR.Interaction.Toolkit", "Unity.XR.OpenVR", "SteamVR",
                "AvatarGo.InputSystem", "AvatarGo.OpenXR", "AvatarGo.SteamVR", "AvatarGo.XRInteractionToolkit",
            }), name);
            Assert.That(player.Assemblies.SelectMany(a => a.Defines), Does.Not.Contain("UNITY_EDITOR"), name);
            Assert.That(player.Skipped.Single(s => s.Name == "AvatarGo.Simulation").Reason, Does.Contain("UNITY_EDITOR || UNITY_INCLUDE_TESTS"), name);
        }
    }

    [Test]
    public void EverySurfaceDeclarationNamesItsUnitySource()
    {
        List<SurfaceDeclaration> declarations = SurfaceUsage.Declarations(Paths.PackageRoot, UnityConfiguration.Standard);
        Assert.That(declarations, Is.Not.Empty);
        var unnamed = declarations.Where(d => d.Source == null).Select(d => $"{d.Id} ({d.File})").ToList();
        Assert.That(unnamed, Is.Empty, "declarations without a '// UnityCsReference@2021.3 path' comment on them or their type");
        TestContext.Progress.WriteLine("surface: " + string.Join("; ", declarations.Select(d => $"{d.Id} <- {d.Source}")));
    }

    [Test]
    public void SurfaceDeclaresNothingThePackageDoesNotUse()
    {
        Assume.That(_gate.Succeeded, "the gate build failed (see EveryConfigurationCompiles)");
        SortedSet<string> used = SurfaceUsage.Used(_gate);
        var unused = SurfaceUsage.Declarations(Paths.PackageRoot, UnityConfiguration.Standard).Where(d => !used.Contains(d.Id)).Select(d => $"{d.Id} ({d.File})").ToList();
        Assert.That(unused, Is.Empty, "surface declarations the package's code never references: remove them (or use them)");
        Assert.That(used, Does.Contain("M:UnityEngine.Transform.SetPositionAndRotation(UnityEngine.Vector3,UnityEngine.Quaternion)"));
    }

    [Test]
    public void BuiltInModulesThePackageUsesAreDeclaredDependencies()
    {
        Assume.That(_gate.Succeeded, "the gate build failed (see EveryConfigurationCompiles)");
        List<string> problems = ModuleDependencies.Check(Paths.PackageRoot, _gate);
        Assert.That(problems, Is.Empty, string.Join("\n", problems));
    }
}
