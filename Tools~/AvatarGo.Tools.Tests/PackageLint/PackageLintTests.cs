using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// The package lint, run on this repository's package: each check is one test whose failure message
/// lists every offending path. The checks themselves are proven able to fail by
/// <see cref="PackageLinterSelfTests"/>.
/// </summary>
[TestFixture]
public class PackageLintTests
{
    private PackageLinter _linter;

    [OneTimeSetUp]
    public void FindPackage()
    {
        string root = PackageLinter.FindPackageRoot(TestContext.CurrentContext.TestDirectory, Directory.GetCurrentDirectory());
        Assert.That(root, Is.Not.Null, $"no folder above {TestContext.CurrentContext.TestDirectory} has a package.json named {PackageLinter.PackageName}");
        _linter = new PackageLinter(root);
        Assert.That(_linter.Files, Is.Not.Empty, "the package lists no files");
        TestContext.Progress.WriteLine($"package lint: {_linter.Files.Count} files listed by {_linter.ListingSource} under {root}");
    }

    private static void AssertClean(List<string> problems) =>
        Assert.That(problems, Is.Empty, PackageLinter.Describe(problems));

    [Test]
    public void EveryAssetHasAMetaWithAUniqueGuidAndTheRightImporter() => AssertClean(_linter.CheckMetas());

    [Test]
    public void NoProjectFilesOrBuildOutputOutsideTildeFolders() => AssertClean(_linter.CheckNoBuildArtifacts());

    [Test]
    public void AsmdefsAreValidAndReferencesResolve() => AssertClean(_linter.CheckAsmdefs());

    [Test]
    public void EveryFolderWithCSharpIsCoveredByAnAsmdef() => AssertClean(_linter.CheckAsmdefCoverage());

    [Test]
    public void PackageJsonHasRequiredFields() => AssertClean(_linter.CheckPackageJson());

    [Test]
    public void ChangelogFollowsKeepAChangelog() => AssertClean(_linter.CheckChangelog());

    [Test]
    public void CoreSourcesDoNotUseUnity() => AssertClean(_linter.CheckCoreIsEngineFree());

    [Test]
    public void OnePublicTypePerFileNamedAfterIt() => AssertClean(_linter.CheckOnePublicTypePerFile());

    [Test]
    public void SimulationStaysOutOfTheRuntime() => AssertClean(_linter.CheckAssemblyBoundaries());

    [Test]
    public void InternalsVisibleToIsDeclaredInSource() => AssertClean(_linter.CheckInternalsVisibleToInSource());

    [Test]
    public void RequiredFilesExist() => AssertClean(_linter.CheckRequiredFiles());

    [Test]
    public void TextFilesAreWellFormedAsPvsRequires() => AssertClean(_linter.CheckTextFiles());

    [Test]
    public void PathsFitPvsLimit() => AssertClean(_linter.CheckPathLengths());

    [Test]
    public void LicenseHasACopyrightLine() => AssertClean(_linter.CheckLicense());

    [Test]
    public void DocumentationHasMarkdownPages() => AssertClean(_linter.CheckDocumentation());

    [Test]
    public void TheAvatarGoCoreAsmdefIsChecked()
    {
        // Guards against the lint silently checking nothing (e.g. a listing that lost the asmdefs).
        Assert.That(_linter.Files, Has.Member("Runtime/Core/AvatarGo.Core.asmdef"));
        Assert.That(_linter.Files, Has.Member("package.json.meta"));
    }
}
