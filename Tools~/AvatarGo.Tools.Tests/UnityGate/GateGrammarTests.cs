using System;
using System.Collections.Generic;
using AvatarGo.UnityGate;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// Unity's expression rules as the gate evaluates them: versionDefines ranges (engine-api.md §6.1, ExpressionTypeFactory.cs)
/// and defineConstraints (DefineConstraintsHelper.cs), with Unity's version orderings.
/// </summary>
[TestFixture]
public class GateGrammarTests
{
    [TestCase("1.2.3", "1.2.3", true)]
    [TestCase("1.2.3", "1.2.2", false)]
    [TestCase("1.2.3", "2.0.0", true)]
    [TestCase("[1.2.3]", "1.2.3", true)]
    [TestCase("[1.2.3]", "1.2.4", false)]
    [TestCase("(1.2.3,)", "1.2.3", false)]
    [TestCase("(1.2.3,)", "1.2.4", true)]
    [TestCase("(,1.2.3]", "1.2.3", true)]
    [TestCase("(,1.2.3]", "1.2.4", false)]
    [TestCase("(,1.2.3)", "1.2.3", false)]
    [TestCase("(,1.2.3)", "1.2.2", true)]
    [TestCase("[1.0,2.0]", "2.0.0", true)]
    [TestCase("[1.0,2.0)", "2.0.0", false)]
    [TestCase("[1.0,2.0)", "1.0.0", true)]
    [TestCase("(1.0,2.0]", "1.0.0", false)]
    [TestCase("(1.0,2.0)", "1.5.0", true)]
    [TestCase("1.0.0", "1.0.0-pre.1", false)] // a pre-release sorts before its release
    [TestCase("[1.0.0-pre.2,1.0.0)", "1.0.0-pre.10", true)] // numeric pre-release parts compare as numbers
    [TestCase("1.2", "1.2.0+build5", true)] // missing parts are 0, build metadata is ignored
    public void PackageRanges(string expression, string version, bool expected) =>
        Assert.That(VersionRange.Parse(expression, unityVersions: false).Contains(SemanticVersion.Parse(version)), Is.EqualTo(expected));

    [TestCase("2021.3", "2021.3.0f1", true)]
    [TestCase("2022.1", "2021.3.45f1", false)]
    [TestCase("[2021.3.11f1,2022.1)", "2021.3.11f1", true)]
    [TestCase("[2021.3.11f1,2022.1)", "2021.3.10f1", false)]
    [TestCase("(,2023.1)", "2023.1.0a1", true)] // an alpha precedes the release: 2023.1.0a1 < 2023.1 (= 2023.1.0f0)
    [TestCase("(,2023.1)", "2023.1.0f1", false)]
    [TestCase("6000.0", "6000.5.2f1", true)]
    [TestCase("2021.3.0b1", "2021.3.0f1", true)]
    [TestCase("[2021.3.0c1]", "2021.3.0f1", true)] // a China release counts as f
    public void EditorRanges(string expression, string version, bool expected) =>
        Assert.That(VersionRange.Parse(expression, unityVersions: true).Contains(UnityVersion.Parse(version)), Is.EqualTo(expected));

    [TestCase("[1.2.3,)", "not a valid expression")] // "at least" is the bare version, never [x,)
    [TestCase("(1.2.3)", "not a valid expression")]
    [TestCase("[1.2.3", "Incomplete expression")]
    [TestCase("1.2.3)", "Incomplete expression")]
    [TestCase("{1.2.3}", "Invalid character '{'")]
    [TestCase("[1.2.3;2.0]", "';' is not valid")]
    [TestCase("1.2.3,2.0", "not a valid expression")]
    [TestCase("[a.b]", "not a valid package version")]
    public void InvalidExpressionsAreRejected(string expression, string message)
    {
        var e = Assert.Throws<FormatException>(() => VersionRange.Parse(expression, unityVersions: false));
        Assert.That(e.Message, Does.Contain(message));
    }

    [TestCase("A", "A", true)]
    [TestCase("A", "B", false)]
    [TestCase("!A", "B", true)]
    [TestCase("!A", "A", false)]
    [TestCase("A || B", "B", true)]
    [TestCase("A || B", "C", false)]
    [TestCase("A || !B", "C", true)] // B undefined satisfies the negation
    [TestCase("A || !B", "B", false)]
    [TestCase("A || !B", "A,B", true)]
    [TestCase("!A || !B", "A", false)] // Unity's quirk: an entry of negations holds only when none is defined
    [TestCase("!A || !B", "C", true)]
    [TestCase("UNITY_EDITOR || UNITY_INCLUDE_TESTS", "UNITY_INCLUDE_TESTS", true)]
    [TestCase("UNITY_EDITOR || UNITY_INCLUDE_TESTS", "UNITY_STANDALONE", false)]
    public void DefineConstraintsFollowUnity(string constraint, string defined, bool expected)
    {
        var defines = new HashSet<string>(defined.Split(','), StringComparer.Ordinal);
        Assert.That(DefineConstraints.Holds(constraint, defines), Is.EqualTo(expected));
    }

    [TestCase("")]
    [TestCase("A || || B")]
    [TestCase("1A")]
    [TestCase("A-B")]
    [TestCase("A || !A")] // cancels out: names no symbol
    public void InvalidDefineConstraintsAreRejected(string constraint) =>
        Assert.Throws<FormatException>(() => DefineConstraints.Holds(constraint, new HashSet<string>()));

    [Test]
    public void EditorVersionSymbolsIncludeEverySeriesUpToTheVersion()
    {
        var symbols = new HashSet<string>(UnityConfiguration.VersionSymbols(UnityVersion.Parse("2021.3.0f1")));
        Assert.That(symbols, Does.Contain("UNITY_2021_3_OR_NEWER").And.Contain("UNITY_5_3_OR_NEWER").And.Contain("UNITY_2021_3_0"));
        Assert.That(symbols, Does.Not.Contain("UNITY_2022_1_OR_NEWER"));
        var current = new HashSet<string>(UnityConfiguration.VersionSymbols(UnityVersion.Parse("6000.5.2f1")));
        Assert.That(current, Does.Contain("UNITY_2023_1_OR_NEWER").And.Contain("UNITY_6000_5_OR_NEWER").And.Contain("UNITY_6000"));
    }
}
