using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;

namespace AvatarGo.UnityGate;

/// <summary>One compiler or MSBuild error from a gate build.</summary>
/// <param name="Configuration">The configurations (comma-separated) that compile the failing project, or "" when MSBuild could not tell.</param>
/// <param name="Assembly">The assembly (project) name.</param>
/// <param name="File">The file, package-relative when it is in the package.</param>
/// <param name="Line">1-based line, 0 when none.</param>
/// <param name="Code">The code: CS0117, CS0619, MSB4019, NU1101, ...</param>
/// <param name="Message">The message text.</param>
public sealed record GateDiagnostic(string Configuration, string Assembly, string File, int Line, string Code, string Message)
{
    /// <inheritdoc />
    public override string ToString() => $"[{Configuration}] {Assembly}: {File}({Line}): {Code}: {Message}";
}

/// <summary>How a gate build compiles the planned assemblies.</summary>
public enum GateCompiler
{
    /// <summary>In this process, with Roslyn, from the same plan and settings as the generated projects (the default).</summary>
    Roslyn,

    /// <summary>The generated projects, built by the .NET SDK's MSBuild (dotnet build gate.slnx).</summary>
    MSBuild,
}

/// <summary>The outcome of a gate build.</summary>
/// <param name="ExitCode">dotnet build's exit code; for the in-process compiler 1 when there is an error, else 0.</param>
/// <param name="Errors">Every distinct error.</param>
/// <param name="Output">MSBuild's console output, or the in-process compiler's log of each compilation.</param>
/// <param name="Seconds">Wall-clock time of the compile (projects written and plans made before it are not counted).</param>
/// <param name="CpuSeconds">
/// Processor time: of dotnet build and every process it waited for (MSBuild nodes, csc), or of this whole process
/// while it compiled in-process.
/// </param>
public sealed record GateResult(int ExitCode, IReadOnlyList<GateDiagnostic> Errors, string Output, double Seconds, double CpuSeconds)
{
    /// <summary>Which compiler built it.</summary>
    public GateCompiler Compiler { get; init; }

    /// <summary>The assemblies it built, to reference again (only complete when it succeeded).</summary>
    public IBuiltAssemblies Built { get; init; }

    /// <summary>
    /// Compilations not run again because one with the same content key was kept: in memory from earlier in this
    /// process (in-process compiler), or in the cache folder (MSBuild).
    /// </summary>
    public int Reused { get; init; }

    /// <summary>The plans that were built.</summary>
    public IReadOnlyList<ConfigurationPlan> Plans { get; init; }

    /// <summary>The projects that were written.</summary>
    public ProjectSet Projects { get; init; }

    /// <summary>The folder the projects were written to.</summary>
    public string OutDir { get; init; }

    /// <summary>The package that was built.</summary>
    public string PackageRoot { get; init; }

    /// <summary>True when the build succeeded with no error.</summary>
    public bool Succeeded => ExitCode == 0 && Errors.Count == 0;

    /// <summary>A readable summary for assertion messages.</summary>
    public string Describe() =>
        $"{Compiler}: exit {ExitCode}, {Errors.Count} error(s), {Projects?.Graph.Assemblies.Count} compilation(s) ({Reused} reused) in {Seconds:0.0} s ({CpuSeconds:0.0} s of processor time)" + (Errors.Count > 0 ? ":\n  " + string.Join("\n  ", Errors) : "") +
        (ExitCode != 0 && Errors.Count == 0 ? "\n--- output ---\n" + Output : "");
}

/// <summary>The assemblies a gate build produced, as references for another compilation against them.</summary>
public interface IBuiltAssemblies
{
    /// <summary>The built assembly of a compilation.</summary>
    MetadataReference Reference(GateAssembly assembly);
}

/// <summary>Plans configurations, writes their MSBuild projects and compiles them, in-process or with MSBuild.</summary>
public static class GateBuild
{
    /// <summary>Where the gate writes its projects inside a package: Tools~/out/gate (ignored by git).</summary>
    public static string DefaultOutDir(string packageRoot) => Path.Combine(packageRoot, "Tools~", "out", "gate");

    /// <summary>
    /// Plans the configurations, writes their projects and compiles them. With <paramref name="onlyAssemblies"/>,
    /// only those assemblies and what they reference are compiled (for quick checks of one assembly); otherwise
    /// everything each configuration compiles.
    /// </summary>
    /// <param name="packageRoot">The package.</param>
    /// <param name="nugetRoot">The NuGet packages folder (NUnit 3.6.0).</param>
    /// <param name="configurations">The configurations to compile.</param>
    /// <param name="outDir">Where the projects go (default <see cref="DefaultOutDir"/>).</param>
    /// <param name="onlyAssemblies">Optional: the assemblies to compile, with their references.</param>
    /// <param name="compiler">In-process Roslyn (default) or MSBuild over the generated projects.</param>
    /// <param name="cacheDir">MSBuild only: a folder of assemblies built before, by content (see <see cref="ProjectWriter.Write"/>).</param>
    public static GateResult Run(string packageRoot, string nugetRoot, IEnumerable<UnityConfiguration> configurations, string outDir = null,
        IReadOnlyCollection<string> onlyAssemblies = null, GateCompiler compiler = GateCompiler.Roslyn, string cacheDir = null)
    {
        var planner = new Planner(packageRoot, nugetRoot);
        var plans = configurations.Select(planner.Plan).ToList();
        if (onlyAssemblies != null) plans = plans.Select(p => Restrict(p, onlyAssemblies)).ToList();
        return Build(planner.PackageRoot, plans, outDir ?? DefaultOutDir(planner.PackageRoot), compiler, cacheDir);
    }

    /// <summary>The plan cut down to the named assemblies and their references.</summary>
    public static ConfigurationPlan Restrict(ConfigurationPlan plan, IReadOnlyCollection<string> names)
    {
        var keep = new HashSet<string>(names, StringComparer.Ordinal);
        foreach (AssemblyPlan a in plan.Assemblies.Reverse())
            if (keep.Contains(a.Name)) keep.UnionWith(a.References);
        return plan with { Assemblies = plan.Assemblies.Where(a => keep.Contains(a.Name)).ToList() };
    }

    /// <summary>
    /// Writes the plans' projects and compiles them. The in-process compiler writes the same projects (the cache is
    /// MSBuild's only), so Tools~/out/gate always holds what was checked, ready for dotnet build or an IDE.
    /// </summary>
    public static GateResult Build(string packageRoot, IReadOnlyList<ConfigurationPlan> plans, string outDir,
        GateCompiler compiler = GateCompiler.Roslyn, string cacheDir = null)
    {
        AssemblyGraph graph = AssemblyGraph.Of(packageRoot, plans);
        ProjectSet projects = ProjectWriter.Write(packageRoot, outDir, graph, compiler == GateCompiler.MSBuild ? cacheDir : null);
        GateResult result = compiler == GateCompiler.MSBuild
            ? MSBuildGate.Build(packageRoot, projects, outDir, cacheDir)
            : RoslynGate.Build(packageRoot, graph);
        return result with
        {
            Compiler = compiler,
            Plans = plans,
            Projects = projects,
            OutDir = outDir,
            PackageRoot = packageRoot,
        };
    }
}
