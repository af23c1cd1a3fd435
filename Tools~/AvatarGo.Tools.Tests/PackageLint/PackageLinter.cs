using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// Checks that a folder is a UPM package Unity installs from git without a warning. Each check returns
/// the list of problems (empty when clean), each naming the path concerned.
/// </summary>
public sealed class PackageLinter
{
    /// <summary>Assemblies an asmdef may reference besides the package's own: Unity's test runner and the
    /// optional integrations we plan (referenced from satellite asmdefs guarded by defineConstraints).</summary>
    public static readonly string[] AllowedExternalReferences =
    {
        "UnityEngine.TestRunner", "UnityEditor.TestRunner",
        "Unity.XR.OpenXR", "Unity.XR.Interaction.Toolkit", "SteamVR", "Unity.InputSystem", "Unity.XR.CoreUtils",
    };

    private static readonly string[] RootAssets = { "package.json", "README.md", "CHANGELOG.md", "LICENSE.md", "Third Party Notices.md", "Runtime", "Editor", "Tests" };

    private readonly string _root;
    private readonly List<string> _files;   // relative paths with '/', assets and metas, outside ~ and dot folders
    private readonly HashSet<string> _dirs;

    public PackageLinter(string root)
    {
        _root = Path.GetFullPath(root);
        var all = ListFiles(_root);
        _files = all.Where(f => !IsHidden(f)).ToList();
        _dirs = new HashSet<string>(StringComparer.Ordinal);
        foreach (string f in _files)
            for (string d = Parent(f); d.Length > 0; d = Parent(d)) _dirs.Add(d);
        AllFiles = all;
    }

    /// <summary>Every file (tracked or not ignored), `~` folders included.</summary>
    public IReadOnlyList<string> AllFiles { get; }

    public List<string> MissingMetas()
    {
        var problems = new List<string>();
        foreach (string asset in Assets())
            if (!_files.Contains(asset + ".meta")) problems.Add($"{asset}: no .meta (Unity ignores it in a git install)");
        return problems;
    }

    public List<string> OrphanMetas()
    {
        var assets = new HashSet<string>(Assets(), StringComparer.Ordinal);
        return _files.Where(f => f.EndsWith(".meta", StringComparison.Ordinal) && !assets.Contains(f[..^5]))
            .Select(f => $"{f}: its asset does not exist").ToList();
    }

    public List<string> GuidProblems()
    {
        var problems = new List<string>();
        var seen = new Dictionary<string, string>();
        foreach (string meta in _files.Where(f => f.EndsWith(".meta", StringComparison.Ordinal)))
        {
            string text = File.ReadAllText(Path.Combine(_root, meta));
            var m = Regex.Match(text, @"^guid: (\S*)\s*$", RegexOptions.Multiline);
            if (!m.Success) { problems.Add($"{meta}: no guid"); continue; }
            string guid = m.Groups[1].Value;
            if (!Regex.IsMatch(guid, "^[0-9a-f]{32}$")) problems.Add($"{meta}: guid '{guid}' is not 32 lowercase hex digits");
            if (seen.TryGetValue(guid, out string other)) problems.Add($"{meta}: guid {guid} is also used by {other}");
            else seen[guid] = meta;
            string asset = meta[..^5];
            string expected = _dirs.Contains(asset) ? "folderAsset: yes"
                : asset.EndsWith(".cs") ? "MonoImporter:"
                : asset.EndsWith(".asmdef") ? "AssemblyDefinitionImporter:"
                : asset == "package.json" ? "PackageManifestImporter:"
                : null;
            if (expected != null && !text.Contains(expected)) problems.Add($"{meta}: expected '{expected}' for {asset}");
            if (expected == null && !(text.Contains("TextScriptImporter:") || text.Contains("DefaultImporter:")))
                problems.Add($"{meta}: expected TextScriptImporter or DefaultImporter");
        }
        return problems;
    }

    public List<string> BuildArtifactsOutsideTilde() =>
        AllFiles.Where(f => !IsInTilde(f))
            .Where(f => f.EndsWith(".csproj") || f.EndsWith(".sln") || f.EndsWith(".slnx") || f.Split('/').Any(p => p is "bin" or "obj"))
            .Select(f => $"{f}: build files outside a ~ folder break a Unity package").ToList();

    public List<string> AsmdefProblems()
    {
        var problems = new List<string>();
        var asmdefs = new Dictionary<string, (string path, JsonElement json)>();
        foreach (string path in _files.Where(f => f.EndsWith(".asmdef")))
        {
            JsonElement json;
            try { json = JsonDocument.Parse(File.ReadAllText(Path.Combine(_root, path))).RootElement.Clone(); }
            catch (JsonException e) { problems.Add($"{path}: not valid JSON ({e.Message})"); continue; }
            string name = json.TryGetProperty("name", out var n) ? n.GetString() : null;
            if (name != Path.GetFileNameWithoutExtension(path)) problems.Add($"{path}: name '{name}' differs from the file name");
            if (name != null && asmdefs.ContainsKey(name)) problems.Add($"{path}: assembly name '{name}' is also defined by {asmdefs[name].path}");
            else if (name != null) asmdefs[name] = (path, json);
        }
        foreach (var (name, (path, json)) in asmdefs)
        {
            foreach (string reference in Strings(json, "references"))
                if (!asmdefs.ContainsKey(reference) && !AllowedExternalReferences.Contains(reference))
                    problems.Add($"{path}: reference '{reference}' is neither a package asmdef nor an allowed optional assembly");
            bool isTest = Strings(json, "defineConstraints").Contains("UNITY_INCLUDE_TESTS");
            if (path.StartsWith("Tests/") && !isTest) problems.Add($"{path}: test assemblies need UNITY_INCLUDE_TESTS in defineConstraints");
            if (isTest && !Strings(json, "precompiledReferences").Contains("nunit.framework.dll")) problems.Add($"{path}: test assemblies reference nunit.framework.dll");
        }
        if (!asmdefs.TryGetValue("AvatarGo.Core", out var core)) problems.Add("Runtime/Core: no AvatarGo.Core asmdef");
        else
        {
            if (!(core.json.TryGetProperty("noEngineReferences", out var ne) && ne.ValueKind == JsonValueKind.True)) problems.Add($"{core.path}: must set noEngineReferences true");
            if (Strings(core.json, "references").Any()) problems.Add($"{core.path}: the core references nothing");
        }
        if (asmdefs.TryGetValue("AvatarGo.Editor", out var editor) && !Strings(editor.json, "includePlatforms").SequenceEqual(new[] { "Editor" }))
            problems.Add($"{editor.path}: the Editor assembly must include only the Editor platform");
        // Every folder with C# code is covered by the nearest asmdef above it.
        foreach (string cs in _files.Where(f => f.EndsWith(".cs")))
        {
            bool covered = false;
            for (string d = Parent(cs); d.Length > 0 && !covered; d = Parent(d))
                covered = _files.Any(f => Parent(f) == d && f.EndsWith(".asmdef"));
            if (!covered) problems.Add($"{cs}: no asmdef covers it (it would land in Assembly-CSharp)");
        }
        return problems;
    }

    public List<string> ManifestProblems()
    {
        var problems = new List<string>();
        string path = Path.Combine(_root, "package.json");
        if (!File.Exists(path)) return new List<string> { "package.json: missing" };
        JsonElement json;
        try { json = JsonDocument.Parse(File.ReadAllText(path)).RootElement.Clone(); }
        catch (JsonException e) { return new List<string> { $"package.json: not valid JSON ({e.Message})" }; }
        string S(string key) => json.TryGetProperty(key, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;
        if (S("name") != "com.avatargo.selfavatar") problems.Add("package.json: name must be com.avatargo.selfavatar");
        if (S("displayName") != "AvatarGo Self-Avatar") problems.Add("package.json: displayName must be 'AvatarGo Self-Avatar'");
        if (S("version") is not { } version || !Regex.IsMatch(version, @"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$")) problems.Add("package.json: version must be SemVer");
        if (S("unity") != "2021.3") problems.Add("package.json: unity must be 2021.3");
        if (string.IsNullOrWhiteSpace(S("description"))) problems.Add("package.json: description missing");
        if (!json.TryGetProperty("author", out _)) problems.Add("package.json: author missing");
        if (string.IsNullOrWhiteSpace(S("license"))) problems.Add("package.json: license missing");
        if (json.TryGetProperty("samples", out var samples))
            foreach (var sample in samples.EnumerateArray())
            {
                string p = sample.TryGetProperty("path", out var pp) ? pp.GetString() : null;
                if (p == null || !p.StartsWith("Samples~/") || !Directory.Exists(Path.Combine(_root, p))) problems.Add($"package.json: sample path '{p}' does not exist under Samples~");
            }
        return problems;
    }

    public List<string> ChangelogProblems()
    {
        string path = Path.Combine(_root, "CHANGELOG.md");
        if (!File.Exists(path)) return new List<string> { "CHANGELOG.md: missing" };
        var problems = new List<string>();
        string[] lines = File.ReadAllLines(path);
        if (lines.Length == 0 || lines[0] != "# Changelog") problems.Add("CHANGELOG.md:1: the title must be '# Changelog'");
        var versions = lines.Select((l, i) => (l, i)).Where(x => x.l.StartsWith("## ")).ToList();
        if (versions.Count == 0 || versions[0].l != "## [Unreleased]") problems.Add("CHANGELOG.md: the first section must be '## [Unreleased]'");
        foreach (var (l, i) in versions.Skip(1))
            if (!Regex.IsMatch(l, @"^## \[\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?\] - \d{4}-\d{2}-\d{2}$")) problems.Add($"CHANGELOG.md:{i + 1}: version heading must be '## [x.y.z] - YYYY-MM-DD'");
        string[] kinds = { "Added", "Changed", "Deprecated", "Removed", "Fixed", "Security" };
        foreach (var (l, i) in lines.Select((l, i) => (l, i)).Where(x => x.l.StartsWith("### ")))
            if (!kinds.Contains(l[4..])) problems.Add($"CHANGELOG.md:{i + 1}: '{l}' is not one of {string.Join(", ", kinds)}");
        return problems;
    }

    public List<string> SourceProblems()
    {
        var problems = new List<string>();
        foreach (string cs in _files.Where(f => f.EndsWith(".cs") && (f.StartsWith("Runtime/") || f.StartsWith("Editor/") || f.StartsWith("Tests/Core/"))))
        {
            string text = File.ReadAllText(Path.Combine(_root, cs));
            if (cs.StartsWith("Runtime/Core/") && Regex.IsMatch(text, @"^\s*using\s+Unity(Engine|Editor)\b", RegexOptions.Multiline))
                problems.Add($"{cs}: the engine-free core must not use UnityEngine/UnityEditor");
            // Top-level public types: declarations indented by one level inside a namespace block (the layout
            // this package uses). Nested types are indented deeper and are not counted; a file-scoped namespace
            // would be misread, but package code is C# 9, which has none.
            var types = Regex.Matches(text, @"^    public (?:(?:static|sealed|abstract|readonly|partial|ref)\s+)*(?:class|struct|enum|interface|record)\s+(\w+)", RegexOptions.Multiline)
                .Select(m => m.Groups[1].Value).ToList();
            if (types.Count > 1) problems.Add($"{cs}: declares {types.Count} public types ({string.Join(", ", types)}); one per file");
            if (types.Count == 1 && types[0] != Path.GetFileNameWithoutExtension(cs)) problems.Add($"{cs}: declares {types[0]}; the file must be named after it");
        }
        return problems;
    }

    public List<string> RequiredFiles() =>
        new[] { "README.md", "CHANGELOG.md", "LICENSE.md", "Third Party Notices.md", "Documentation~/index.md" }
            .Where(f => !File.Exists(Path.Combine(_root, f))).Select(f => $"{f}: missing").ToList();

    private IEnumerable<string> Assets()
    {
        foreach (string f in _files)
            if (!f.EndsWith(".meta", StringComparison.Ordinal) && IsPackageAsset(f)) yield return f;
        foreach (string d in _dirs)
            if (IsPackageAsset(d)) yield return d;
    }

    private static bool IsPackageAsset(string path) => path.Contains('/') || RootAssets.Contains(path);

    private static bool IsHidden(string path) => path.Split('/').Any(p => p.EndsWith('~') || p.StartsWith('.') || p is "bin" or "obj");

    private static bool IsInTilde(string path) => path.Split('/').Any(p => p.EndsWith('~') || p.StartsWith('.'));

    private static string Parent(string path)
    {
        int slash = path.LastIndexOf('/');
        return slash < 0 ? "" : path[..slash];
    }

    private static IEnumerable<string> Strings(JsonElement json, string key) =>
        json.TryGetProperty(key, out var a) && a.ValueKind == JsonValueKind.Array
            ? a.EnumerateArray().Select(e => e.GetString()) : Enumerable.Empty<string>();

    /// <summary>Files git tracks or would track (not ignored); every file when the folder is not a git checkout.</summary>
    private static List<string> ListFiles(string root)
    {
        if (Directory.Exists(Path.Combine(root, ".git")) || File.Exists(Path.Combine(root, ".git")))
        {
            var psi = new ProcessStartInfo("git", "ls-files -z --cached --others --exclude-standard")
            { WorkingDirectory = root, RedirectStandardOutput = true, UseShellExecute = false };
            using var p = Process.Start(psi);
            string output = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            if (p.ExitCode == 0)
                return output.Split('\0', StringSplitOptions.RemoveEmptyEntries).Where(f => File.Exists(Path.Combine(root, f))).Distinct().ToList();
        }
        return Directory.EnumerateFiles(root, "*", SearchOption.AllDirectories)
            .Select(f => Path.GetRelativePath(root, f).Replace('\\', '/'))
            .Where(f => !f.Split('/').Any(p => p is "bin" or "obj" or ".git")).ToList();
    }
}
