using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Text.RegularExpressions;

namespace AvatarGo.UnityGate;

/// <summary>
/// One compilation of a gate build: a planned assembly, shared by every configuration in which it comes out the same.
/// It is one generated MSBuild project, and one in-process compilation.
/// </summary>
public sealed class GateAssembly
{
    /// <summary>&lt;Assembly&gt;.&lt;hash&gt;: the project's folder and file name, and this compilation's name in reports.</summary>
    public string Folder { get; init; }

    /// <summary>The plan of the first configuration that compiles it (the others' differ at most in symbols no source tests).</summary>
    public AssemblyPlan Plan { get; init; }

    /// <summary>The first configuration that compiles it, for the project's header comment.</summary>
    public ConfigurationPlan FirstConfiguration { get; init; }

    /// <summary>The configurations that compile it, in plan order.</summary>
    public IReadOnlyList<string> Configurations => _configurations;

    /// <summary>The compilations it references, in the order of <see cref="AssemblyPlan.References"/>.</summary>
    public IReadOnlyList<GateAssembly> References { get; init; }

    /// <summary>
    /// A hash of everything that decides the compiler's output: name, kind, options, symbols (when a source has
    /// #if), the sources' package-relative paths and bytes, precompiled references and the references' own keys. Two
    /// compilations with the same key give the same assembly and diagnostics, in any copy of the package.
    /// </summary>
    public string ContentKey { get; init; }

    internal readonly List<string> _configurations = new();

    /// <inheritdoc />
    public override string ToString() => Folder;
}

/// <summary>
/// The distinct compilations of planned configurations, each after the ones it references. An assembly that comes out
/// the same in several configurations is compiled once and shared: same sources, options and references (themselves
/// shared), and either the same symbols or sources with no #if/#elif, so that the symbols cannot change what the
/// compiler sees.
/// </summary>
public sealed class AssemblyGraph
{
    private AssemblyGraph(IReadOnlyList<ConfigurationPlan> plans, IReadOnlyList<GateAssembly> assemblies,
        IReadOnlyDictionary<(string, string), GateAssembly> byConfiguration)
    {
        Plans = plans;
        Assemblies = assemblies;
        _byConfiguration = byConfiguration;
    }

    private readonly IReadOnlyDictionary<(string, string), GateAssembly> _byConfiguration;

    /// <summary>The plans the graph was made of.</summary>
    public IReadOnlyList<ConfigurationPlan> Plans { get; }

    /// <summary>Every distinct compilation, each after those it references.</summary>
    public IReadOnlyList<GateAssembly> Assemblies { get; }

    /// <summary>The compilation of an assembly in a configuration.</summary>
    public GateAssembly Of(string configuration, string assembly) => _byConfiguration[(configuration, assembly)];

    /// <summary>Groups the plans' assemblies into distinct compilations, reading the sources to key them by content.</summary>
    public static AssemblyGraph Of(string packageRoot, IReadOnlyList<ConfigurationPlan> plans)
    {
        var byKey = new Dictionary<string, GateAssembly>(StringComparer.Ordinal);
        var byConfiguration = new Dictionary<(string, string), GateAssembly>();
        var ordered = new List<GateAssembly>();
        var conditional = new Dictionary<string, bool>(StringComparer.Ordinal); // source -> has #if/#elif
        foreach (ConfigurationPlan plan in plans)
        {
            string config = plan.Configuration.Name;
            foreach (AssemblyPlan a in plan.Assemblies)
            {
                var references = a.References.Select(r => byConfiguration[(config, r)]).ToList();
                bool definesMatter = a.Sources.Any(src => conditional.TryGetValue(src, out bool c) ? c : conditional[src] = HasConditional(packageRoot, src));
                string key = string.Join("\n", new[] { a.Name, a.Kind.ToString(), a.AllowUnsafeCode.ToString(), a.RequireDocs.ToString(),
                        definesMatter ? string.Join(";", a.Defines) : "(no #if)" }
                    .Concat(a.Sources).Concat(references.Select(r => "ref:" + r.Folder)).Concat(a.PrecompiledReferences));
                if (!byKey.TryGetValue(key, out GateAssembly compilation))
                {
                    string content = Hash(key + "\n" + string.Join("\n", a.Sources.Select(src => Hash(File.ReadAllBytes(Path.Combine(packageRoot, src)))))
                                          + "\n" + string.Join("\n", references.Select(r => r.ContentKey)));
                    compilation = new GateAssembly
                    {
                        Folder = a.Name + "." + Hash(key).Substring(0, 8),
                        Plan = a,
                        FirstConfiguration = plan,
                        References = references,
                        ContentKey = content,
                    };
                    byKey[key] = compilation;
                    ordered.Add(compilation);
                }
                compilation._configurations.Add(config);
                byConfiguration[(config, a.Name)] = compilation;
            }
        }
        return new AssemblyGraph(plans, ordered, byConfiguration);
    }

    private static bool HasConditional(string packageRoot, string source) =>
        File.ReadLines(Path.Combine(packageRoot, source)).Any(l => Regex.IsMatch(l, @"^\s*#\s*(if|elif)\b"));

    private static string Hash(string text) => Hash(Encoding.UTF8.GetBytes(text));

    private static string Hash(byte[] bytes) => Convert.ToHexString(SHA256.HashData(bytes)).ToLowerInvariant();
}
