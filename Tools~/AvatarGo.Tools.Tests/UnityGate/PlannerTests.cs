using System;
using System.IO;
using System.Linq;
using AvatarGo.UnityGate;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// The planner on small fake packages: which files go into which assembly, how references, platforms,
/// defineConstraints and versionDefines decide what each configuration compiles, and what it refuses.
/// </summary>
[TestFixture]
public class PlannerTests
{
    private string _root;

    [SetUp]
    public void CreatePackage()
    {
        _root = Path.Combine(Path.GetTempPath(), "avatargo-planner-" + Guid.NewGuid().ToString("N"));
        Write("package.json", "{ \"name\": \"com.avatargo.selfavatar\" }");
        Directory.CreateDirectory(Path.Combine(_root, "Tools~", "UnitySurface", "UnityEngine"));
        Directory.CreateDirectory(Path.Combine(_root, "Tools~", "UnitySurface", "UnityEditor"));
        Directory.CreateDirectory(Path.Combine(_root, "Tools~", "UnitySurface", "UnityEngine.TestRunner"));
        Directory.CreateDirectory(Path.Combine(_root, "Tools~", "UnitySurface", "UnityEditor.TestRunner"));
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\" }", guid: "11111111111111111111111111111111");
        Write("Runtime/A.cs", "");
        Write("Runtime/Sub/B.cs", "");
        Write("Runtime/Nested/Nested.asmdef", "{ \"name\": \"Nested\", \"references\": [\"GUID:11111111111111111111111111111111\"] }");
        Write("Runtime/Nested/C.cs", "");
        Write("Runtime/Nested/Deeper/D.cs", "");
        Write("Runtime/Hidden~/E.cs", "");
        Write("Runtime/.hidden/F.cs", "");
    }

    [TearDown]
    public void DeletePackage() => Directory.Delete(_root, recursive: true);

    private void Write(string relative, string text, string guid = null)
    {
        string path = Path.Combine(_root, relative);
        Directory.CreateDirectory(Path.GetDirectoryName(path));
        File.WriteAllText(path, text);
        if (guid != null) File.WriteAllText(path + ".meta", $"fileFormatVersion: 2\nguid: {guid}\n");
    }

    private Planner Planner => new(_root, AvatarGo.UnityGate.Program.NuGetPackageRoot);

    private static UnityConfiguration Editor => UnityConfiguration.Named("editor-2021.3");

    [Test]
    public void SourcesAreTheFolderMinusNestedAsmdefFoldersAndHiddenOnes()
    {
        Planner planner = Planner;
        Assert.That(planner.SourcesOf(planner.Asmdefs.Single(a => a.Name == "Main")), Is.EqualTo(new[] { "Runtime/A.cs", "Runtime/Sub/B.cs" }));
        Assert.That(planner.SourcesOf(planner.Asmdefs.Single(a => a.Name == "Nested")), Is.EqualTo(new[] { "Runtime/Nested/C.cs", "Runtime/Nested/Deeper/D.cs" }));
    }

    [Test]
    public void GuidReferencesResolveAndEngineReferencesFollowTheConfiguration()
    {
        AssemblyPlan nested = Planner.Plan(Editor).Assemblies.Single(a => a.Name == "Nested");
        Assert.That(nested.References, Is.EqualTo(new[] { "UnityEngine", "UnityEditor", "Main" }));
        AssemblyPlan player = Planner.Plan(UnityConfiguration.Named("player-2021.3")).Assemblies.Single(a => a.Name == "Nested");
        Assert.That(player.References, Is.EqualTo(new[] { "UnityEngine", "Main" }), "a player build has no UnityEditor");
        Assert.That(player.Defines, Does.Not.Contain("UNITY_EDITOR"));
        Assert.That(nested.Defines, Does.Contain("UNITY_EDITOR").And.Contain("UNITY_2021_3_OR_NEWER").And.Contain("NETSTANDARD2_1"));
    }

    [Test]
    public void NoEngineReferencesMeansNoUnityAssemblies()
    {
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"noEngineReferences\": true }", guid: "11111111111111111111111111111111");
        AssemblyPlan main = Planner.Plan(Editor).Assemblies.Single(a => a.Name == "Main");
        Assert.That(main.References, Is.Empty);
    }

    [Test]
    public void PlatformsDecideWhereAnAssemblyIsCompiled()
    {
        Write("Editor/Tools.asmdef", "{ \"name\": \"Tools\", \"includePlatforms\": [\"Editor\"] }");
        Write("Editor/T.cs", "");
        Write("Desktop/NotWindows.asmdef", "{ \"name\": \"NotWindows\", \"excludePlatforms\": [\"WindowsStandalone64\"] }");
        Write("Desktop/W.cs", "");
        ConfigurationPlan editor = Planner.Plan(Editor), player = Planner.Plan(UnityConfiguration.Named("player-2021.3"));
        Assert.That(editor.Assemblies.Select(a => a.Name), Does.Contain("Tools").And.Contain("NotWindows"));
        Assert.That(editor.Assemblies.Single(a => a.Name == "Tools").Defines, Does.Contain("NET_UNITY_4_8"), "editor-only assemblies get the .NET Framework API level's symbols");
        Assert.That(player.Skipped.Select(s => s.Name + ": " + s.Reason), Does.Contain("Tools: includePlatforms lacks WindowsStandalone64")
            .And.Contain("NotWindows: excludePlatforms has WindowsStandalone64"));
    }

    [Test]
    public void VersionDefinesFeedDefineConstraints()
    {
        Write("Tests/T.asmdef", "{ \"name\": \"T\", \"references\": [\"UnityEngine.TestRunner\", \"UnityEditor.TestRunner\"], \"includePlatforms\": [\"Editor\"]," +
                                " \"overrideReferences\": true, \"precompiledReferences\": [\"nunit.framework.dll\"], \"defineConstraints\": [\"UNITY_INCLUDE_TESTS\"] }");
        Write("Tests/T.cs", "");
        Write("Integrations/OpenXR.asmdef", "{ \"name\": \"OpenXR\", \"defineConstraints\": [\"HAS_TF\", \"EDITOR_2021_3_11\"], \"versionDefines\": [" +
                                            "{ \"name\": \"com.unity.test-framework\", \"expression\": \"[1.1,2.0)\", \"define\": \"HAS_TF\" }," +
                                            "{ \"name\": \"Unity\", \"expression\": \"2021.3.11f1\", \"define\": \"EDITOR_2021_3_11\" } ] }");
        Write("Integrations/O.cs", "");
        ConfigurationPlan full = Planner.Plan(Editor);
        Assert.That(full.Skipped.Select(s => s.Name + ": " + s.Reason), Does.Contain("OpenXR: define constraint \"EDITOR_2021_3_11\" does not hold"));
        AssemblyPlan tests = full.Assemblies.Single(a => a.Name == "T");
        Assert.That(tests.PrecompiledReferences.Single(), Does.EndWith("nunit/3.6.0/lib/net35/nunit.framework.dll"));
        Assert.That(tests.RequireDocs, Is.False);
        ConfigurationPlan bare = Planner.Plan(UnityConfiguration.Named("editor-2021.3-bare"));
        Assert.That(bare.Skipped.Select(s => s.Name + ": " + s.Reason), Does.Contain("T: define constraint \"UNITY_INCLUDE_TESTS\" does not hold")
            .And.Contain("OpenXR: define constraint \"HAS_TF\" does not hold"));
        ConfigurationPlan current = Planner.Plan(UnityConfiguration.Named("editor-6000.5"));
        Assert.That(current.Assemblies.Select(a => a.Name), Does.Contain("OpenXR"), "Test Framework 1.4.6 is in [1.1,2.0) and 6000.5.2f1 >= 2021.3.11f1");
    }

    [Test]
    public void ReferenceToNoAssemblyIsAnError()
    {
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"references\": [\"Unity.Mathematics\"] }", guid: "11111111111111111111111111111111");
        var e = Assert.Throws<GateException>(() => Planner.Plan(Editor));
        Assert.That(e.Message, Does.Contain("Runtime/Main.asmdef: reference 'Unity.Mathematics' is no assembly"));
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"references\": [\"GUID:0123456789abcdef0123456789abcdef\"] }", guid: "11111111111111111111111111111111");
        e = Assert.Throws<GateException>(() => Planner.Plan(Editor));
        Assert.That(e.Message, Does.Contain("reference GUID:0123456789abcdef0123456789abcdef is the GUID of no asmdef"));
    }

    [Test]
    public void UnknownPrecompiledDllAndInvalidExpressionsAreErrors()
    {
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"overrideReferences\": true, \"precompiledReferences\": [\"Newtonsoft.Json.dll\"] }");
        Assert.That(Assert.Throws<GateException>(() => Planner.Plan(Editor)).Message, Does.Contain("precompiled reference 'Newtonsoft.Json.dll'"));
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"versionDefines\": [ { \"name\": \"Unity\", \"expression\": \"[2021.3,)\", \"define\": \"X\" } ] }");
        Assert.That(Assert.Throws<GateException>(() => Planner.Plan(Editor)).Message, Does.Contain("'[2021.3,)' is not a valid expression"));
        Write("Runtime/Main.asmdef", "{ \"name\": \"Main\", \"defineConstraints\": [\"A || || B\"] }");
        Assert.That(Assert.Throws<GateException>(() => Planner.Plan(Editor)).Message, Does.Contain("Invalid Define Constraint"));
    }

    [Test]
    public void LegacyTestAssemblySwitchIsExpandedAsUnityDoes()
    {
        Write("Tests/Legacy.asmdef", "{ \"name\": \"Legacy\", \"optionalUnityReferences\": [\"TestAssemblies\"] }");
        Write("Tests/L.cs", "");
        AssemblyPlan legacy = Planner.Plan(Editor).Assemblies.Single(a => a.Name == "Legacy");
        Assert.That(legacy.References, Does.Contain("UnityEngine.TestRunner").And.Contain("UnityEditor.TestRunner"));
        Assert.That(legacy.PrecompiledReferences, Has.Count.EqualTo(1));
        Assert.That(Planner.Plan(UnityConfiguration.Named("player-2021.3")).Skipped.Select(s => s.Name), Does.Contain("Legacy"));
    }

    [Test]
    public void AsmdefWithoutScriptsIsSkipped()
    {
        Write("Empty/Empty.asmdef", "{ \"name\": \"Empty\" }");
        Assert.That(Planner.Plan(Editor).Skipped.Single(s => s.Name == "Empty").Reason, Does.StartWith("no scripts"));
    }
}
