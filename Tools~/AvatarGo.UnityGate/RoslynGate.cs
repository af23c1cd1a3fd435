using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Diagnostics;
using System.Linq;
using System.Text;
using System.Threading;
using System.Threading.Tasks;
using Microsoft.CodeAnalysis;

namespace AvatarGo.UnityGate;

/// <summary>
/// Compiles a gate build's assemblies in this process with <see cref="RoslynCompiler"/>, each after those it references,
/// which it references as the images they emitted. An assembly whose reference failed is not compiled (as MSBuild does
/// not build a project whose reference failed). Every compilation is remembered for the life of the process by its
/// <see cref="GateAssembly.ContentKey"/>: a planted copy of the package compiles only what the plant changed, and
/// the surfaces compile once per Unity version flavour.
/// </summary>
public static class RoslynGate
{
    private static readonly ConcurrentDictionary<string, Lazy<CompiledAssembly>> Compiled = new(StringComparer.Ordinal);

    /// <summary>
    /// Compiles every assembly of the graph (or takes it from earlier in this process). Assemblies that do not
    /// depend on each other compile at the same time; the errors and the log follow the graph's order.
    /// </summary>
    public static GateResult Build(string packageRoot, AssemblyGraph graph)
    {
        var watch = Stopwatch.StartNew();
        TimeSpan cpuBefore = Process.GetCurrentProcess().TotalProcessorTime;
        var steps = new Dictionary<GateAssembly, Task<Step>>();
        foreach (GateAssembly a in graph.Assemblies) steps[a] = CompileAfterReferences(packageRoot, a, steps);
        // Rethrows the first failure itself (a GateException for a missing targeting pack, say), not an AggregateException.
        Task.WhenAll(steps.Values).GetAwaiter().GetResult();

        var errors = new List<GateDiagnostic>();
        var log = new StringBuilder();
        foreach (GateAssembly a in graph.Assemblies)
        {
            Step step = steps[a].Result;
            string configurations = string.Join(",", a.Configurations);
            errors.AddRange(step.Outcome.Errors.Select(e => e with { Configuration = configurations, Assembly = a.Plan.Name }));
            log.Append($"{a.Folder} ({configurations}): {step.Note}\n");
        }
        watch.Stop();
        double cpu = (Process.GetCurrentProcess().TotalProcessorTime - cpuBefore).TotalSeconds;
        var distinct = errors.Distinct().ToList();
        return new GateResult(distinct.Count > 0 ? 1 : 0, distinct, log.ToString(), watch.Elapsed.TotalSeconds, cpu)
        {
            Built = new Images(steps.ToDictionary(kv => kv.Key, kv => kv.Value.Result.Outcome)),
            Reused = steps.Values.Count(t => t.Result.Reused),
        };
    }

    // One assembly's part of a build: its outcome, whether it came from the cache, and what the log says.
    private sealed record Step(CompiledAssembly Outcome, bool Reused, string Note);

    private static async Task<Step> CompileAfterReferences(string packageRoot, GateAssembly a, IReadOnlyDictionary<GateAssembly, Task<Step>> steps)
    {
        Step[] references = await Task.WhenAll(a.References.Select(r => steps[r])).ConfigureAwait(false);
        int failed = Array.FindIndex(references, r => !r.Outcome.Succeeded);
        if (failed >= 0)
            return new Step(new CompiledAssembly { Errors = Array.Empty<GateDiagnostic>() }, false, $"not compiled, its reference {a.References[failed].Plan.Name} failed");
        bool fresh = false;
        CompiledAssembly outcome = await Task.Run(() => Compiled.GetOrAdd(a.ContentKey, _ => new Lazy<CompiledAssembly>(() =>
        {
            fresh = true;
            return RoslynCompiler.Compile(packageRoot, a, a.References.Select((r, i) => (r.Plan.Name + ".dll", references[i].Outcome.Reference)));
        }, LazyThreadSafetyMode.ExecutionAndPublication)).Value).ConfigureAwait(false);
        return new Step(outcome, !fresh, fresh
            ? $"compiled in {outcome.Seconds:0.00} s, {outcome.Errors.Count} error(s)"
            : $"compiled earlier in this process, {outcome.Errors.Count} error(s)");
    }

    // The emitted images, referenced from memory.
    private sealed class Images(IReadOnlyDictionary<GateAssembly, CompiledAssembly> outcomes) : IBuiltAssemblies
    {
        public MetadataReference Reference(GateAssembly assembly) =>
            outcomes[assembly].Reference ?? throw new InvalidOperationException($"{assembly.Folder} did not compile");
    }
}
