using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// The manual holds together as a reader follows it: the table of contents lists every page, every page another page
/// names (`name.md`, `name.md#heading`) exists with that heading, and the component pages and menu paths the quick
/// start sends a developer to are the ones the code declares.
/// </summary>
public class ManualTests
{
    private static string Docs => Path.Combine(Paths.PackageRoot, "Documentation~");

    private static readonly Regex PageReference = new(@"(?<![A-Za-z0-9_/""-])`?(?<page>[a-z0-9][a-z0-9-]*\.md)(?:#(?<anchor>[a-z0-9_-]+))?`?", RegexOptions.CultureInvariant);

    private static IEnumerable<string> Pages() => Directory.GetFiles(Docs, "*.md").Select(Path.GetFileName).OrderBy(p => p, StringComparer.Ordinal);

    private static HashSet<string> Anchors(string page) => File.ReadLines(Path.Combine(Docs, page))
        .Select(l => Regex.Match(l, @"^#{1,6}\s+(.*?)\s*#*\s*$")).Where(m => m.Success)
        .Select(m => ComponentDocumentation.Anchor(m.Groups[1].Value)).ToHashSet(StringComparer.Ordinal);

    [Test]
    public void TheTableOfContentsListsEveryPage()
    {
        string index = File.ReadAllText(Path.Combine(Docs, "index.md"));
        var listed = PageReference.Matches(index).Select(m => m.Groups["page"].Value).ToHashSet(StringComparer.Ordinal);
        List<string> missing = Pages().Where(p => p != "index.md" && !listed.Contains(p)).ToList();
        Assert.That(missing, Is.Empty, "pages index.md does not list");
    }

    [Test]
    public void EveryPageThePagesNameExistsWithItsHeading()
    {
        var problems = new List<string>();
        var pages = Pages().ToHashSet(StringComparer.Ordinal);
        foreach (string page in pages)
        {
            string[] lines = File.ReadAllLines(Path.Combine(Docs, page));
            for (int i = 0; i < lines.Length; i++)
                foreach (Match m in PageReference.Matches(lines[i]))
                {
                    string target = m.Groups["page"].Value;
                    if (target is "README.md" or "CHANGELOG.md") continue;
                    if (!pages.Contains(target)) { problems.Add($"{page}:{i + 1}: {target} does not exist"); continue; }
                    string anchor = m.Groups["anchor"].Value;
                    if (anchor.Length > 0 && !Anchors(target).Contains(anchor)) problems.Add($"{page}:{i + 1}: {target} has no heading #{anchor}");
                }
        }
        Assert.That(problems, Is.Empty, string.Join("\n", problems));
    }

    /// <summary>
    /// The wearer's page lists every message a refused step can show, as the core words it (found in review: "every
    /// message" lacked NotInsideAvatar, the walk-in refused from too far, and AvatarScaleOutOfRange).
    /// </summary>
    [Test]
    public void TheHeadsetPageHasEveryRefusalsMessage()
    {
        string page = File.ReadAllText(Path.Combine(Docs, "headset-calibration.md"));
        var missing = new List<string>();
        foreach (AvatarGo.Core.CalibrationError error in Enum.GetValues(typeof(AvatarGo.Core.CalibrationError)))
            if (error != AvatarGo.Core.CalibrationError.None && !page.Contains($"| `{error}` | {AvatarGo.Core.CalibrationMessages.For(error)} |", StringComparison.Ordinal))
                missing.Add($"{error}: {AvatarGo.Core.CalibrationMessages.For(error)}");
        Assert.That(missing, Is.Empty, "rows of headset-calibration.md's message table missing or worded otherwise");
    }

    [Test]
    public void TheQuickStartsMenusAndComponentsAreTheCodes()
    {
        string quick = File.ReadAllText(Path.Combine(Docs, "quick-start.md"));
        string code = string.Join("\n", Directory.GetFiles(Path.Combine(Paths.PackageRoot, "Runtime"), "*.cs", SearchOption.AllDirectories)
            .Concat(Directory.GetFiles(Path.Combine(Paths.PackageRoot, "Editor"), "*.cs", SearchOption.AllDirectories)).Select(File.ReadAllText));
        // Every component the quick start names in bold, as the inspector titles it ("AvatarGo Calibrator").
        foreach (string component in new[] { "AvatarGoCalibrator", "AvatarGoFingers", "XRInputDevicesTrackingSource" })
            Assert.That(code, Does.Contain("class " + component + " "), component);
        Assert.That(quick, Does.Contain("**AvatarGo Calibrator**").And.Contain("**AvatarGo Fingers**"));
        // Every field it names exists as a serialized field (Unity shows m_FieldName as "Field Name").
        foreach (string field in new[] { "m_Animator", "m_Driver", "m_Offsets", "m_RestoreSavedProfile", "m_TrackingSpaceOrigin" })
        {
            Assert.That(code, Does.Contain(" " + field + " ").Or.Contain(" " + field + ";"), field);
            string shown = Regex.Replace(field.Substring(2), "(?<=[a-z])(?=[A-Z])", " ");
            Assert.That(quick, Does.Contain("**" + shown + "**"), $"the quick start names {field} as Unity shows it");
        }
    }
}
