using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace AvatarGo.UnityGate;

/// <summary>
/// Compares the surface with Unity's own sources (a local git clone of Unity-Technologies/UnityCsReference, or of a
/// needle-mirror package): for every declaration, the file its source comment names is read at that branch with
/// `git show`, parsed with Roslyn, and must declare a member of the same name, kind (field, property, method,
/// constructor, operator, enum), static-ness, parameter types and modifiers, and for properties the same accessors;
/// a type must have the same kind and first base type. The same file on the current branch (6000.5) is compared too,
/// and differences there are listed as notes. Needs no network, but the clones are not in CI: run by hand.
/// </summary>
public static class SurfaceVerifier
{
    /// <summary>The branch the current editor's sources are compared on.</summary>
    public const string CurrentBranch = "6000.5";

    /// <summary>
    /// The symbols Unity's and the packages' sources are parsed with: those the real assemblies see where AvatarGo uses
    /// them (the Editor, XR enabled: the Input System's XR types sit in #if UNITY_INPUT_SYSTEM_ENABLE_XR &amp;&amp; ENABLE_VR,
    /// OpenXR's feature attribute in #if UNITY_EDITOR), and the oldest supported editor's version symbols.
    /// </summary>
    public static IReadOnlyList<string> SourceSymbols { get; } = new[] { "UNITY_EDITOR", "ENABLE_VR", "UNITY_INPUT_SYSTEM_ENABLE_XR", "UNITY_INPUT_SYSTEM_ENABLE_VR" }
        .Concat(UnityConfiguration.VersionSymbols(UnityConfiguration.Oldest)).ToList();

    /// <summary>Verifies every surface file; returns problems and writes notes to <paramref name="log"/>.</summary>
    /// <param name="surfaceRoot">Tools~/UnitySurface.</param>
    /// <param name="sources">Source alias ("UnityCsReference", "com.unity.test-framework") to its git directory.</param>
    /// <param name="log">Where each checked declaration is reported.</param>
    public static List<string> Verify(string surfaceRoot, IReadOnlyDictionary<string, string> sources, TextWriter log)
    {
        var problems = new List<string>();
        var parse = new CSharpParseOptions(LanguageVersion.Preview);
        foreach (string file in Directory.GetFiles(surfaceRoot, "*.cs", SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal))
        {
            // Every flavour of the surface: the Editor, the current editor's version symbols and every package-version symbol,
            // so that members declared for newer versions are checked too (against the source their comment names).
            var surfaceSymbols = new[] { "UNITY_EDITOR" }.Concat(UnityConfiguration.VersionSymbols(UnityConfiguration.Current))
                .Concat(UnityCatalog.SurfaceAssemblies.SelectMany(a => a.VersionDefines).Select(v => v.Define)).Distinct();
            SyntaxNode root = CSharpSyntaxTree.ParseText(File.ReadAllText(file), parse.WithPreprocessorSymbols(surfaceSymbols)).GetRoot();
            foreach (BaseTypeDeclarationSyntax type in root.DescendantNodes().OfType<BaseTypeDeclarationSyntax>())
            {
                var members = type is TypeDeclarationSyntax td ? td.Members.Where(m => m is not BaseTypeDeclarationSyntax).ToList()
                    : ((EnumDeclarationSyntax)type).Members.Cast<MemberDeclarationSyntax>().ToList();
                foreach (SyntaxNode declaration in new SyntaxNode[] { type }.Concat(members))
                {
                    string source = SurfaceUsage.SourceOf(declaration);
                    var m = source == null ? null : SurfaceUsage.SourceComment.Match("// " + source);
                    string what = $"{type.Identifier.Text}{(declaration == type ? "" : "." + Name(declaration))}";
                    if (m == null || !m.Success) { problems.Add($"{file}: {what} names no source"); continue; }
                    if (!sources.TryGetValue(m.Groups["repo"].Value, out string git)) { log.WriteLine($"  skipped {what}: no clone given for {m.Groups["repo"].Value}"); continue; }
                    // Unity's own sources on the current editor's branch; a package's at its newest snapshot (the mirror's HEAD).
                    string current = m.Groups["repo"].Value == "UnityCsReference" ? CurrentBranch : "HEAD";
                    foreach (string branch in new[] { m.Groups["ref"].Value, current }.Distinct())
                    {
                        string text = Show(git, branch, m.Groups["path"].Value);
                        string verdict = text == null ? "file missing" : Compare(type, declaration, CSharpSyntaxTree.ParseText(text, parse.WithPreprocessorSymbols(SourceSymbols)).GetRoot());
                        bool primary = branch == m.Groups["ref"].Value;
                        if (verdict == null) log.WriteLine($"  ok   {what} @{branch} {m.Groups["path"].Value}");
                        else if (primary) problems.Add($"{what}: {verdict} in {m.Groups["repo"].Value}@{branch} {m.Groups["path"].Value}");
                        else log.WriteLine($"  note {what} @{branch}: {verdict}");
                    }
                }
            }
        }
        return problems;
    }

    private static string Compare(BaseTypeDeclarationSyntax surfaceType, SyntaxNode declaration, SyntaxNode unity)
    {
        var candidates = unity.DescendantNodes().OfType<BaseTypeDeclarationSyntax>()
            .Where(t => t.Identifier.Text == surfaceType.Identifier.Text && Arity(t) == Arity(surfaceType)).ToList();
        if (candidates.Count == 0) return $"no type {surfaceType.Identifier.Text}";
        if (declaration == surfaceType)
        {
            BaseTypeDeclarationSyntax u = candidates[0];
            if (u.Kind() != surfaceType.Kind()) return $"declared as {u.Kind()}, not {surfaceType.Kind()}";
            string ub = Last(u.BaseList?.Types.FirstOrDefault()?.Type.ToString()), sb = Last(surfaceType.BaseList?.Types.FirstOrDefault()?.Type.ToString());
            if (sb != null && ub != sb) return $"first base type is {ub ?? "none"}, not {sb}";
            return null;
        }
        string want = Signature(declaration);
        var found = candidates.SelectMany(t => t is TypeDeclarationSyntax td ? td.Members.Cast<SyntaxNode>() : ((EnumDeclarationSyntax)t).Members)
            .Where(n => Name(n) == Name(declaration)).ToList();
        if (found.Count == 0) return "no member of that name";
        if (found.Any(n => Signature(n) == want)) return null;
        return $"signature differs: surface '{want}', Unity '{string.Join("' | '", found.Select(Signature))}'";
    }

    // InputControl and InputControl<TValue> are different types.
    private static int Arity(BaseTypeDeclarationSyntax t) => (t as TypeDeclarationSyntax)?.TypeParameterList?.Parameters.Count ?? 0;

    private static string Name(SyntaxNode n) => n switch
    {
        IndexerDeclarationSyntax => "this[]",
        MethodDeclarationSyntax x => x.Identifier.Text,
        PropertyDeclarationSyntax x => x.Identifier.Text,
        FieldDeclarationSyntax x => x.Declaration.Variables[0].Identifier.Text,
        ConstructorDeclarationSyntax x => ".ctor",
        OperatorDeclarationSyntax x => "op" + x.OperatorToken.Text,
        EnumMemberDeclarationSyntax x => x.Identifier.Text,
        EventFieldDeclarationSyntax x => x.Declaration.Variables[0].Identifier.Text,
        EventDeclarationSyntax x => x.Identifier.Text,
        _ => n.Kind().ToString(),
    };

    private static readonly string[] ComparedModifiers = { "public", "protected", "internal", "private", "static", "const", "readonly" };

    // Kind, static-ness, visibility, types by their last name segment, parameter modifiers, accessors, enum values.
    private static string Signature(SyntaxNode n)
    {
        // In one canonical order: Unity writes "static public" as often as "public static".
        string Mods(SyntaxTokenList m) => string.Join(" ", m.Select(t => t.Text).Where(t => Array.IndexOf(ComparedModifiers, t) >= 0).OrderBy(t => Array.IndexOf(ComparedModifiers, t)));
        string Params(ParameterListSyntax p) => "(" + string.Join(", ", p.Parameters.Select(x => (x.Modifiers.ToString() + " " + Last(x.Type?.ToString())).Trim() + " " + x.Identifier.Text)) + ")";
        return n switch
        {
            MethodDeclarationSyntax x => $"{Mods(x.Modifiers)} {Last(x.ReturnType.ToString())} {x.Identifier.Text}{Params(x.ParameterList)}",
            ConstructorDeclarationSyntax x => $"{Mods(x.Modifiers)} .ctor{Params(x.ParameterList)}",
            OperatorDeclarationSyntax x => $"{Mods(x.Modifiers)} {Last(x.ReturnType.ToString())} operator{x.OperatorToken.Text}{Params(x.ParameterList)}",
            PropertyDeclarationSyntax x => $"{Mods(x.Modifiers)} {Last(x.Type.ToString())} {x.Identifier.Text} {{{string.Join(" ", (x.AccessorList?.Accessors.Select(a => (Mods(a.Modifiers) + " " + a.Keyword.Text).Trim()) ?? new[] { "get" }))}}}",
            IndexerDeclarationSyntax x => $"{Mods(x.Modifiers)} {Last(x.Type.ToString())} this[{string.Join(", ", x.ParameterList.Parameters.Select(p => Last(p.Type?.ToString()) + " " + p.Identifier.Text))}] {{{string.Join(" ", (x.AccessorList?.Accessors.Select(a => (Mods(a.Modifiers) + " " + a.Keyword.Text).Trim()) ?? new[] { "get" }))}}}",
            FieldDeclarationSyntax x => $"{Mods(x.Modifiers)} {Last(x.Declaration.Type.ToString())} {x.Declaration.Variables[0].Identifier.Text}",
            EnumMemberDeclarationSyntax x => $"{x.Identifier.Text} = {x.EqualsValue?.Value}",
            // An event with accessors and a field-like event are the same to a caller: kind, type and name.
            EventDeclarationSyntax x => $"{Mods(x.Modifiers)} event {Last(x.Type.ToString())} {x.Identifier.Text}",
            EventFieldDeclarationSyntax x => $"{Mods(x.Modifiers)} event {Last(x.Declaration.Type.ToString())} {x.Declaration.Variables[0].Identifier.Text}",
            _ => n.ToString(),
        };
    }

    private static string Last(string typeName) => typeName?.Split('.').Last().Trim();

    private static string Show(string gitDir, string branch, string path)
    {
        var psi = new ProcessStartInfo("git") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in new[] { "-C", gitDir, "show", $"{branch}:{path}" }) psi.ArgumentList.Add(a);
        using Process p = Process.Start(psi);
        string text = p.StandardOutput.ReadToEnd();
        p.StandardError.ReadToEnd();
        p.WaitForExit();
        return p.ExitCode == 0 ? text : null;
    }
}
