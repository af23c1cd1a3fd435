using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace AvatarGo.UnityGate;

/// <summary>One <c>versionDefines</c> entry of an asmdef.</summary>
/// <param name="Resource">A package name, or "Unity" for the editor's version.</param>
/// <param name="Expression">A version range (see <see cref="VersionRange"/>); empty means "whenever the resource is present".</param>
/// <param name="Define">The symbol defined when the range matches.</param>
public sealed record VersionDefine(string Resource, string Expression, string Define);

/// <summary>
/// An assembly definition as Unity reads it (fields of CustomScriptAssemblyData in UnityCsReference@2021.3
/// Editor/Mono/Scripting/ScriptCompilation/CustomScriptAssembly.cs), with its GUID from the .meta beside it.
/// The legacy <c>optionalUnityReferences: ["TestAssemblies"]</c> is expanded as Unity expands it.
/// </summary>
public sealed class Asmdef
{
    /// <summary>Path of the .asmdef relative to the package root, with '/'.</summary>
    public string Path { get; init; }

    /// <summary>The folder the asmdef sits in, relative to the package root ("" for the root).</summary>
    public string Folder => Path.Contains('/') ? Path.Substring(0, Path.LastIndexOf('/')) : "";

    /// <summary>The GUID of the .asmdef.meta (null when there is none).</summary>
    public string Guid { get; init; }

    /// <summary>The assembly name.</summary>
    public string Name { get; init; }

    /// <summary>References by assembly name or "GUID:...".</summary>
    public IReadOnlyList<string> References { get; init; } = Array.Empty<string>();

    /// <summary>Platforms the assembly is compiled for ("Editor", "WindowsStandalone64", ...); empty means all.</summary>
    public IReadOnlyList<string> IncludePlatforms { get; init; } = Array.Empty<string>();

    /// <summary>Platforms the assembly is not compiled for.</summary>
    public IReadOnlyList<string> ExcludePlatforms { get; init; } = Array.Empty<string>();

    /// <summary>True when only <see cref="PrecompiledReferences"/> are referenced among precompiled DLLs.</summary>
    public bool OverrideReferences { get; init; }

    /// <summary>DLL file names referenced when <see cref="OverrideReferences"/> is true.</summary>
    public IReadOnlyList<string> PrecompiledReferences { get; init; } = Array.Empty<string>();

    /// <summary>Symbols that must all hold for the assembly to be compiled (see <see cref="DefineConstraints"/>).</summary>
    public IReadOnlyList<string> DefineConstraints { get; init; } = Array.Empty<string>();

    /// <summary>Symbols defined from package or editor versions.</summary>
    public IReadOnlyList<VersionDefine> VersionDefines { get; init; } = Array.Empty<VersionDefine>();

    /// <summary>True when neither UnityEngine nor UnityEditor is referenced.</summary>
    public bool NoEngineReferences { get; init; }

    /// <summary>True when the assembly may contain unsafe code.</summary>
    public bool AllowUnsafeCode { get; init; }

    /// <summary>True when predefined assemblies (Assembly-CSharp) reference it automatically.</summary>
    public bool AutoReferenced { get; init; } = true;

    /// <summary>True when the assembly is compiled for the Editor only (includePlatforms is exactly ["Editor"]).</summary>
    public bool EditorOnly => IncludePlatforms.Count == 1 && IncludePlatforms[0] == "Editor";

    /// <summary>True when Unity treats it as a test assembly (a define constraint UNITY_INCLUDE_TESTS).</summary>
    public bool IsTestAssembly => DefineConstraints.Contains("UNITY_INCLUDE_TESTS");

    /// <summary>Reads an asmdef; throws <see cref="GateException"/> for JSON Unity could not read or a missing name.</summary>
    public static Asmdef Read(string packageRoot, string relativePath)
    {
        string full = System.IO.Path.Combine(packageRoot, relativePath);
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(File.ReadAllText(full));
        }
        catch (JsonException e)
        {
            throw new GateException($"{relativePath}: not valid JSON ({e.Message})");
        }
        using (doc)
        {
            JsonElement r = doc.RootElement;
            if (r.ValueKind != JsonValueKind.Object) throw new GateException($"{relativePath}: not a JSON object");
            string name = Str(r, "name");
            if (string.IsNullOrEmpty(name)) throw new GateException($"{relativePath}: Required property 'name' not set");
            var references = Strings(r, "references", relativePath);
            var precompiled = Strings(r, "precompiledReferences", relativePath);
            var constraints = Strings(r, "defineConstraints", relativePath);
            bool overrideReferences = Bool(r, "overrideReferences", false);
            bool autoReferenced = Bool(r, "autoReferenced", true);
            if (Strings(r, "optionalUnityReferences", relativePath).Count > 0)
            {
                // CustomScriptAssemblyWithLegacyData.UpdateLegacyData: the legacy test-assembly switch.
                autoReferenced = false;
                overrideReferences = true;
                references.AddRange(new[] { "UnityEngine.TestRunner", "UnityEditor.TestRunner" });
                precompiled.Add("nunit.framework.dll");
                constraints.Add("UNITY_INCLUDE_TESTS");
            }
            var include = Strings(r, "includePlatforms", relativePath);
            var exclude = Strings(r, "excludePlatforms", relativePath);
            if (include.Count > 0 && exclude.Count > 0)
                throw new GateException($"{relativePath}: both includePlatforms and excludePlatforms are set (Unity refuses the asmdef)");
            var versionDefines = new List<VersionDefine>();
            if (r.TryGetProperty("versionDefines", out JsonElement vds) && vds.ValueKind == JsonValueKind.Array)
                foreach (JsonElement vd in vds.EnumerateArray())
                    versionDefines.Add(new VersionDefine(Str(vd, "name") ?? "", Str(vd, "expression") ?? "", Str(vd, "define") ?? ""));
            return new Asmdef
            {
                Path = relativePath,
                Guid = ReadGuid(full + ".meta"),
                Name = name,
                References = references,
                IncludePlatforms = include,
                ExcludePlatforms = exclude,
                OverrideReferences = overrideReferences,
                PrecompiledReferences = precompiled,
                DefineConstraints = constraints,
                VersionDefines = versionDefines,
                NoEngineReferences = Bool(r, "noEngineReferences", false),
                AllowUnsafeCode = Bool(r, "allowUnsafeCode", false),
                AutoReferenced = autoReferenced,
            };
        }
    }

    /// <summary>The guid line of a .meta, or null.</summary>
    public static string ReadGuid(string metaPath)
    {
        if (!File.Exists(metaPath)) return null;
        string line = File.ReadLines(metaPath).FirstOrDefault(l => l.StartsWith("guid:", StringComparison.Ordinal));
        return line?.Substring(5).Trim();
    }

    private static string Str(JsonElement o, string key) =>
        o.TryGetProperty(key, out JsonElement e) && e.ValueKind == JsonValueKind.String ? e.GetString() : null;

    private static bool Bool(JsonElement o, string key, bool fallback) =>
        o.TryGetProperty(key, out JsonElement e) ? e.ValueKind == JsonValueKind.True || (e.ValueKind != JsonValueKind.False && fallback) : fallback;

    private static List<string> Strings(JsonElement o, string key, string path)
    {
        var list = new List<string>();
        if (!o.TryGetProperty(key, out JsonElement e) || e.ValueKind == JsonValueKind.Null) return list;
        if (e.ValueKind != JsonValueKind.Array) throw new GateException($"{path}: \"{key}\" is not an array");
        foreach (JsonElement item in e.EnumerateArray())
        {
            if (item.ValueKind != JsonValueKind.String) throw new GateException($"{path}: \"{key}\" holds a non-string");
            list.Add(item.GetString());
        }
        return list;
    }
}
