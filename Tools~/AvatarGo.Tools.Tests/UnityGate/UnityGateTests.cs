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
    public void PlayersCompileTheRuntimeWithoutTheEditor()
    {
        foreach (string name in new[] { "player-2021.3", "player-6000.5" })
        {
            ConfigurationPlan player = Plan(name);
            Assert.That(player.Assemblies.Select(a => a.Name), Is.EquivalentTo(new[] { "UnityEngine", "AvatarGo.Core", "AvatarGo" }), name);
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
