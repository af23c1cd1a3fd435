using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>The package as committed must be valid for Unity; each check reports every offending path.</summary>
public class PackageLintTests
{
    private static PackageLinter Lint() => new PackageLinter(Paths.PackageRoot);

    private static void Clean(List<string> problems) =>
        Assert.That(problems, Is.Empty, string.Join("\n", problems));

    [Test] public void EveryAssetHasAMeta() => Clean(Lint().MissingMetas());
    [Test] public void NoOrphanMetas() => Clean(Lint().OrphanMetas());
    [Test] public void GuidsAreUniqueAndImportersMatch() => Clean(Lint().GuidProblems());
    [Test] public void NoBuildFilesOutsideTildeFolders() => Clean(Lint().BuildArtifactsOutsideTilde());
    [Test] public void AsmdefsParseAndResolve() => Clean(Lint().AsmdefProblems());
    [Test] public void PackageManifestHasItsFields() => Clean(Lint().ManifestProblems());
    [Test] public void ChangelogFollowsKeepAChangelog() => Clean(Lint().ChangelogProblems());
    [Test] public void SourcesAreEngineFreeAndOneTypePerFile() => Clean(Lint().SourceProblems());
    [Test] public void RequiredFilesExist() => Clean(Lint().RequiredFiles());
}

/// <summary>Each check finds a defect planted in a small fake package (so none of them can pass vacuously).</summary>
public class PackageLintCanFailTests
{
    private string _dir;

    [SetUp]
    public void MakeFakePackage()
    {
        _guid = 0; // NUnit reuses the fixture instance between tests
        _dir = Path.Combine(Path.GetTempPath(), "avatargo-lint-" + Guid.NewGuid().ToString("N"));
        Write("package.json", "{\"name\":\"com.avatargo.selfavatar\",\"displayName\":\"AvatarGo Self-Avatar\",\"version\":\"0.1.0\",\"unity\":\"2021.3\",\"description\":\"d\",\"author\":{\"name\":\"a\"},\"license\":\"MIT\",\"samples\":[{\"path\":\"Samples~/S\"}]}");
        Meta("package.json", "PackageManifestImporter:");
        Write("CHANGELOG.md", "# Changelog\n\n## [Unreleased]\n\n### Added\n- x\n\n## [0.1.0] - 2026-01-01\n");
        Meta("CHANGELOG.md", "TextScriptImporter:");
        Directory.CreateDirectory(Path.Combine(_dir, "Samples~", "S"));
        Write("Runtime/Core/AvatarGo.Core.asmdef", "{\"name\":\"AvatarGo.Core\",\"references\":[],\"noEngineReferences\":true}");
        Meta("Runtime", "folderAsset: yes"); Meta("Runtime/Core", "folderAsset: yes");
        Meta("Runtime/Core/AvatarGo.Core.asmdef", "AssemblyDefinitionImporter:");
        Write("Runtime/Core/Thing.cs", "namespace A\n{\n    public sealed class Thing { }\n}\n");
        Meta("Runtime/Core/Thing.cs", "MonoImporter:");
    }

    [TearDown]
    public void Remove() => Directory.Delete(_dir, true);

    private int _guid;

    private void Write(string rel, string text)
    {
        string path = Path.Combine(_dir, rel);
        Directory.CreateDirectory(Path.GetDirectoryName(path));
        File.WriteAllText(path, text);
    }

    private void Meta(string rel, string importer, string guid = null) =>
        Write(rel + ".meta", $"fileFormatVersion: 2\nguid: {guid ?? (++_guid).ToString("x32")}\n{importer}\n");

    private PackageLinter Lint() => new PackageLinter(_dir);

    [Test]
    public void TheFakePackageIsClean()
    {
        var l = Lint();
        Assert.That(l.MissingMetas(), Is.Empty);
        Assert.That(l.GuidProblems(), Is.Empty);
        Assert.That(l.AsmdefProblems(), Is.Empty);
        Assert.That(l.ManifestProblems(), Is.Empty);
        Assert.That(l.ChangelogProblems(), Is.Empty);
        Assert.That(l.SourceProblems(), Is.Empty);
    }

    [Test]
    public void FindsAMissingMetaAndAnOrphan()
    {
        Write("Runtime/Core/New.cs", "namespace A { }");
        Write("Runtime/Core/Gone.cs.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000abcd\nMonoImporter:\n");
        StringAssert.Contains("Runtime/Core/New.cs", string.Join("\n", Lint().MissingMetas()));
        StringAssert.Contains("Runtime/Core/Gone.cs.meta", string.Join("\n", Lint().OrphanMetas()));
    }

    [Test]
    public void FindsADuplicateGuidAndAWrongImporter()
    {
        File.WriteAllText(Path.Combine(_dir, "Runtime/Core/Thing.cs.meta"), "fileFormatVersion: 2\nguid: 00000000000000000000000000000001\nDefaultImporter:\n");
        string problems = string.Join("\n", Lint().GuidProblems());
        StringAssert.Contains("also used by", problems);
        StringAssert.Contains("MonoImporter", problems);
    }

    [Test]
    public void FindsACsprojOutsideTilde()
    {
        Write("Runtime/Core/Oops.csproj", "<Project/>");
        Write("Tools~/Fine.csproj", "<Project/>");
        var problems = Lint().BuildArtifactsOutsideTilde();
        Assert.That(problems.Count, Is.EqualTo(1));
        StringAssert.Contains("Oops.csproj", problems[0]);
    }

    [Test]
    public void FindsABadAsmdefReferenceAndAnEngineReferencingCore()
    {
        Write("Runtime/Core/AvatarGo.Core.asmdef", "{\"name\":\"AvatarGo.Core\",\"references\":[\"Nowhere.Assembly\"],\"noEngineReferences\":false}");
        string problems = string.Join("\n", Lint().AsmdefProblems());
        StringAssert.Contains("Nowhere.Assembly", problems);
        StringAssert.Contains("noEngineReferences", problems);
    }

    [Test]
    public void FindsABadChangelogAndManifest()
    {
        Write("CHANGELOG.md", "# Changelog\n\n## 0.1.0\n\n### Stuff\n");
        Write("package.json", "{\"name\":\"com.other\",\"version\":\"one\",\"samples\":[{\"path\":\"Samples~/Missing\"}]}");
        Assert.That(Lint().ChangelogProblems().Count, Is.GreaterThanOrEqualTo(2));
        string manifest = string.Join("\n", Lint().ManifestProblems());
        StringAssert.Contains("name", manifest);
        StringAssert.Contains("SemVer", manifest);
        StringAssert.Contains("Samples~/Missing", manifest);
    }

    [Test]
    public void FindsTwoPublicTypesInAFileAndUnityInTheCore()
    {
        Write("Runtime/Core/Thing.cs", "using UnityEngine;\nnamespace A\n{\n    public sealed class Thing { }\n    public enum Other { }\n}\n");
        string problems = string.Join("\n", Lint().SourceProblems());
        StringAssert.Contains("UnityEngine", problems);
        StringAssert.Contains("2 public types", problems);
    }
}
