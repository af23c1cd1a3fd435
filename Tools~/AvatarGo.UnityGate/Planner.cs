using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace AvatarGo.UnityGate;

/// <summary>
/// Works out, from a package's asmdefs, what Unity compiles in a configuration: which assemblies, from which
/// sources, with which symbols and references. The rules are Unity's, restated from UnityCsReference@2021.3
/// Editor/Mono/Scripting/ScriptCompilation (CustomScriptAssembly.IsCompatibleWith, EditorBuildRules.GetUnityReferences
/// and AddScriptAssemblyReferences, EditorCompilation.GetTargetAssemblyDefines). Where Unity silently drops something
/// that is probably a mistake (a reference to an assembly that exists in no configuration, an unknown precompiled
/// DLL, an invalid versionDefines expression), the planner throws <see cref="GateException"/> instead.
/// </summary>
public sealed class Planner
{
    private readonly string _packageRoot;
    private readonly string _surfaceRoot;
    private readonly string _nugetRoot;
    private readonly List<Asmdef> _asmdefs;

    /// <summary>Reads every asmdef of the package.</summary>
    /// <param name="packageRoot">The folder holding package.json.</param>
    /// <param name="nugetPackageRoot">The NuGet packages folder holding NUnit 3.6.0 (for nunit.framework.dll).</param>
    public Planner(string packageRoot, string nugetPackageRoot)
    {
        _packageRoot = Path.GetFullPath(packageRoot);
        _surfaceRoot = Path.Combine(_packageRoot, "Tools~", "UnitySurface");
        _nugetRoot = nugetPackageRoot;
        _asmdefs = PackageFiles.Imported(_packageRoot)
            .Where(f => f.EndsWith(".asmdef", StringComparison.Ordinal))
            .Select(f => Asmdef.Read(_packageRoot, f)).ToList();
        string asmref = PackageFiles.Imported(_packageRoot).FirstOrDefault(f => f.EndsWith(".asmref", StringComparison.Ordinal));
        if (asmref != null) throw new GateException($"{asmref}: .asmref files are not supported by the gate yet");
        foreach (var g in _asmdefs.GroupBy(a => a.Name, StringComparer.Ordinal).Where(g => g.Count() > 1))
            throw new GateException($"assembly name '{g.Key}' is defined by {string.Join(" and ", g.Select(a => a.Path))}");
        foreach (Asmdef a in _asmdefs.Where(a => UnityCatalog.Surface(a.Name) != null))
            throw new GateException($"{a.Path}: '{a.Name}' is the name of a Unity assembly");
    }

    /// <summary>The package's asmdefs.</summary>
    public IReadOnlyList<Asmdef> Asmdefs => _asmdefs;

    /// <summary>The package root.</summary>
    public string PackageRoot => _packageRoot;

    /// <summary>Plans one configuration.</summary>
    public ConfigurationPlan Plan(UnityConfiguration config)
    {
        var compiled = new Dictionary<string, AssemblyPlan>(StringComparer.Ordinal);
        var skipped = new List<SkippedAssembly>();
        var packagePlans = new List<(Asmdef Asmdef, List<string> Sources, SortedSet<string> Defines)>();

        // 1. Which package asmdefs Unity compiles here.
        foreach (Asmdef a in _asmdefs.OrderBy(a => a.Path, StringComparer.Ordinal))
        {
            List<string> sources = SourcesOf(a);
            SortedSet<string> defines = config.Defines(a.EditorOnly);
            defines.UnionWith(VersionDefines(a, config));
            string reason = WhySkipped(a, config, defines, sources);
            if (reason != null) skipped.Add(new SkippedAssembly(a.Name, a.Path, reason));
            else packagePlans.Add((a, sources, defines));
        }
        var present = new HashSet<string>(packagePlans.Select(p => p.Asmdef.Name), StringComparer.Ordinal);

        // 2. Their references, and the surface assemblies they pull in.
        var surfaceNeeded = new SortedSet<string>(StringComparer.Ordinal);
        var packageAssemblies = new List<AssemblyPlan>();
        foreach (var (a, sources, defines) in packagePlans)
        {
            var notes = new List<string>();
            var references = new List<string>();
            foreach (string raw in a.References)
            {
                string name = Resolve(a, raw);
                if (present.Contains(name))
                {
                    references.Add(name);
                    continue;
                }
                if (_asmdefs.Any(x => x.Name == name))
                {
                    notes.Add($"reference {name} dropped: not compiled in this configuration ({skipped.First(s => s.Name == name).Reason})");
                    continue;
                }
                SurfaceAssembly surface = UnityCatalog.Surface(name);
                string absent = surface == null ? null : SurfaceAbsence(surface, config);
                if (absent != null)
                {
                    notes.Add($"reference {name} dropped: {absent}");
                    continue;
                }
                references.Add(name);
                surfaceNeeded.Add(name);
            }
            if (!a.NoEngineReferences)
            {
                // GetUnityReferences: every engine assembly in the Editor; runtime ones only in a player or for runtime code.
                references.Insert(0, "UnityEngine");
                surfaceNeeded.Add("UnityEngine");
                if (config.Editor || a.EditorOnly)
                {
                    references.Insert(1, "UnityEditor");
                    surfaceNeeded.Add("UnityEditor");
                }
            }
            var precompiled = new List<string>();
            if (a.OverrideReferences)
                foreach (string dll in a.PrecompiledReferences)
                {
                    string path = PrecompiledPath(a, dll, config);
                    if (path != null) precompiled.Add(path);
                    else notes.Add($"precompiled {dll} dropped: {UnityCatalog.NUnitPackage} is not in the project");
                }
            packageAssemblies.Add(new AssemblyPlan
            {
                Name = a.Name,
                Kind = PlanKind.Package,
                Origin = a.Path,
                Sources = sources,
                Defines = defines.ToList(),
                References = references.Distinct(StringComparer.Ordinal).ToList(),
                PrecompiledReferences = precompiled,
                AllowUnsafeCode = a.AllowUnsafeCode,
                RequireDocs = !a.IsTestAssembly,
                EditorOnly = a.EditorOnly,
                Notes = notes,
            });
        }

        // 3. Surface assemblies (with their own references), then the package in dependency order.
        foreach (string name in surfaceNeeded.ToList())
            foreach (string r in UnityCatalog.Surface(name).References)
                if (SurfaceAbsence(UnityCatalog.Surface(r), config) == null) surfaceNeeded.Add(r);
        var ordered = new List<AssemblyPlan>();
        foreach (SurfaceAssembly s in UnityCatalog.SurfaceAssemblies.Where(s => surfaceNeeded.Contains(s.Name)))
            ordered.Add(SurfacePlan(s, config));
        foreach (AssemblyPlan p in packageAssemblies) compiled[p.Name] = p;
        var visiting = new HashSet<string>(StringComparer.Ordinal);
        var done = new HashSet<string>(ordered.Select(p => p.Name), StringComparer.Ordinal);
        void Visit(AssemblyPlan p)
        {
            if (done.Contains(p.Name)) return;
            if (!visiting.Add(p.Name)) throw new GateException($"{p.Origin}: assembly references form a cycle through {p.Name}");
            foreach (string r in p.References)
                if (compiled.TryGetValue(r, out AssemblyPlan dep)) Visit(dep);
            done.Add(p.Name);
            ordered.Add(p);
        }
        foreach (AssemblyPlan p in packageAssemblies) Visit(p);
        return new ConfigurationPlan(config, ordered, skipped);
    }

    /// <summary>
    /// The .cs files Unity puts in the asmdef's assembly: every script under its folder, minus folders that hold
    /// their own asmdef (and everything under them), minus what Unity never imports (`~` and dot folders).
    /// </summary>
    public List<string> SourcesOf(Asmdef a)
    {
        var nested = _asmdefs.Where(x => x != a).Select(x => x.Folder)
            .Where(f => IsUnder(f, a.Folder)).ToList();
        return PackageFiles.Imported(_packageRoot)
            .Where(f => f.EndsWith(".cs", StringComparison.Ordinal) && IsUnder(ParentOf(f), a.Folder))
            .Where(f => !nested.Any(n => IsUnder(ParentOf(f), n) && n.Length > a.Folder.Length))
            .OrderBy(f => f, StringComparer.Ordinal).ToList();
    }

    private static bool IsUnder(string folder, string root) =>
        root.Length == 0 || folder == root || folder.StartsWith(root + "/", StringComparison.Ordinal);

    private static string ParentOf(string path) => path.Contains('/') ? path.Substring(0, path.LastIndexOf('/')) : "";

    private string Resolve(Asmdef from, string reference)
    {
        if (reference.StartsWith("GUID:", StringComparison.Ordinal))
        {
            string guid = reference.Substring(5);
            Asmdef target = _asmdefs.FirstOrDefault(x => string.Equals(x.Guid, guid, StringComparison.OrdinalIgnoreCase));
            if (target == null)
                throw new GateException($"{from.Path}: reference {reference} is the GUID of no asmdef in the package " +
                                        "(Unity would drop it silently; a surface assembly is referenced by name)");
            return target.Name;
        }
        if (_asmdefs.Any(x => x.Name == reference) || UnityCatalog.Surface(reference) != null) return reference;
        throw new GateException($"{from.Path}: reference '{reference}' is no assembly: neither an asmdef of the package nor a Unity " +
                                $"assembly with a surface in Tools~/UnitySurface ({string.Join(", ", UnityCatalog.SurfaceAssemblies.Select(s => s.Name))})");
    }

    /// <summary>Why a surface assembly does not exist in the configuration, or null when it does.</summary>
    public static string SurfaceAbsence(SurfaceAssembly s, UnityConfiguration config)
    {
        if (s.Package != null && !config.HasPackage(s.Package)) return $"{s.Package} is not in the project";
        if (s.ImportedIntoAssets && !config.AssetsAssemblies.Contains(s.Name)) return $"the plug-in providing {s.Name} is not imported into Assets";
        if (s.EditorOnly && !config.Editor) return "an Editor-only assembly does not exist in a player build";
        return null;
    }

    private AssemblyPlan SurfacePlan(SurfaceAssembly s, UnityConfiguration config)
    {
        // A surface with no declaration yet has no folder (git keeps no empty folder): it compiles to an empty assembly.
        string folder = "Tools~/UnitySurface/" + s.Name;
        string dir = Path.Combine(_packageRoot, folder);
        var sources = (Directory.Exists(dir) ? Directory.GetFiles(dir, "*.cs", SearchOption.AllDirectories) : Array.Empty<string>())
            .Select(f => Path.GetRelativePath(_packageRoot, f).Replace('\\', '/'))
            .OrderBy(f => f, StringComparer.Ordinal).ToList();
        // The surface sees the editor version (UNITY_X_Y_OR_NEWER) and UNITY_EDITOR, to declare what differs between versions.
        var defines = SurfaceDefines(s, config);
        var references = s.References.Where(r => SurfaceAbsence(UnityCatalog.Surface(r), config) == null).ToList();
        var precompiled = new List<string>();
        if (s.UsesNUnit) precompiled.Add(NUnitPath(config));
        return new AssemblyPlan
        {
            Name = s.Name,
            Kind = PlanKind.Surface,
            Origin = folder,
            Sources = sources,
            Defines = defines.ToList(),
            References = references,
            PrecompiledReferences = precompiled,
            RequireDocs = false,
            EditorOnly = s.EditorOnly,
            Notes = new[] { "compile-only Unity API surface: " + s.Source },
        };
    }

    /// <summary>
    /// The symbols a surface assembly is compiled with: the editor's version symbols, UNITY_EDITOR in the Editor, and its
    /// own versionDefines (<see cref="SurfaceAssembly.VersionDefines"/>) evaluated against the configuration's packages.
    /// </summary>
    public static SortedSet<string> SurfaceDefines(SurfaceAssembly s, UnityConfiguration config)
    {
        var defines = new SortedSet<string>(UnityConfiguration.VersionSymbols(config.Unity), StringComparer.Ordinal);
        if (config.Editor) defines.Add("UNITY_EDITOR");
        defines.UnionWith(VersionDefines(s.VersionDefines, "Tools~/AvatarGo.UnityGate/UnityCatalog.cs (" + s.Name + ")", config));
        return defines;
    }

    private string PrecompiledPath(Asmdef a, string dll, UnityConfiguration config)
    {
        if (dll != UnityCatalog.NUnitDll)
            throw new GateException($"{a.Path}: precompiled reference '{dll}' is no DLL the gate knows ({UnityCatalog.NUnitDll} only)");
        return config.HasPackage(UnityCatalog.NUnitPackage) ? NUnitPath(config) : null;
    }

    private string NUnitPath(UnityConfiguration config)
    {
        string framework = UnityCatalog.NUnitFramework(config.PackageVersion(UnityCatalog.NUnitPackage) ?? "1.0.6");
        string path = Path.Combine(_nugetRoot, "nunit", UnityCatalog.NUnitNuGetVersion, "lib", framework, UnityCatalog.NUnitDll);
        if (!File.Exists(path))
            throw new GateException($"{path} is missing: restore Tools~/AvatarGo.UnityGate (it downloads NUnit {UnityCatalog.NUnitNuGetVersion})");
        return path;
    }

    /// <summary>
    /// The symbols an asmdef's versionDefines add in a configuration: an entry whose resource (package name, or
    /// "Unity") is absent adds nothing; an empty expression adds its symbol whenever the resource is present;
    /// otherwise the expression must match the resource's version.
    /// </summary>
    public static IEnumerable<string> VersionDefines(Asmdef a, UnityConfiguration config) => VersionDefines(a.VersionDefines, a.Path, config);

    /// <summary>The symbols a list of versionDefines adds in a configuration (see the overload for an asmdef); <paramref name="where"/> names them in errors.</summary>
    public static IEnumerable<string> VersionDefines(IEnumerable<VersionDefine> versionDefines, string where, UnityConfiguration config)
    {
        foreach (VersionDefine vd in versionDefines)
        {
            bool unity = vd.Resource == "Unity";
            if (!unity && !config.HasPackage(vd.Resource)) continue;
            if (string.IsNullOrEmpty(vd.Define)) continue;
            if (string.IsNullOrEmpty(vd.Expression))
            {
                yield return vd.Define;
                continue;
            }
            VersionRange range;
            try
            {
                range = VersionRange.Parse(vd.Expression, unity);
            }
            catch (FormatException e)
            {
                throw new GateException($"{where}: versionDefines entry for {vd.Resource} ({vd.Define}): {e.Message}");
            }
            bool match = unity ? range.Contains(config.Unity) : range.Contains(SemanticVersion.Parse(config.PackageVersion(vd.Resource)));
            if (match) yield return vd.Define;
        }
    }

    /// <summary>Why Unity does not compile the asmdef in the configuration (CustomScriptAssembly.IsCompatibleWith), or null.</summary>
    public static string WhySkipped(Asmdef a, UnityConfiguration config, IReadOnlySet<string> defines, IReadOnlyList<string> sources)
    {
        if (sources.Count == 0) return "no scripts (Unity builds no assembly for an asmdef without .cs files)";
        bool testFramework = a.DefineConstraints.Contains("UNITY_INCLUDE_TESTS") || a.DefineConstraints.Contains("UNITY_TESTS_FRAMEWORK");
        if (!config.Editor && testFramework && !config.IncludeTestAssemblies) return "a test assembly, and the player is built without test assemblies";
        foreach (string c in a.DefineConstraints)
        {
            bool holds;
            try
            {
                holds = DefineConstraints.Holds(c, defines);
            }
            catch (FormatException e)
            {
                throw new GateException($"{a.Path}: Invalid Define Constraint: {e.Message}");
            }
            if (!holds) return $"define constraint \"{c}\" does not hold";
        }
        string platform = config.Editor ? "Editor" : config.PlayerPlatform;
        if (a.ExcludePlatforms.Contains(platform)) return $"excludePlatforms has {platform}";
        if (a.IncludePlatforms.Count > 0 && !a.IncludePlatforms.Contains(platform)) return $"includePlatforms lacks {platform}";
        return null;
    }
}
