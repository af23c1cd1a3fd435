using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// The package's counterpart of Unity's own DocumentationTests, on the sources: every MonoBehaviour and ScriptableObject
/// of the package (a class whose base chain, through the package's own classes, reaches one of Unity's) has a
/// <c>/// &lt;summary&gt;</c>, a <c>[HelpURL(AvatarGoDocs.Manual + "page.md[#anchor]")]</c> naming a page of
/// <c>Documentation~</c> (and a heading of it, for an anchor), and every serialized field a <c>[Tooltip]</c>; every
/// component that can be added (a non-abstract MonoBehaviour) has <c>[AddComponentMenu("XR/AvatarGo/...")]</c>.
/// Read with Roslyn's parser, so comments and strings cannot fool it; the compile gate checks the code compiles.
/// </summary>
public static class ComponentDocumentation
{
    /// <summary>Unity's classes a package class can derive from, and whether they are components (MonoBehaviour-like).</summary>
    private static readonly Dictionary<string, bool> UnityBases = new(StringComparer.Ordinal)
    {
        ["MonoBehaviour"] = true,
        ["ScriptableObject"] = false,
        // com.unity.xr.openxr: an OpenXR feature is a ScriptableObject.
        ["OpenXRFeature"] = false,
        ["OpenXRInteractionFeature"] = false,
    };

    /// <summary>The problems found in the given sources (path relative to the package, text), checked against the pages of <paramref name="documentation"/>.</summary>
    public static List<string> Check(IEnumerable<(string Path, string Text)> sources, string documentation)
    {
        var classes = new List<(string Path, ClassDeclarationSyntax Class)>();
        foreach ((string path, string text) in sources)
        {
            SyntaxNode root = CSharpSyntaxTree.ParseText(text, new CSharpParseOptions(LanguageVersion.CSharp9, DocumentationMode.Parse,
                preprocessorSymbols: new[] { "UNITY_EDITOR", "UNITY_2021_3_OR_NEWER" })).GetRoot();
            foreach (ClassDeclarationSyntax c in root.DescendantNodes().OfType<ClassDeclarationSyntax>()) classes.Add((path, c));
        }
        var baseOf = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach ((_, ClassDeclarationSyntax c) in classes)
        {
            BaseTypeSyntax first = c.BaseList?.Types.FirstOrDefault();
            if (first != null) baseOf[c.Identifier.Text] = Last(first.Type.ToString());
        }
        var problems = new List<string>();
        foreach ((string path, ClassDeclarationSyntax c) in classes)
        {
            bool? component = UnityKind(c.Identifier.Text, baseOf);
            if (component == null) continue;
            string at = $"{path}: {c.Identifier.Text}";
            if (!HasSummary(c)) problems.Add($"{at} has no /// <summary>");
            bool isAbstract = c.Modifiers.Any(m => m.IsKind(SyntaxKind.AbstractKeyword));
            if (component == true && !isAbstract)
            {
                string menu = StringArgument(Attribute(c, "AddComponentMenu"));
                if (menu == null) problems.Add($"{at} has no [AddComponentMenu(\"XR/AvatarGo/...\")]");
                else if (!menu.StartsWith("XR/AvatarGo/", StringComparison.Ordinal) || menu.Length == "XR/AvatarGo/".Length)
                    problems.Add($"{at}: AddComponentMenu \"{menu}\" is not under XR/AvatarGo/");
            }
            if (!isAbstract) CheckHelpUrl(at, Attribute(c, "HelpURL"), documentation, problems);
            foreach (FieldDeclarationSyntax f in c.Members.OfType<FieldDeclarationSyntax>())
            {
                bool serialized = Has(f.AttributeLists, "SerializeField") ||
                                  (f.Modifiers.Any(m => m.IsKind(SyntaxKind.PublicKeyword)) && !f.Modifiers.Any(m => m.IsKind(SyntaxKind.StaticKeyword) || m.IsKind(SyntaxKind.ConstKeyword) || m.IsKind(SyntaxKind.ReadOnlyKeyword)) && !Has(f.AttributeLists, "NonSerialized"));
                if (serialized && !Has(f.AttributeLists, "Tooltip"))
                    problems.Add($"{at}.{f.Declaration.Variables[0].Identifier.Text} is serialized without a [Tooltip]");
            }
        }
        return problems;
    }

    /// <summary>The package's runtime and editor sources (not the engine-free core, the simulation or the tests), relative paths.</summary>
    public static IEnumerable<(string Path, string Text)> PackageSources(string packageRoot)
    {
        foreach (string top in new[] { "Runtime", "Editor" })
        {
            string dir = Path.Combine(packageRoot, top);
            if (!Directory.Exists(dir)) continue;
            foreach (string file in Directory.EnumerateFiles(dir, "*.cs", SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal))
            {
                string rel = Path.GetRelativePath(packageRoot, file).Replace('\\', '/');
                if (rel.StartsWith("Runtime/Core/", StringComparison.Ordinal) || rel.StartsWith("Runtime/Simulation/", StringComparison.Ordinal)) continue;
                if (rel.Split('/').Any(p => p.EndsWith("~", StringComparison.Ordinal) || p.StartsWith(".", StringComparison.Ordinal))) continue;
                yield return (rel, File.ReadAllText(file));
            }
        }
    }

    /// <summary>GitHub's anchor of a Markdown heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'.</summary>
    public static string Anchor(string heading)
    {
        var b = new StringBuilder();
        foreach (char ch in heading.Trim().ToLowerInvariant())
        {
            if (char.IsLetterOrDigit(ch) || ch == '-' || ch == '_') b.Append(ch);
            else if (ch == ' ') b.Append('-');
        }
        return b.ToString();
    }

    // True for a component, false for a ScriptableObject, null for neither (or a chain that leaves the package elsewhere).
    private static bool? UnityKind(string name, Dictionary<string, string> baseOf)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        while (baseOf.TryGetValue(name, out string b) && seen.Add(name))
        {
            if (UnityBases.TryGetValue(b, out bool component)) return component;
            name = b;
        }
        return null;
    }

    private static void CheckHelpUrl(string at, AttributeSyntax help, string documentation, List<string> problems)
    {
        if (help == null || help.ArgumentList == null || help.ArgumentList.Arguments.Count != 1)
        {
            problems.Add($"{at} has no [HelpURL(AvatarGoDocs.Manual + \"page.md\")]");
            return;
        }
        ExpressionSyntax e = help.ArgumentList.Arguments[0].Expression;
        if (e is not BinaryExpressionSyntax { RawKind: (int)SyntaxKind.AddExpression } add || Last(add.Left.ToString()) != "Manual" ||
            add.Right is not LiteralExpressionSyntax literal || !literal.IsKind(SyntaxKind.StringLiteralExpression))
        {
            problems.Add($"{at}: HelpURL '{e}' is not AvatarGoDocs.Manual + \"page.md\"");
            return;
        }
        string target = literal.Token.ValueText;
        int hash = target.IndexOf('#');
        string page = hash >= 0 ? target.Substring(0, hash) : target;
        string file = Path.Combine(documentation, page);
        if (page.Length == 0 || page.Contains('/') || page.Contains('\\') || !page.EndsWith(".md", StringComparison.Ordinal) || !File.Exists(file))
        {
            problems.Add($"{at}: HelpURL names Documentation~/{page}, which does not exist");
            return;
        }
        if (hash < 0) return;
        string anchor = target.Substring(hash + 1);
        bool found = File.ReadLines(file).Select(l => Regex.Match(l, @"^#{1,6}\s+(.*?)\s*#*\s*$")).Where(m => m.Success).Any(m => Anchor(m.Groups[1].Value) == anchor);
        if (!found) problems.Add($"{at}: HelpURL names Documentation~/{page}#{anchor}, a heading that page does not have");
    }

    private static bool HasSummary(ClassDeclarationSyntax c) =>
        c.GetLeadingTrivia().Select(t => t.GetStructure()).OfType<DocumentationCommentTriviaSyntax>()
            .SelectMany(d => d.Content.OfType<XmlElementSyntax>()).Any(x => x.StartTag.Name.ToString() == "summary" && x.Content.ToString().Trim('/', ' ', '\r', '\n', '\t').Length > 0);

    private static AttributeSyntax Attribute(ClassDeclarationSyntax c, string name) =>
        c.AttributeLists.SelectMany(l => l.Attributes).FirstOrDefault(a => IsNamed(a, name));

    private static bool Has(SyntaxList<AttributeListSyntax> lists, string name) => lists.SelectMany(l => l.Attributes).Any(a => IsNamed(a, name));

    private static bool IsNamed(AttributeSyntax a, string name)
    {
        string n = Last(a.Name.ToString());
        return n == name || n == name + "Attribute";
    }

    private static string StringArgument(AttributeSyntax a) =>
        a?.ArgumentList?.Arguments.FirstOrDefault()?.Expression is LiteralExpressionSyntax l && l.IsKind(SyntaxKind.StringLiteralExpression) ? l.Token.ValueText : null;

    private static string Last(string typeName)
    {
        string t = typeName.Trim();
        int lt = t.IndexOf('<');
        if (lt >= 0) t = t.Substring(0, lt);
        return t.Split('.').Last().Trim();
    }
}
