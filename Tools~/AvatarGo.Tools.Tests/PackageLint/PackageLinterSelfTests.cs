using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// Each lint check, run on a temporary fake package: clean it reports nothing; with one planted defect
/// it reports exactly that defect by path. Without these the lint tests could pass by checking nothing.
/// </summary>
[TestFixture]
public class PackageLinterSelfTests
{
    private FakePackage _pkg;

    [SetUp]
    public void CreatePackage() => _pkg = new FakePackage();

    [TearDown]
    public void DeletePackage() => _pkg.Dispose();

    private static void AssertReported(List<string> problems, params string[] fragments)
    {
        foreach (string fragment in fragments)
            Assert.That(problems.Any(p => p.Contains(fragment, StringComparison.Ordinal)), Is.True,
                $"expected a problem containing \"{fragment}\", got {PackageLinter.Describe(problems)}");
    }

    [Test]
    public void CleanFakePackageHasNoProblems()
    {
        PackageLinter linter = _pkg.Linter;
        List<string> problems = linter.CheckAll();
        Assert.That(problems, Is.Empty, PackageLinter.Describe(problems));
        Assert.That(linter.ListingSource, Is.EqualTo("walk"));
        Assert.That(linter.Files, Has.Member("Runtime/Core/Math/Thing.cs.meta"));
        Assert.That(linter.Files, Has.Member("Tools~/AvatarGo.Core/AvatarGo.Core.csproj"), "`~` folders ship too (PVS checks their text files)");
        Assert.That(linter.Files.Any(f => f.Contains("/bin/", StringComparison.Ordinal)), Is.False, "build output is ignored, as .gitignore does");
    }

    [Test]
    public void MissingMetaIsReported()
    {
        _pkg.Delete("Runtime/Core/Math/Thing.cs.meta");
        _pkg.Delete("Runtime/Core/Math.meta");
        AssertReported(_pkg.Linter.CheckMetas(), "Runtime/Core/Math/Thing.cs: no .meta", "Runtime/Core/Math: no .meta");
    }

    [Test]
    public void AStrayFileAtTheRootIsReported()
    {
        _pkg.Write("f_main.json", "{}");
        _pkg.Write("Scratch/notes.txt", "x");
        AssertReported(_pkg.Linter.CheckMetas(), "f_main.json: at the package root but no package entry", "Scratch: at the package root but no package entry");
    }

    [Test]
    public void OrphanMetaIsReported()
    {
        _pkg.Write("Runtime/Gone.cs.meta", FakePackage.Meta("Runtime/Gone.cs", folder: false));
        _pkg.Write("Runtime/EmptyFolder.meta", FakePackage.Meta("Runtime/EmptyFolder", folder: true));
        Directory.CreateDirectory(Path.Combine(_pkg.Root, "Runtime/EmptyFolder"));
        AssertReported(_pkg.Linter.CheckMetas(), "Runtime/Gone.cs.meta: orphan", "Runtime/EmptyFolder.meta: orphan");
    }

    [Test]
    public void DuplicateGuidIsReported()
    {
        string guid = _pkg.GuidOf("Runtime/AvatarGo.asmdef.meta");
        _pkg.Delete("Editor/AvatarGo.Editor.asmdef.meta");
        _pkg.Write("Editor/AvatarGo.Editor.asmdef.meta", FakePackage.Meta("Editor/AvatarGo.Editor.asmdef", folder: false, guid));
        AssertReported(_pkg.Linter.CheckMetas(), $"Runtime/AvatarGo.asmdef.meta: guid {guid} is also used by Editor/AvatarGo.Editor.asmdef.meta");
    }

    [Test]
    public void MalformedGuidIsReported()
    {
        _pkg.Write("README.md.meta", FakePackage.Meta("README.md", folder: false, "0123456789ABCDEF0123456789abcdef"));
        AssertReported(_pkg.Linter.CheckMetas(), "README.md.meta: guid '0123456789ABCDEF0123456789abcdef' is not 32 lowercase hex");
    }

    [Test]
    public void WrongImporterIsReported()
    {
        _pkg.Write("Runtime/Core/Math/Thing.cs.meta", FakePackage.Meta("Thing.md", folder: false));
        _pkg.Write("Runtime/Core.meta", FakePackage.Meta("Runtime/Core.cs", folder: false));
        _pkg.Write("package.json.meta", FakePackage.Meta("x.md", folder: false));
        AssertReported(_pkg.Linter.CheckMetas(),
            "Runtime/Core/Math/Thing.cs.meta: importer TextScriptImporter, expected MonoImporter",
            "Runtime/Core.meta: Runtime/Core is a folder but the .meta lacks 'folderAsset: yes'",
            "package.json.meta: importer TextScriptImporter, expected PackageManifestImporter");
    }

    [Test]
    public void ProjectFilesOutsideTildeFoldersAreReported()
    {
        _pkg.Write("Runtime/AvatarGo.csproj", "<Project />");
        _pkg.Write("Editor/Tools.slnx", "<Solution />");
        _pkg.Write("Runtime/obj/project.assets.json", "{}");
        List<string> problems = _pkg.Linter.CheckNoBuildArtifacts();
        AssertReported(problems, "Runtime/AvatarGo.csproj", "Editor/Tools.slnx", "Runtime/obj/");
        Assert.That(problems.Any(p => p.StartsWith("Tools~", StringComparison.Ordinal)), Is.False, PackageLinter.Describe(problems));
    }

    [Test]
    public void UnresolvedAsmdefReferenceIsReported()
    {
        _pkg.Write("Runtime/AvatarGo.asmdef", FakePackage.Asmdef("AvatarGo", "\"AvatarGo.Core\", \"Unity.Mathematics\", \"GUID:00000000000000000000000000000000\""));
        AssertReported(_pkg.Linter.CheckAsmdefs(), "Runtime/AvatarGo.asmdef: reference 'Unity.Mathematics'",
            "Runtime/AvatarGo.asmdef: reference GUID:00000000000000000000000000000000");
    }

    [Test]
    public void GuidAndAllowListedReferencesResolve()
    {
        string coreGuid = _pkg.GuidOf("Runtime/Core/AvatarGo.Core.asmdef.meta");
        _pkg.Write("Runtime/AvatarGo.asmdef", FakePackage.Asmdef("AvatarGo", $"\"GUID:{coreGuid}\", \"Unity.XR.OpenXR\", \"SteamVR\""));
        List<string> problems = _pkg.Linter.CheckAsmdefs();
        Assert.That(problems, Is.Empty, PackageLinter.Describe(problems));
    }

    [Test]
    public void AsmdefRuleBreachesAreReported()
    {
        _pkg.Write("Runtime/Core/AvatarGo.Core.asmdef", FakePackage.Asmdef("AvatarGo.Core", "\"AvatarGo\""));
        _pkg.Write("Editor/AvatarGo.Editor.asmdef", FakePackage.Asmdef("AvatarGo.Editor", "\"AvatarGo\""));
        _pkg.Write("Tests/Core/AvatarGo.Core.Tests.asmdef", FakePackage.Asmdef("AvatarGo.Core.Tests", "\"AvatarGo.Core\""));
        _pkg.Write("Tests/Runtime/Renamed.asmdef", FakePackage.Asmdef("AvatarGo", "", test: true));
        _pkg.Write("Tests/Broken/Broken.asmdef", "{ \"name\": \"Broken\", ");
        _pkg.MakeMetas();
        AssertReported(_pkg.Linter.CheckAsmdefs(),
            "Runtime/Core/AvatarGo.Core.asmdef: AvatarGo.Core must have \"noEngineReferences\": true",
            "Runtime/Core/AvatarGo.Core.asmdef: AvatarGo.Core must reference nothing",
            "Editor/AvatarGo.Editor.asmdef: an Editor asmdef must have \"includePlatforms\": [\"Editor\"]",
            "Tests/Core/AvatarGo.Core.Tests.asmdef: a test asmdef needs UNITY_INCLUDE_TESTS",
            "Tests/Core/AvatarGo.Core.Tests.asmdef: a test asmdef needs nunit.framework.dll",
            "Tests/Runtime/Renamed.asmdef: name 'AvatarGo' differs from the file name 'Renamed'",
            "asmdef name 'AvatarGo' is used by Runtime/AvatarGo.asmdef, Tests/Runtime/Renamed.asmdef",
            "Tests/Broken/Broken.asmdef: not valid JSON");
    }

    [Test]
    public void CSharpFolderWithoutAsmdefIsReported()
    {
        _pkg.Write("Tests/Loose/LooseTests.cs", "public class LooseTests { }\n");
        _pkg.MakeMetas();
        AssertReported(_pkg.Linter.CheckAsmdefCoverage(), "Tests/Loose/: holds .cs files but no asmdef covers it");
    }

    [Test]
    public void PackageJsonDefectsAreReported()
    {
        string json = _pkg.Read("package.json").Replace("\"0.1.0\"", "\"0.1\"").Replace("\"2021.3\"", "\"2022.3\"")
            .Replace("Samples~/Demo", "Samples~/Missing").Replace("\"license\": \"MIT\",", "");
        _pkg.Write("package.json", json);
        AssertReported(_pkg.Linter.CheckPackageJson(), "\"version\" \"0.1\" is not SemVer", "\"unity\" is \"2022.3\"",
            "sample path \"Samples~/Missing\" does not exist", "\"license\" is missing");
        _pkg.Write("package.json", json.Replace("Samples~/Missing", "Runtime"));
        AssertReported(_pkg.Linter.CheckPackageJson(), "sample path \"Runtime\" is not a folder under Samples~/");
    }

    [TestCase("# Changes\n\n## [Unreleased]\n", "title is '# Changes'")]
    [TestCase("# Changelog\n\n## [0.1.0] - 2024-01-01\n\n## [Unreleased]\n", "the first section must be '## [Unreleased]'")]
    [TestCase("# Changelog\n\n## [Unreleased]\n\n## 0.1.0 - 2024-01-01\n", "is not '## [x.y.z] - YYYY-MM-DD'")]
    [TestCase("# Changelog\n\n## [Unreleased]\n\n## [0.1.0] - 2024-13-01\n", "'2024-13-01' is not a real date")]
    [TestCase("# Changelog\n\n## [Unreleased]\n\n## [0.1] - 2024-01-01\n", "version '0.1' is not SemVer")]
    [TestCase("# Changelog\n\n## [Unreleased]\n\n## [0.1.0] - 2024-01-01\n\n## [0.2.0] - 2024-02-01\n", "version 0.2.0 is not older than 0.1.0")]
    [TestCase("# Changelog\n\n## [Unreleased]\n\n### New features\n- x\n", "subsection 'New features' is not one of")]
    [TestCase("# Changelog\n\n### Added\n- x\n", "subsection 'Added' outside any version section")]
    [TestCase("# Changelog\n", "no '## [Unreleased]' section")]
    public void ChangelogDefectsAreReported(string text, string expected)
    {
        _pkg.Write("CHANGELOG.md", text);
        AssertReported(_pkg.Linter.CheckChangelog(), expected);
    }

    [Test]
    public void ChangelogHeadingsInCodeFencesAreIgnored()
    {
        List<string> problems = PackageLinter.CheckChangelogText(
            "# Changelog\n\n## [Unreleased]\n\n### Changed\n- Example:\n```\n# not a title\n### Nope\n```\n".Split('\n'));
        Assert.That(problems, Is.Empty, PackageLinter.Describe(problems));
    }

    [Test]
    public void UnityUsingInCoreIsReported()
    {
        _pkg.Write("Runtime/Core/Math/Thing.cs", "using System;\nusing UnityEngine;\n// using UnityEditor; (a comment is fine)\n" +
                                                 "namespace AvatarGo.Core { public struct Thing { } }\n");
        List<string> problems = _pkg.Linter.CheckCoreIsEngineFree();
        AssertReported(problems, "Runtime/Core/Math/Thing.cs: 'using UnityEngine'");
        Assert.That(problems, Has.Count.EqualTo(1), PackageLinter.Describe(problems));
    }

    [Test]
    public void RuntimeReferencingTheSimulationAssemblyIsReported()
    {
        _pkg.Write("Runtime/AvatarGo.asmdef", FakePackage.Asmdef("AvatarGo", "\"AvatarGo.Core\", \"GUID:" + _pkg.GuidOf("Runtime/Simulation/AvatarGo.Simulation.asmdef.meta") + "\""));
        _pkg.Write("Runtime/Core/AvatarGo.Core.asmdef", FakePackage.Asmdef("AvatarGo.Core", "\"AvatarGo.Simulation\"", noEngineReferences: true));
        _pkg.Write("Runtime/Simulation/AvatarGo.Simulation.asmdef", FakePackage.Asmdef("AvatarGo.Simulation", "\"AvatarGo.Core\""));
        List<string> problems = _pkg.Linter.CheckAssemblyBoundaries();
        AssertReported(problems, "Runtime/AvatarGo.asmdef: runtime assembly AvatarGo references AvatarGo.Simulation",
            "Runtime/Core/AvatarGo.Core.asmdef: runtime assembly AvatarGo.Core references AvatarGo.Simulation",
            "must have \"noEngineReferences\": true", "must have \"autoReferenced\": false", "UNITY_EDITOR || UNITY_INCLUDE_TESTS");
        Assert.That(problems, Has.Count.EqualTo(5), PackageLinter.Describe(problems));
    }

    [Test]
    public void InternalsVisibleToOnlyInMsbuildIsReported()
    {
        _pkg.Delete("Runtime/Core/AssemblyInfo.cs");
        _pkg.Delete("Runtime/Core/AssemblyInfo.cs.meta");
        _pkg.Write("Tools~/AvatarGo.Core/AvatarGo.Core.csproj",
            "<Project>\n  <ItemGroup><Compile Include=\"$(PackageRoot)/Runtime/Core/**/*.cs\" /></ItemGroup>\n" +
            "  <ItemGroup><InternalsVisibleTo Include=\"AvatarGo.Core.Tests\" /></ItemGroup>\n</Project>\n");
        List<string> problems = _pkg.Linter.CheckInternalsVisibleToInSource();
        AssertReported(problems, "Tools~/AvatarGo.Core/AvatarGo.Core.csproj: declares InternalsVisibleTo in MSBuild",
            "Runtime/Core: no source file declares");
        Assert.That(problems, Has.Count.EqualTo(2), PackageLinter.Describe(problems));
    }

    [Test]
    public void SecondPublicTypeOrMisnamedFileIsReported()
    {
        _pkg.Write("Runtime/Core/Math/Thing.cs", "namespace AvatarGo.Core\n{\n    public struct Thing { }\n    public enum ThingKind { A }\n}\n");
        _pkg.Write("Tests/Core/Math/ThingTests.cs", "namespace AvatarGo.Core.Tests;\n\npublic sealed class OtherTests { }\n");
        AssertReported(_pkg.Linter.CheckOnePublicTypePerFile(),
            "Runtime/Core/Math/Thing.cs: 2 public top-level types (Thing, ThingKind)",
            "Tests/Core/Math/ThingTests.cs: declares public type OtherTests, so the file should be OtherTests.cs");
    }

    [Test]
    public void PartsOfAPartialTypeMayBeNamedTypeDotPart()
    {
        _pkg.Write("Runtime/Core/Math/Thing.Io.cs", "namespace AvatarGo.Core { public partial struct Thing { } }\n");
        _pkg.Write("Runtime/Core/Math/Thing.Extra.cs", "namespace AvatarGo.Core { public struct Thing { } }\n");
        _pkg.MakeMetas();
        List<string> problems = _pkg.Linter.CheckOnePublicTypePerFile();
        AssertReported(problems, "Runtime/Core/Math/Thing.Extra.cs: declares public type Thing");
        Assert.That(problems, Has.Count.EqualTo(1), PackageLinter.Describe(problems));
    }

    [TestCase("namespace A { public class B { public class Nested { } public enum E { X } } }", "B")]
    [TestCase("namespace A;\n[System.Serializable]\npublic readonly struct P { }\ninternal class Q { }", "P")]
    [TestCase("namespace A { public static class X { const string S = \"public class Y {\"; const char C = '{'; } }", "X")]
    [TestCase("namespace A { /* public class Y { */ public sealed record R(int V); }", "R")]
    [TestCase("namespace A { public delegate void Handler<T>(T value); }", "Handler")]
    [TestCase("namespace A { public class G<T> where T : class\n{ } }", "G")]
    [TestCase("namespace A.B { namespace C { public interface I { } } }", "I")]
    [TestCase("namespace A { internal class Hidden { public class Inner { } } }", "")]
    public void PublicTopLevelTypesAreFound(string source, string expected)
    {
        string found = string.Join(",", PackageLinter.PublicTopLevelTypes(source));
        Assert.That(found, Is.EqualTo(expected));
    }

    [Test]
    public void MalformedTextFilesAreReported()
    {
        File.WriteAllText(Path.Combine(_pkg.Root, "Runtime/Core/Math/Thing.cs"), "namespace AvatarGo.Core\r\n{\r\n    public struct Thing { }\r\n}\r\n");
        File.WriteAllBytes(Path.Combine(_pkg.Root, "README.md"), new byte[] { 0xEF, 0xBB, 0xBF, (byte)'#', (byte)'\n' });
        _pkg.Write("Documentation~/index.md", "# Manual\n\nTrailing space here \n");
        _pkg.Write("Tools~/notes.txt", "a\tb\n");
        File.WriteAllBytes(Path.Combine(_pkg.Root, "CHANGELOG.md"), new byte[] { (byte)'#', 0xC3, (byte)'\n' });
        List<string> problems = _pkg.Linter.CheckTextFiles();
        AssertReported(problems, "Runtime/Core/Math/Thing.cs:1: carriage return", "README.md: UTF-8 byte-order mark",
            "Documentation~/index.md:3: trailing whitespace", "Tools~/notes.txt:1: tab character", "CHANGELOG.md: not well-formed UTF-8");
        Assert.That(problems, Has.Count.EqualTo(5), PackageLinter.Describe(problems));
    }

    [Test]
    public void DataAndMetaFilesAreOutsideThePvsTextRules()
    {
        File.WriteAllText(Path.Combine(_pkg.Root, "Samples~/Demo/clip.bvh"), "HIERARCHY\r\n\tROOT Hips \r\n"); // byte-exact mocap data (.gitattributes -text)
        _pkg.Write("README.md.meta", FakePackage.Meta("README.md", folder: false) + "  assetBundleName: \n"); // Unity writes these
        List<string> problems = _pkg.Linter.CheckTextFiles();
        Assert.That(problems, Is.Empty, PackageLinter.Describe(problems));
    }

    [Test]
    public void PathLongerThan140IsReported()
    {
        string path = "Runtime/" + new string('a', 130) + ".cs";
        _pkg.Write(path, "namespace AvatarGo { }\n");
        AssertReported(_pkg.Linter.CheckPathLengths(), path + ": 141 characters, PVS allows 140");
    }

    [TestCase("MIT License\n\nPermission is hereby granted.\n", "LICENSE.md: no copyright line")]
    [TestCase(null, "LICENSE.md: missing")]
    public void LicenseWithoutCopyrightIsReported(string text, string expected)
    {
        if (text == null) _pkg.Delete("LICENSE.md");
        else _pkg.Write("LICENSE.md", text);
        AssertReported(_pkg.Linter.CheckLicense(), expected);
    }

    [Test]
    public void CopyrightWithTheSignOrAYearRangeIsAccepted()
    {
        _pkg.Write("LICENSE.md", "com.avatargo.selfavatar copyright © 2024-2026 AvatarGo contributors\n");
        Assert.That(_pkg.Linter.CheckLicense(), Is.Empty);
    }

    [Test]
    public void DocumentationWithoutPagesIsReported()
    {
        _pkg.Write("Documentation~/index.md", "# Doc\n");
        AssertReported(_pkg.Linter.CheckDocumentation(), "Documentation~/index.md: fewer than 10 characters");
        _pkg.Delete("Documentation~/index.md");
        AssertReported(_pkg.Linter.CheckDocumentation(), "Documentation~: no .md file");
        _pkg.Write("Documentation~/Index.md", "# Manual\n\nHow to use it.\n");
        AssertReported(_pkg.Linter.CheckDocumentation(), "Documentation~/index.md: missing or not lowercase");
    }

    [Test]
    public void MissingRequiredFileIsReported()
    {
        _pkg.Delete("Documentation~/index.md");
        _pkg.Delete("Third Party Notices.md");
        _pkg.Delete("Third Party Notices.md.meta");
        AssertReported(_pkg.Linter.CheckRequiredFiles(), "Documentation~/index.md: missing", "Third Party Notices.md: missing");
    }

    [Test]
    public void GitListingSkipsIgnoredFilesAndCountsUntrackedOnes()
    {
        if (!Git("init -q")) Assert.Ignore("git is not available");
        _pkg.Write(".gitignore", "*.local.txt\n");
        _pkg.Write("Runtime/notes.local.txt", "ignored, so no .meta needed");
        _pkg.Write("Runtime/New.txt", "untracked but not ignored: would be committed, needs a .meta");
        PackageLinter linter = _pkg.Linter;
        List<string> problems = linter.CheckMetas();
        Assert.That(linter.ListingSource, Is.EqualTo("git"));
        Assert.That(linter.Files, Has.No.Member("Runtime/notes.local.txt"));
        AssertReported(problems, "Runtime/New.txt: no .meta");
        Assert.That(problems, Has.Count.EqualTo(1), PackageLinter.Describe(problems));
    }

    private bool Git(string arguments)
    {
        try
        {
            using Process p = Process.Start(new ProcessStartInfo("git", arguments)
            {
                WorkingDirectory = _pkg.Root, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false,
            });
            p.WaitForExit();
            return p.ExitCode == 0;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return false;
        }
    }
}
