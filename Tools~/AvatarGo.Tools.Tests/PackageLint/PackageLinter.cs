using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// Static checks of the Unity package layout that Unity itself would only report (or silently get
/// wrong) after someone installs the package: .meta files and GUIDs, asmdefs, package.json, the
/// CHANGELOG, engine-free core sources, one public type per file. Every check returns a list of
/// problems, each naming the offending path; an empty list means the check passed. The checks work
/// on any folder, so the self-tests run them on small fake packages with planted defects.
/// </summary>
public sealed class PackageLinter
{
    /// <summary>The package name this repository ships.</summary>
    public const string PackageName = "com.avatargo.selfavatar";

    /// <summary>
    /// Root entries Unity imports as package assets (each needs a .meta). Everything else at the root is
    /// either a `~` folder or a dot entry (never imported) or repository furniture. Keep in step with
    /// ROOT_ENTRIES in Tools~/make-metas.py.
    /// </summary>
    public static readonly IReadOnlyList<string> RootAssets = new[]
    {
        "package.json", "README.md", "CHANGELOG.md", "LICENSE.md", "Third Party Notices.md",
        "Runtime", "Editor", "Tests",
    };

    /// <summary>
    /// Assemblies an asmdef may reference that are not defined in this package. This is the one place
    /// to add to, with a reason:
    /// - UnityEngine.TestRunner, UnityEditor.TestRunner: Unity Test Framework (test asmdefs only).
    /// - Unity.XR.OpenXR: optional OpenXR device backend (com.unity.xr.openxr).
    /// - Unity.XR.Interaction.Toolkit: optional XRI integration (com.unity.xr.interaction.toolkit).
    /// - SteamVR: optional SteamVR plugin backend (trackers by serial/role).
    /// - Unity.InputSystem: optional Input System source (com.unity.inputsystem), also the OpenXR tracker layout's base.
    /// - Unity.XR.CoreUtils: optional XR Origin integration (com.unity.xr.core-utils).
    /// - Unity.XR.OpenVR: the OpenVR API types of the OpenVR XR plug-in (com.valvesoftware.unity.openvr), for serials.
    /// Optional ones must sit behind defineConstraints/versionDefines so the package compiles without them.
    /// </summary>
    public static readonly IReadOnlyList<string> AllowedExternalAssemblies = new[]
    {
        "UnityEngine.TestRunner",
        "UnityEditor.TestRunner",
        "Unity.XR.OpenXR",
        "Unity.XR.Interaction.Toolkit",
        "SteamVR",
        "Unity.InputSystem",
        "Unity.XR.CoreUtils",
        "Unity.XR.OpenVR",
    };

    /// <summary>Files that must exist (relative to the package root).</summary>
    public static readonly IReadOnlyList<string> RequiredFiles = new[]
    {
        "README.md", "CHANGELOG.md", "LICENSE.md", "Third Party Notices.md", "Documentation~/index.md",
    };

    /// <summary>The Keep a Changelog subsection names.</summary>
    public static readonly IReadOnlyList<string> ChangelogSubsections = new[]
    {
        "Added", "Changed", "Deprecated", "Removed", "Fixed", "Security",
    };

    private static readonly string[] CodeRoots = { "Runtime", "Editor", "Tests" };
    private static readonly Regex GuidPattern = new("^[0-9a-f]{32}$", RegexOptions.CultureInvariant);
    private static readonly Regex SemVer = new(
        @"^(0|[1-9]\d*)\.(0|[1-9]\d*)\.(0|[1-9]\d*)(?:-((?:0|[1-9]\d*|\d*[a-zA-Z-][0-9a-zA-Z-]*)(?:\.(?:0|[1-9]\d*|\d*[a-zA-Z-][0-9a-zA-Z-]*))*))?(?:\+([0-9a-zA-Z-]+(?:\.[0-9a-zA-Z-]+)*))?$",
        RegexOptions.CultureInvariant);

    private List<string> _files;

    /// <summary>Lints the package whose root folder (the one holding package.json) is <paramref name="root"/>.</summary>
    public PackageLinter(string root)
    {
        Root = Path.GetFullPath(root);
    }

    /// <summary>The package root folder.</summary>
    public string Root { get; }

    /// <summary>How <see cref="Files"/> was listed: "git" or "walk".</summary>
    public string ListingSource { get; private set; }

    /// <summary>
    /// Every file that would ship, relative to <see cref="Root"/> with '/' separators: when the root is in a
    /// git checkout, tracked files plus untracked files that are not ignored (a fresh clone is what a git
    /// install sees); otherwise every file on disk, skipping dot entries and what .gitignore leaves out of a clone
    /// (bin/ and obj/ inside `~` folders, Tools~/out). Deleted-but-staged files are dropped.
    /// </summary>
    public IReadOnlyList<string> Files => _files ??= ListFiles();

    /// <summary>Walks up from each start folder to the folder whose package.json names <see cref="PackageName"/>.</summary>
    public static string FindPackageRoot(params string[] starts)
    {
        foreach (string start in starts)
        {
            for (string dir = start; !string.IsNullOrEmpty(dir); dir = Path.GetDirectoryName(dir))
            {
                string manifest = Path.Combine(dir, "package.json");
                if (!File.Exists(manifest)) continue;
                try
                {
                    using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(manifest));
                    if (doc.RootElement.ValueKind == JsonValueKind.Object &&
                        doc.RootElement.TryGetProperty("name", out JsonElement name) &&
                        name.ValueKind == JsonValueKind.String && name.GetString() == PackageName)
                        return dir;
                }
                catch (JsonException)
                {
                    // Not our manifest (or a broken one further up): keep walking.
                }
            }
        }
        return null;
    }

    /// <summary>Formats problems for an assertion message: one per line.</summary>
    public static string Describe(IReadOnlyCollection<string> problems) =>
        problems.Count + " problem(s):" + Environment.NewLine +
        string.Join(Environment.NewLine, problems.Select(p => "  - " + p));

    // ---------------------------------------------------------------------------------------------
    // .meta files

    /// <summary>
    /// Every imported file and folder has a .meta; no .meta lacks its asset; every GUID is 32 lowercase
    /// hex digits and unique; the importer matches the asset kind. A folder exists for this check only if
    /// it holds a listed file (git does not carry empty folders, so their .meta would be orphaned).
    /// </summary>
    public List<string> CheckMetas()
    {
        var problems = new List<string>();
        var files = new HashSet<string>(Files, StringComparer.Ordinal);
        var folders = new HashSet<string>(StringComparer.Ordinal);
        foreach (string f in Files)
            for (string d = ParentOf(f); d.Length > 0; d = ParentOf(d))
                folders.Add(d);

        // A file or folder at the root that is no package entry, `~` folder or dot entry is imported by Unity all the same
        // (two scratch JSON files once landed there, unseen: this check skipped everything outside the package entries).
        var strays = new SortedSet<string>(StringComparer.Ordinal);
        foreach (string f in Files)
        {
            string top = f.Split('/')[0];
            string entry = top.EndsWith(".meta", StringComparison.Ordinal) ? top.Substring(0, top.Length - ".meta".Length) : top;
            if (top.StartsWith(".", StringComparison.Ordinal) || top.EndsWith("~", StringComparison.Ordinal) || RootAssets.Contains(entry)) continue;
            strays.Add(top);
        }
        foreach (string stray in strays)
            problems.Add($"{stray}: at the package root but no package entry: Unity imports it; move it under a ~ folder or delete it");

        var assets = files.Where(f => !f.EndsWith(".meta", StringComparison.Ordinal))
            .Concat(folders).Where(IsImported).OrderBy(p => p, StringComparer.Ordinal);
        foreach (string asset in assets)
            if (!files.Contains(asset + ".meta"))
                problems.Add($"{asset}: no .meta (run python3 \"Tools~/make-metas.py\" and commit the result)");

        var guids = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string meta in files.Where(f => f.EndsWith(".meta", StringComparison.Ordinal)).OrderBy(p => p, StringComparer.Ordinal))
        {
            string asset = meta.Substring(0, meta.Length - ".meta".Length);
            if (!IsImported(asset)) continue;
            bool isFolder = folders.Contains(asset);
            if (!isFolder && !files.Contains(asset))
            {
                problems.Add($"{meta}: orphan .meta, its asset {asset} is gone");
                continue;
            }

            string[] lines = File.ReadAllLines(Path.Combine(Root, meta));
            if (!lines.Any(l => l.TrimEnd() == "fileFormatVersion: 2"))
                problems.Add($"{meta}: missing 'fileFormatVersion: 2'");
            string guidLine = lines.FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal));
            string guid = guidLine?.Substring(5).Trim();
            if (guid == null)
                problems.Add($"{meta}: no guid line");
            else if (!GuidPattern.IsMatch(guid))
                problems.Add($"{meta}: guid '{guid}' is not 32 lowercase hex digits");
            else if (guids.TryGetValue(guid, out string first))
                problems.Add($"{meta}: guid {guid} is also used by {first}");
            else
                guids.Add(guid, meta);

            string importer = lines.Select(l => Regex.Match(l, @"^(\w+Importer):\s*$"))
                .Where(m => m.Success).Select(m => m.Groups[1].Value).FirstOrDefault();
            bool folderAsset = lines.Any(l => l.TrimEnd() == "folderAsset: yes");
            string expected = ExpectedImporters(asset, isFolder);
            if (isFolder && !folderAsset)
                problems.Add($"{meta}: {asset} is a folder but the .meta lacks 'folderAsset: yes'");
            else if (!isFolder && folderAsset)
                problems.Add($"{meta}: {asset} is a file but the .meta says 'folderAsset: yes'");
            if (importer == null)
                problems.Add($"{meta}: no importer section");
            else if (expected != null && !expected.Split('|').Contains(importer))
                problems.Add($"{meta}: importer {importer}, expected {expected.Replace("|", " or ")} for {asset}");
        }
        return problems;
    }

    /// <summary>The importer(s) Unity uses for an asset kind, '|'-separated; null when any is fine.</summary>
    private static string ExpectedImporters(string asset, bool isFolder)
    {
        if (isFolder) return "DefaultImporter";
        string name = FileName(asset);
        if (name == "package.json") return "PackageManifestImporter";
        switch (Path.GetExtension(name).ToLowerInvariant())
        {
            case ".cs": return "MonoImporter";
            case ".asmdef": return "AssemblyDefinitionImporter";
            case ".asmref": return "AssemblyDefinitionReferenceImporter";
            case ".md":
            case ".json":
            case ".txt": return "TextScriptImporter|DefaultImporter";
            case ".prefab": return "PrefabImporter";
            default: return null;
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Build artefacts

    /// <summary>No .csproj, .sln, .slnx, bin/ or obj/ outside `~` folders (Unity would import them).</summary>
    public List<string> CheckNoBuildArtifacts()
    {
        var problems = new SortedSet<string>(StringComparer.Ordinal);
        foreach (string f in Files)
        {
            if (InTildeFolder(f)) continue;
            string[] parts = f.Split('/');
            for (int i = 0; i < parts.Length - 1; i++)
                if (parts[i] is "bin" or "obj")
                {
                    problems.Add($"{string.Join("/", parts.Take(i + 1))}/: build output outside a `~` folder");
                    break;
                }
            string ext = Path.GetExtension(f).ToLowerInvariant();
            if (ext is ".csproj" or ".sln" or ".slnx")
                problems.Add($"{f}: {ext} outside a `~` folder (Unity generates its own; keep ours in Tools~)");
        }
        return problems.ToList();
    }

    // ---------------------------------------------------------------------------------------------
    // Assembly definitions

    /// <summary>
    /// Every asmdef parses; its name is its file name and unique; references resolve (by name or
    /// "GUID:") to package asmdefs or <see cref="AllowedExternalAssemblies"/>; AvatarGo.Core is
    /// engine-free and references nothing; asmdefs under Editor/ are Editor-only; asmdefs under Tests/
    /// are test assemblies (UNITY_INCLUDE_TESTS, nunit.framework.dll with overrideReferences).
    /// </summary>
    public List<string> CheckAsmdefs()
    {
        var problems = new List<string>();
        var parsed = new List<(string Path, string Name, JsonElement Json)>();
        var docs = new List<JsonDocument>();
        try
        {
            foreach (string path in Asmdefs())
            {
                JsonDocument doc;
                try
                {
                    doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(Root, path)));
                }
                catch (JsonException e)
                {
                    problems.Add($"{path}: not valid JSON ({e.Message})");
                    continue;
                }
                docs.Add(doc);
                if (doc.RootElement.ValueKind != JsonValueKind.Object)
                {
                    problems.Add($"{path}: not a JSON object");
                    continue;
                }
                string name = GetString(doc.RootElement, "name");
                string expected = Path.GetFileNameWithoutExtension(FileName(path));
                if (name != expected)
                    problems.Add($"{path}: name '{name}' differs from the file name '{expected}'");
                parsed.Add((path, name, doc.RootElement));
            }

            foreach (var group in parsed.Where(a => a.Name != null).GroupBy(a => a.Name, StringComparer.Ordinal).Where(g => g.Count() > 1))
                problems.Add($"asmdef name '{group.Key}' is used by {string.Join(", ", group.Select(a => a.Path))}");

            var names = new HashSet<string>(parsed.Where(a => a.Name != null).Select(a => a.Name), StringComparer.Ordinal);
            var guidToName = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (var a in parsed)
            {
                string guid = ReadGuid(a.Path + ".meta");
                if (guid != null) guidToName[guid] = a.Name;
            }

            foreach (var (path, name, json) in parsed)
            {
                List<string> references = GetStrings(json, "references", path, problems);
                foreach (string reference in references)
                {
                    string target = reference;
                    if (reference.StartsWith("GUID:", StringComparison.Ordinal) &&
                        !guidToName.TryGetValue(reference.Substring(5), out target))
                    {
                        problems.Add($"{path}: reference {reference} is no asmdef in this package");
                        continue;
                    }
                    if (!names.Contains(target) && !AllowedExternalAssemblies.Contains(target))
                        problems.Add($"{path}: reference '{target}' is neither an asmdef in this package nor in the allow-list " +
                                     $"({string.Join(", ", AllowedExternalAssemblies)})");
                }

                List<string> precompiled = GetStrings(json, "precompiledReferences", path, problems);
                List<string> include = GetStrings(json, "includePlatforms", path, problems);
                List<string> constraints = GetStrings(json, "defineConstraints", path, problems);

                if (name == "AvatarGo.Core")
                {
                    if (!(json.TryGetProperty("noEngineReferences", out JsonElement ner) && ner.ValueKind == JsonValueKind.True))
                        problems.Add($"{path}: AvatarGo.Core must have \"noEngineReferences\": true");
                    if (references.Count > 0 || precompiled.Count > 0)
                        problems.Add($"{path}: AvatarGo.Core must reference nothing, found {string.Join(", ", references.Concat(precompiled))}");
                }

                string top = path.Split('/')[0];
                if (top == "Editor" && !(include.Count == 1 && include[0] == "Editor"))
                    problems.Add($"{path}: an Editor asmdef must have \"includePlatforms\": [\"Editor\"], found [{string.Join(", ", include)}]");

                if (top == "Tests")
                {
                    if (!constraints.Contains("UNITY_INCLUDE_TESTS"))
                        problems.Add($"{path}: a test asmdef needs UNITY_INCLUDE_TESTS in defineConstraints");
                    if (!precompiled.Contains("nunit.framework.dll"))
                        problems.Add($"{path}: a test asmdef needs nunit.framework.dll in precompiledReferences");
                    else if (!(json.TryGetProperty("overrideReferences", out JsonElement ovr) && ovr.ValueKind == JsonValueKind.True))
                        problems.Add($"{path}: precompiledReferences only apply with \"overrideReferences\": true");
                }
            }
        }
        finally
        {
            foreach (JsonDocument d in docs) d.Dispose();
        }
        return problems;
    }

    /// <summary>
    /// Every folder under Runtime/, Editor/ or Tests/ that holds .cs files is covered by an asmdef in it
    /// or in a folder above it (still under the same top folder); otherwise Unity compiles those files
    /// into Assembly-CSharp of whichever project installs the package.
    /// </summary>
    public List<string> CheckAsmdefCoverage()
    {
        var asmdefFolders = new HashSet<string>(Asmdefs().Select(ParentOf), StringComparer.Ordinal);
        var problems = new List<string>();
        foreach (string folder in Files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal) && IsImported(f))
                     .Select(ParentOf).Distinct().OrderBy(p => p, StringComparer.Ordinal))
        {
            bool covered = false;
            for (string d = folder; d.Length > 0; d = ParentOf(d))
                if (asmdefFolders.Contains(d)) { covered = true; break; }
            if (!covered)
                problems.Add($"{(folder.Length == 0 ? "." : folder)}/: holds .cs files but no asmdef covers it");
        }
        return problems;
    }

    // ---------------------------------------------------------------------------------------------
    // package.json

    /// <summary>package.json has the fields Unity's Package Manager and our users rely on.</summary>
    public List<string> CheckPackageJson()
    {
        var problems = new List<string>();
        string path = Path.Combine(Root, "package.json");
        if (!File.Exists(path)) return new List<string> { "package.json: missing" };
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(File.ReadAllText(path));
        }
        catch (JsonException e)
        {
            return new List<string> { $"package.json: not valid JSON ({e.Message})" };
        }
        using (doc)
        {
            JsonElement r = doc.RootElement;
            if (r.ValueKind != JsonValueKind.Object) return new List<string> { "package.json: not a JSON object" };
            void Expect(string key, string value)
            {
                string actual = GetString(r, key);
                if (actual != value) problems.Add($"package.json: \"{key}\" is {Quote(actual)}, expected \"{value}\"");
            }
            Expect("name", PackageName);
            Expect("displayName", "AvatarGo Self-Avatar");
            Expect("unity", "2021.3");
            string version = GetString(r, "version");
            if (version == null || !SemVer.IsMatch(version))
                problems.Add($"package.json: \"version\" {Quote(version)} is not SemVer (x.y.z)");
            if (string.IsNullOrWhiteSpace(GetString(r, "description")))
                problems.Add("package.json: \"description\" is missing or empty");
            if (string.IsNullOrWhiteSpace(GetString(r, "license")))
                problems.Add("package.json: \"license\" is missing or empty");
            bool hasAuthor = r.TryGetProperty("author", out JsonElement author) &&
                             (author.ValueKind == JsonValueKind.String ? !string.IsNullOrWhiteSpace(author.GetString())
                                 : author.ValueKind == JsonValueKind.Object && !string.IsNullOrWhiteSpace(GetString(author, "name")));
            if (!hasAuthor)
                problems.Add("package.json: \"author\" (a name) is missing");

            if (r.TryGetProperty("samples", out JsonElement samples))
            {
                if (samples.ValueKind != JsonValueKind.Array)
                    problems.Add("package.json: \"samples\" is not an array");
                else
                    foreach (JsonElement s in samples.EnumerateArray())
                    {
                        string sp = s.ValueKind == JsonValueKind.Object ? GetString(s, "path") : null;
                        if (sp == null)
                        {
                            problems.Add("package.json: a sample has no \"path\"");
                            continue;
                        }
                        string[] parts = sp.Split('/');
                        if (parts.Length < 2 || parts[0] != "Samples~" || parts.Contains("..") || parts.Contains(""))
                            problems.Add($"package.json: sample path \"{sp}\" is not a folder under Samples~/");
                        else if (!Directory.Exists(Path.Combine(Root, sp)))
                            problems.Add($"package.json: sample path \"{sp}\" does not exist");
                    }
            }
        }
        return problems;
    }

    // ---------------------------------------------------------------------------------------------
    // CHANGELOG.md

    /// <summary>
    /// CHANGELOG.md follows Keep a Changelog 1.1: "# Changelog" title, "## [Unreleased]" first, then
    /// "## [x.y.z] - YYYY-MM-DD" sections newest first, and only the six standard "###" subsections.
    /// Headings inside ``` code fences are ignored.
    /// </summary>
    public List<string> CheckChangelog()
    {
        string path = Path.Combine(Root, "CHANGELOG.md");
        if (!File.Exists(path)) return new List<string> { "CHANGELOG.md: missing" };
        return CheckChangelogText(File.ReadAllLines(path));
    }

    /// <summary>The CHANGELOG rules on given lines (see <see cref="CheckChangelog"/>).</summary>
    public static List<string> CheckChangelogText(IReadOnlyList<string> lines)
    {
        var problems = new List<string>();
        var versionHeading = new Regex(@"^## \[(?<v>[^\]]+)\] - (?<d>\d{4}-\d{2}-\d{2})$", RegexOptions.CultureInvariant);
        bool inFence = false, sawTitle = false;
        int sections = 0;
        Version previous = null;
        string previousText = null;
        for (int i = 0; i < lines.Count; i++)
        {
            string line = lines[i].TrimEnd();
            string at = $"CHANGELOG.md:{i + 1}";
            if (line.StartsWith("```", StringComparison.Ordinal)) { inFence = !inFence; continue; }
            if (inFence || !line.StartsWith("#", StringComparison.Ordinal)) continue;

            if (line.StartsWith("# ", StringComparison.Ordinal))
            {
                if (sawTitle || sections > 0) problems.Add($"{at}: a second top-level heading '{line}'");
                else if (line != "# Changelog") problems.Add($"{at}: title is '{line}', expected '# Changelog'");
                sawTitle = true;
            }
            else if (line.StartsWith("## ", StringComparison.Ordinal))
            {
                if (!sawTitle) problems.Add($"{at}: section before the '# Changelog' title");
                sections++;
                if (line == "## [Unreleased]")
                {
                    if (sections != 1) problems.Add($"{at}: '## [Unreleased]' must be the first section");
                    continue;
                }
                if (sections == 1) problems.Add($"{at}: the first section must be '## [Unreleased]', found '{line}'");
                Match m = versionHeading.Match(line);
                if (!m.Success)
                {
                    problems.Add($"{at}: '{line}' is not '## [x.y.z] - YYYY-MM-DD'");
                    continue;
                }
                string v = m.Groups["v"].Value;
                if (!SemVer.IsMatch(v)) problems.Add($"{at}: version '{v}' is not SemVer");
                if (!DateTime.TryParseExact(m.Groups["d"].Value, "yyyy-MM-dd", CultureInfo.InvariantCulture, DateTimeStyles.None, out _))
                    problems.Add($"{at}: '{m.Groups["d"].Value}' is not a real date");
                if (Version.TryParse(v.Split('-', '+')[0], out Version parsed))
                {
                    if (previous != null && parsed >= previous)
                        problems.Add($"{at}: version {v} is not older than {previousText} above it (newest first)");
                    previous = parsed;
                    previousText = v;
                }
            }
            else if (line.StartsWith("### ", StringComparison.Ordinal))
            {
                string sub = line.Substring(4).Trim();
                if (sections == 0) problems.Add($"{at}: subsection '{sub}' outside any version section");
                if (!ChangelogSubsections.Contains(sub))
                    problems.Add($"{at}: subsection '{sub}' is not one of {string.Join("/", ChangelogSubsections)}");
            }
            else
            {
                problems.Add($"{at}: heading '{line}' is deeper than Keep a Changelog uses");
            }
        }
        if (!sawTitle) problems.Add("CHANGELOG.md: no '# Changelog' title");
        if (sections == 0) problems.Add("CHANGELOG.md: no '## [Unreleased]' section");
        return problems;
    }

    // ---------------------------------------------------------------------------------------------
    // C# sources

    /// <summary>No .cs under Runtime/Core or Runtime/Simulation (the engine-free assemblies) has a `using UnityEngine`/`using UnityEditor` directive.</summary>
    public List<string> CheckCoreIsEngineFree()
    {
        var usingEngine = new Regex(@"^\s*(?:global\s+)?using\s+(?:static\s+)?(?:\w+\s*=\s*)?(?<ns>UnityEngine|UnityEditor)\b",
            RegexOptions.Multiline | RegexOptions.CultureInvariant);
        var problems = new List<string>();
        foreach (string f in Files.Where(f => (f.StartsWith("Runtime/Core/", StringComparison.Ordinal) || f.StartsWith("Runtime/Simulation/", StringComparison.Ordinal)) && f.EndsWith(".cs", StringComparison.Ordinal)))
        {
            string text = StripCommentsAndStrings(File.ReadAllText(Path.Combine(Root, f)));
            foreach (Match m in usingEngine.Matches(text))
                problems.Add($"{f}: 'using {m.Groups["ns"].Value}' in engine-free core code");
        }
        return problems;
    }

    /// <summary>
    /// Every .cs under Runtime/, Editor/ and Tests/ declares at most one public top-level type (nested
    /// types don't count), and a file declaring one is named after it (a part of a partial type may be
    /// named Type.Part.cs).
    /// </summary>
    public List<string> CheckOnePublicTypePerFile()
    {
        var problems = new List<string>();
        foreach (string f in Files.Where(f => f.EndsWith(".cs", StringComparison.Ordinal) && IsImported(f)))
        {
            string source = File.ReadAllText(Path.Combine(Root, f));
            List<string> types = PublicTopLevelTypes(source);
            string stem = Path.GetFileNameWithoutExtension(FileName(f));
            if (types.Count > 1)
                problems.Add($"{f}: {types.Count} public top-level types ({string.Join(", ", types)}); one per file");
            else if (types.Count == 1 && types[0] != stem &&
                     !(stem.StartsWith(types[0] + ".", StringComparison.Ordinal) && IsPartial(source, types[0])))
                problems.Add($"{f}: declares public type {types[0]}, so the file should be {types[0]}.cs");
        }
        return problems;
    }

    /// <summary>True when <paramref name="type"/> is declared partial: then Type.Part.cs is an accepted file name.</summary>
    private static bool IsPartial(string source, string type) =>
        Regex.IsMatch(StripCommentsAndStrings(source), @"\bpartial\s+(?:class|struct|interface|record(?:\s+class|\s+struct)?)\s+" + Regex.Escape(type) + @"\b");

    /// <summary>
    /// The public types declared outside any type in C# source, found by a regex scan after removing
    /// comments, strings and char literals, counting braces and telling namespace braces apart.
    /// Limits, acceptable for a lint: both branches of #if/#else are scanned as if both compiled; strings
    /// inside interpolation holes of interpolated strings ($"{f("x")}") can confuse the string stripper;
    /// a type whose accessibility comes only from another partial declaration is not seen as public.
    /// </summary>
    public static List<string> PublicTopLevelTypes(string source)
    {
        string code = StripCommentsAndStrings(source);
        const string mods = @"(?<mods>(?:(?:public|internal|private|protected|static|sealed|abstract|partial|readonly|ref|unsafe|new|file)\s+)*)";
        var token = new Regex(
            @"(?<ns>\bnamespace\s+[\w.]+\s*\{)" +
            @"|(?<open>\{)|(?<close>\})" +
            @"|(?<type>\b" + mods + @"(?:class|struct|interface|enum|record(?:\s+class|\s+struct)?)\s+(?<name>[A-Za-z_]\w*))" +
            @"|(?<del>\b" + mods.Replace("<mods>", "<dmods>") + @"delegate\s+[\w<>\[\],.?\s]+?\s(?<dname>[A-Za-z_]\w*)\s*(?:<[^>]*>\s*)?\()",
            RegexOptions.CultureInvariant);
        var stack = new Stack<bool>(); // true: a namespace brace
        int nonNamespaceDepth = 0;
        var found = new List<string>();
        foreach (Match m in token.Matches(code))
        {
            if (m.Groups["ns"].Success) stack.Push(true);
            else if (m.Groups["open"].Success) { stack.Push(false); nonNamespaceDepth++; }
            else if (m.Groups["close"].Success)
            {
                if (stack.Count > 0 && !stack.Pop()) nonNamespaceDepth--;
            }
            else if (nonNamespaceDepth == 0)
            {
                bool isType = m.Groups["type"].Success;
                string modifiers = isType ? m.Groups["mods"].Value : m.Groups["dmods"].Value;
                if (Regex.IsMatch(modifiers, @"\bpublic\b"))
                    found.Add(isType ? m.Groups["name"].Value : m.Groups["dname"].Value);
            }
        }
        return found;
    }

    /// <summary>Replaces comments, string and char literals by spaces (keeping line breaks).</summary>
    public static string StripCommentsAndStrings(string s)
    {
        var sb = new StringBuilder(s.Length);
        int i = 0;
        while (i < s.Length)
        {
            char c = s[i];
            char n = i + 1 < s.Length ? s[i + 1] : '\0';
            if (c == '/' && n == '/')
            {
                while (i < s.Length && s[i] != '\n') { sb.Append(' '); i++; }
            }
            else if (c == '/' && n == '*')
            {
                int end = s.IndexOf("*/", i + 2, StringComparison.Ordinal);
                end = end < 0 ? s.Length : end + 2;
                Blank(sb, s, i, end);
                i = end;
            }
            else if (c == '"' && string.CompareOrdinal(s, i, "\"\"\"", 0, 3) == 0)
            {
                int end = s.IndexOf("\"\"\"", i + 3, StringComparison.Ordinal);
                end = end < 0 ? s.Length : end + 3;
                Blank(sb, s, i, end);
                i = end;
            }
            else if (c == '"' || c == '\'')
            {
                bool verbatim = false;
                for (int k = i - 1; k >= 0 && (s[k] == '@' || s[k] == '$'); k--) verbatim |= s[k] == '@';
                int j = i + 1;
                while (j < s.Length)
                {
                    if (!verbatim && s[j] == '\\') { j += 2; continue; }
                    if (s[j] == c)
                    {
                        if (verbatim && j + 1 < s.Length && s[j + 1] == c) { j += 2; continue; }
                        j++;
                        break;
                    }
                    if (!verbatim && s[j] == '\n') break; // unterminated: stop at the line end
                    j++;
                }
                j = Math.Min(j, s.Length);
                Blank(sb, s, i, j);
                i = j;
            }
            else
            {
                sb.Append(c);
                i++;
            }
        }
        return sb.ToString();
    }

    // ---------------------------------------------------------------------------------------------
    // Assembly boundaries

    /// <summary>The engine-free assembly of simulation, evaluation and test rigs, which players never ship.</summary>
    public const string SimulationAssembly = "AvatarGo.Simulation";

    /// <summary>
    /// The simulation/evaluation assembly stays out of what ships: it is engine-free, not auto-referenced, compiled
    /// only in the Editor or in builds that include tests (a define constraint naming UNITY_EDITOR and
    /// UNITY_INCLUDE_TESTS), and no other assembly under Runtime/ references it, by name or by GUID.
    /// </summary>
    public List<string> CheckAssemblyBoundaries()
    {
        var problems = new List<string>();
        var asmdefs = new List<(string Path, string Name, List<string> References)>();
        string simulationGuid = null, simulationPath = null;
        foreach (string path in Asmdefs())
        {
            using JsonDocument doc = TryParse(path);
            if (doc == null || doc.RootElement.ValueKind != JsonValueKind.Object) continue; // CheckAsmdefs reports it
            JsonElement json = doc.RootElement;
            string name = GetString(json, "name");
            asmdefs.Add((path, name, GetStrings(json, "references", path, problems)));
            if (name != SimulationAssembly) continue;
            simulationPath = path;
            simulationGuid = ReadGuid(path + ".meta");
            if (!(json.TryGetProperty("noEngineReferences", out JsonElement ner) && ner.ValueKind == JsonValueKind.True))
                problems.Add($"{path}: {SimulationAssembly} must have \"noEngineReferences\": true");
            if (!(json.TryGetProperty("autoReferenced", out JsonElement auto) && auto.ValueKind == JsonValueKind.False))
                problems.Add($"{path}: {SimulationAssembly} must have \"autoReferenced\": false (user code references it on purpose)");
            List<string> constraints = GetStrings(json, "defineConstraints", path, problems);
            if (!constraints.Any(c => c.Contains("UNITY_EDITOR", StringComparison.Ordinal) && c.Contains("UNITY_INCLUDE_TESTS", StringComparison.Ordinal)))
                problems.Add($"{path}: {SimulationAssembly} needs the define constraint \"UNITY_EDITOR || UNITY_INCLUDE_TESTS\" so players never ship it");
        }
        foreach (var (path, name, references) in asmdefs)
        {
            if (!path.StartsWith("Runtime/", StringComparison.Ordinal) || path == simulationPath) continue;
            foreach (string reference in references)
                if (reference == SimulationAssembly || (simulationGuid != null && reference == "GUID:" + simulationGuid))
                    problems.Add($"{path}: runtime assembly {name} references {SimulationAssembly} (simulation and evaluation do not ship)");
        }
        return problems;
    }

    /// <summary>
    /// Unity builds from asmdefs and sources, never from Tools~'s projects: an <c>InternalsVisibleTo</c> in a Tools~
    /// project that compiles package sources would let tests pass here that Unity cannot compile. The core grants its
    /// test assembly access in a source file under Runtime/Core instead.
    /// </summary>
    public List<string> CheckInternalsVisibleToInSource()
    {
        var problems = new List<string>();
        string tools = Path.Combine(Root, "Tools~");
        if (Directory.Exists(tools))
            foreach (string project in Directory.GetFiles(tools, "*.csproj", SearchOption.AllDirectories))
            {
                string text = File.ReadAllText(project);
                bool compilesPackage = Regex.IsMatch(text, @"<Compile\s+Include=""\$\(PackageRoot\)/(Runtime|Editor|Tests)/", RegexOptions.CultureInvariant);
                if (compilesPackage && text.Contains("<InternalsVisibleTo", StringComparison.Ordinal))
                    problems.Add($"{Path.GetRelativePath(Root, project).Replace('\\', '/')}: declares InternalsVisibleTo in MSBuild; Unity never sees it, declare it in a source file");
            }
        var grant = new Regex(@"\[\s*assembly\s*:\s*(?:System\.Runtime\.CompilerServices\.)?InternalsVisibleTo\s*\(\s*""AvatarGo\.Core\.Tests""", RegexOptions.CultureInvariant);
        bool hasTests = Files.Contains("Tests/Core/AvatarGo.Core.Tests.asmdef");
        bool granted = Files.Any(f => f.StartsWith("Runtime/Core/", StringComparison.Ordinal) && f.EndsWith(".cs", StringComparison.Ordinal)
                                      && grant.IsMatch(File.ReadAllText(Path.Combine(Root, f))));
        if (hasTests && !granted)
            problems.Add("Runtime/Core: no source file declares [assembly: InternalsVisibleTo(\"AvatarGo.Core.Tests\")]");
        return problems;
    }

    private JsonDocument TryParse(string relative)
    {
        try
        {
            return JsonDocument.Parse(File.ReadAllText(Path.Combine(Root, relative)));
        }
        catch (JsonException)
        {
            return null;
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Package Validation Suite file rules

    /// <summary>
    /// The extensions PVS checks as text (FileExt.TextFile in needle-mirror/com.unity.package-validation-suite
    /// Lib/PvpXray/Verifier.cs). .meta files (Unity writes "userData: " with a trailing space), .bvh/.agsession data
    /// (byte-exact on purpose, see .gitattributes) and Unity YAML assets are not in it.
    /// </summary>
    public static readonly IReadOnlySet<string> PvsTextExtensions = new HashSet<string>(StringComparer.OrdinalIgnoreCase)
    {
        ".asmdef", ".asmref", ".cginc", ".compute", ".cpp", ".cs", ".h", ".hlsl", ".java", ".js", ".json", ".m", ".md", ".mm",
        ".plist", ".py", ".shader", ".txt", ".uss", ".uxml", ".yaml", ".yml",
    };

    /// <summary>
    /// PVP-120..125 (WellFormedTextFilesVerifier): every text file of the package, `~` folders included (a git install
    /// and the registry tarball ship them too), is well-formed UTF-8 with no carriage return (CRLF), no tab, no
    /// trailing space or tab and no byte-order mark anywhere.
    /// </summary>
    public List<string> CheckTextFiles()
    {
        var problems = new List<string>();
        var strict = new UTF8Encoding(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);
        foreach (string f in Files.Where(f => PvsTextExtensions.Contains(Path.GetExtension(f))))
        {
            byte[] bytes = File.ReadAllBytes(Path.Combine(Root, f));
            string text;
            try
            {
                text = strict.GetString(bytes);
            }
            catch (DecoderFallbackException)
            {
                problems.Add($"{f}: not well-formed UTF-8 (PVP-120)");
                continue;
            }
            if (text.Contains('\uFEFF')) problems.Add($"{f}: UTF-8 byte-order mark (PVP-125)");
            string[] lines = text.Split('\n');
            int cr = Array.FindIndex(lines, l => l.Contains('\r'));
            if (cr >= 0) problems.Add($"{f}:{cr + 1}: carriage return (CRLF line ending; PVP-121)");
            int tab = Array.FindIndex(lines, l => l.Contains('\t'));
            if (tab >= 0) problems.Add($"{f}:{tab + 1}: tab character (PVP-122)");
            int trailing = Array.FindIndex(lines, l => l.TrimEnd('\r').Length > 0 && l.TrimEnd('\r') is var t && (t[^1] == ' ' || t[^1] == '\t'));
            if (trailing >= 0) problems.Add($"{f}:{trailing + 1}: trailing whitespace (PVP-124)");
        }
        return problems;
    }

    /// <summary>PVS US-0113 / PVP-22-1: every path, relative to the package root, is at most 140 characters.</summary>
    public List<string> CheckPathLengths() =>
        Files.Where(f => f.Length > 140).Select(f => $"{f}: {f.Length} characters, PVS allows 140 (PVP-22-1)").ToList();

    private static readonly Regex CopyrightLine = new(@"^\s*(?:.+\s)?copyright\s+(?:\(c\)|©)\s+\d{4}(?:\s*[-–]\s*\d{4})?\s+\S.*$",
        RegexOptions.IgnoreCase | RegexOptions.CultureInvariant);

    /// <summary>
    /// PVS US-0032 / PVP-30/31: LICENSE.md exists and has a copyright line ("Copyright (c) 2026 Holder" or with ©).
    /// PVS's own form (first line "&lt;package name&gt; copyright © YEAR ...") is only a warning there and not required here.
    /// </summary>
    public List<string> CheckLicense()
    {
        string path = Path.Combine(Root, "LICENSE.md");
        if (!File.Exists(path)) return new List<string> { "LICENSE.md: missing (PVP-30-1)" };
        return File.ReadLines(path).Any(l => CopyrightLine.IsMatch(l))
            ? new List<string>()
            : new List<string> { "LICENSE.md: no copyright line such as 'Copyright (c) 2026 AvatarGo contributors' (PVP-31-1)" };
    }

    /// <summary>PVS US-0040 / PVP-60..62: a Documentation~ folder whose .md files each hold at least 10 characters, with a lowercase index.md.</summary>
    public List<string> CheckDocumentation()
    {
        var problems = new List<string>();
        string dir = Path.Combine(Root, "Documentation~");
        string[] docs = Directory.Exists(dir) ? Directory.GetFiles(dir, "*.md", SearchOption.AllDirectories) : Array.Empty<string>();
        if (docs.Length == 0) return new List<string> { "Documentation~: no .md file (PVP-60-1)" };
        foreach (string d in docs.Where(d => File.ReadAllText(d).Trim().Length < 10))
            problems.Add($"{Path.GetRelativePath(Root, d).Replace('\\', '/')}: fewer than 10 characters (PVP-61-1)");
        if (!docs.Any(d => Path.GetFileName(d) == "index.md"))
            problems.Add("Documentation~/index.md: missing or not lowercase (PVP-62-1)");
        return problems;
    }

    // ---------------------------------------------------------------------------------------------
    // Required files

    /// <summary>The files every release needs exist.</summary>
    public List<string> CheckRequiredFiles() =>
        RequiredFiles.Where(f => !File.Exists(Path.Combine(Root, f))).Select(f => $"{f}: missing").ToList();

    /// <summary>Every check, concatenated.</summary>
    public List<string> CheckAll() =>
        CheckMetas().Concat(CheckNoBuildArtifacts()).Concat(CheckAsmdefs()).Concat(CheckAsmdefCoverage())
            .Concat(CheckPackageJson()).Concat(CheckChangelog()).Concat(CheckCoreIsEngineFree())
            .Concat(CheckOnePublicTypePerFile()).Concat(CheckRequiredFiles()).Concat(CheckAssemblyBoundaries())
            .Concat(CheckInternalsVisibleToInSource()).Concat(CheckTextFiles()).Concat(CheckPathLengths()).Concat(CheckLicense())
            .Concat(CheckDocumentation()).ToList();

    // ---------------------------------------------------------------------------------------------
    // Helpers

    /// <summary>
    /// True when Unity imports the path: no `~` or dot segment, under a <see cref="RootAssets"/> entry; or inside a
    /// sample (`Samples~/NAME/...`, by the same rules below NAME), which the Package Manager copies into the project's
    /// Assets with its .meta files when the user imports it. The sample's own folder is not imported (Unity names it).
    /// </summary>
    public static bool IsImported(string relative)
    {
        string[] parts = relative.Split('/');
        if (parts.Length > 2 && parts[0] == "Samples~")
            parts = parts.Skip(2).ToArray();
        else if (!RootAssets.Contains(parts[0]))
            return false;
        return !parts.Any(p => p.Length == 0 || p.StartsWith(".", StringComparison.Ordinal) || p.EndsWith("~", StringComparison.Ordinal));
    }

    private IEnumerable<string> Asmdefs() =>
        Files.Where(f => f.EndsWith(".asmdef", StringComparison.Ordinal) && IsImported(f) && (CodeRoots.Contains(f.Split('/')[0]) || f.StartsWith("Samples~/", StringComparison.Ordinal)));

    private static bool InTildeFolder(string relative)
    {
        string[] parts = relative.Split('/');
        for (int i = 0; i < parts.Length - 1; i++)
            if (parts[i].EndsWith("~", StringComparison.Ordinal)) return true;
        return false;
    }

    private string ReadGuid(string relativeMeta)
    {
        string path = Path.Combine(Root, relativeMeta);
        if (!File.Exists(path)) return null;
        string line = File.ReadLines(path).FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal));
        return line?.Substring(5).Trim();
    }

    private static string GetString(JsonElement obj, string key) =>
        obj.TryGetProperty(key, out JsonElement e) && e.ValueKind == JsonValueKind.String ? e.GetString() : null;

    private static List<string> GetStrings(JsonElement obj, string key, string path, List<string> problems)
    {
        var list = new List<string>();
        if (!obj.TryGetProperty(key, out JsonElement e)) return list;
        if (e.ValueKind != JsonValueKind.Array)
        {
            problems.Add($"{path}: \"{key}\" is not an array");
            return list;
        }
        foreach (JsonElement item in e.EnumerateArray())
        {
            if (item.ValueKind == JsonValueKind.String) list.Add(item.GetString());
            else problems.Add($"{path}: \"{key}\" holds a non-string {item.ValueKind}");
        }
        return list;
    }

    private static string Quote(string s) => s == null ? "missing" : $"\"{s}\"";

    private static string ParentOf(string relative)
    {
        int slash = relative.LastIndexOf('/');
        return slash < 0 ? "" : relative.Substring(0, slash);
    }

    private static string FileName(string relative) => relative.Substring(relative.LastIndexOf('/') + 1);

    private static void Blank(StringBuilder sb, string s, int from, int to)
    {
        for (int k = from; k < to; k++) sb.Append(s[k] == '\n' ? '\n' : ' ');
    }

    private List<string> ListFiles()
    {
        List<string> fromGit = GitFiles();
        if (fromGit != null)
        {
            ListingSource = "git";
            return fromGit.Where(f => File.Exists(Path.Combine(Root, f))).OrderBy(f => f, StringComparer.Ordinal).ToList();
        }
        ListingSource = "walk";
        var files = new List<string>();
        Walk(Root, "", files);
        files.Sort(StringComparer.Ordinal);
        return files;
    }

    private static void Walk(string dir, string prefix, List<string> files)
    {
        foreach (string f in Directory.GetFiles(dir))
        {
            string name = Path.GetFileName(f);
            if (!name.StartsWith(".", StringComparison.Ordinal)) files.Add(prefix + name);
        }
        foreach (string d in Directory.GetDirectories(dir))
        {
            string name = Path.GetFileName(d);
            // Inside `~` folders, the Tools~ builds' output is ignored by git (.gitignore); outside, CheckNoBuildArtifacts reports it.
            bool inTilde = prefix.Split('/').Any(p => p.EndsWith("~", StringComparison.Ordinal));
            if (name.StartsWith(".", StringComparison.Ordinal) || (inTilde && name is "bin" or "obj") || prefix + name == "Tools~/out") continue;
            Walk(d, prefix + name + "/", files);
        }
    }

    /// <summary>The git listing, or null when the root is not in a git work tree or git is unavailable.</summary>
    private List<string> GitFiles()
    {
        string inside = RunGit("rev-parse --is-inside-work-tree");
        if (inside == null || inside.Trim() != "true") return null;
        string listing = RunGit("ls-files -z --cached --others --exclude-standard");
        if (listing == null) return null;
        return listing.Split('\0', StringSplitOptions.RemoveEmptyEntries).Distinct(StringComparer.Ordinal).ToList();
    }

    private string RunGit(string arguments)
    {
        try
        {
            var psi = new ProcessStartInfo("git", arguments)
            {
                WorkingDirectory = Root,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
            };
            using Process p = Process.Start(psi);
            if (p == null) return null;
            System.Threading.Tasks.Task<string> err = p.StandardError.ReadToEndAsync();
            string output = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            _ = err.Result;
            return p.ExitCode == 0 ? output : null;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return null; // git is not installed
        }
    }
}
