using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace AvatarGo.UnityGate;

/// <summary>
/// Built-in modules are packages a project can disable (com.unity.modules.*): a package whose code uses a type of
/// UnityEngine.AnimationModule must declare com.unity.modules.animation in package.json "dependencies". The surface
/// keeps UnityEngine's types in one folder per module (Tools~/UnitySurface/UnityEngine/&lt;Module&gt;/), so the modules
/// the package uses follow from the surface declarations its code references.
/// </summary>
public static class ModuleDependencies
{
    /// <summary>
    /// The built-in package of each engine module the surface has (module names from the assembly each type lives in,
    /// UnityEngine.&lt;Module&gt;.dll; package names as listed in Unity's "Built-in packages" manual page). CoreModule is
    /// the engine itself and no package.
    /// </summary>
    public static readonly IReadOnlyDictionary<string, string> PackageOfModule = new Dictionary<string, string>(StringComparer.Ordinal)
    {
        ["CoreModule"] = null,
        ["AnimationModule"] = "com.unity.modules.animation",
        ["XRModule"] = "com.unity.modules.xr",
        ["PhysicsModule"] = "com.unity.modules.physics",
        ["JSONSerializeModule"] = "com.unity.modules.jsonserialize",
        ["TextRenderingModule"] = "com.unity.modules.textrendering",
        ["IMGUIModule"] = "com.unity.modules.imgui",
    };

    /// <summary>Problems: a module the package's code uses that package.json does not list, or a module folder with no known package.</summary>
    public static List<string> Check(string packageRoot, GateResult built)
    {
        var problems = new List<string>();
        SortedSet<string> used = SurfaceUsage.Used(built);
        var modules = SurfaceUsage.Declarations(packageRoot, UnityConfiguration.Standard)
            .Where(d => d.Assembly == "UnityEngine" && used.Contains(d.Id))
            .GroupBy(d => d.Module).ToDictionary(g => g.Key, g => g.Select(d => d.Id).ToList(), StringComparer.Ordinal);
        HashSet<string> declared = DeclaredDependencies(packageRoot);
        foreach (var (module, ids) in modules.OrderBy(kv => kv.Key, StringComparer.Ordinal))
        {
            if (!PackageOfModule.TryGetValue(module, out string package))
                problems.Add($"Tools~/UnitySurface/UnityEngine/{module}: no built-in package is known for this module (add it to ModuleDependencies.PackageOfModule)");
            else if (package != null && !declared.Contains(package))
                problems.Add($"package.json: the package uses UnityEngine.{module} ({string.Join(", ", ids.Take(3))}) but \"dependencies\" lacks \"{package}\": \"1.0.0\"");
        }
        return problems;
    }

    /// <summary>The names in package.json "dependencies".</summary>
    public static HashSet<string> DeclaredDependencies(string packageRoot)
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(packageRoot, "package.json")));
        var names = new HashSet<string>(StringComparer.Ordinal);
        if (doc.RootElement.TryGetProperty("dependencies", out JsonElement deps) && deps.ValueKind == JsonValueKind.Object)
            foreach (JsonProperty p in deps.EnumerateObject()) names.Add(p.Name);
        return names;
    }
}
