using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

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

/// <summary>The outcome of building generated projects.</summary>
/// <param name="ExitCode">dotnet build's exit code.</param>
/// <param name="Errors">Every distinct error.</param>
/// <param name="Output">MSBuild's console output, for messages when something unexpected happened.</param>
/// <param name="Seconds">Wall-clock time of the build.</param>
/// <param name="CpuSeconds">Processor time of dotnet build and every process it waited for (MSBuild nodes, csc).</param>
public sealed record GateResult(int ExitCode, IReadOnlyList<GateDiagnostic> Errors, string Output, double Seconds, double CpuSeconds)
{
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
        $"exit {ExitCode}, {Errors.Count} error(s) in {Seconds:0.0} s ({CpuSeconds:0.0} s of processor time)" + (Errors.Count > 0 ? ":\n  " + string.Join("\n  ", Errors) : "") +
        (ExitCode != 0 && Errors.Count == 0 ? "\n--- output ---\n" + Output : "");
}

/// <summary>Plans, writes and builds configurations with the .NET SDK's MSBuild.</summary>
public static class GateBuild
{
    private static readonly Regex ErrorLine = new(
        @"^(?:(?<file>[^\s(][^(\r\n]*?)\((?<line>\d+),(?<col>\d+)\)\s*:[ \t]*|(?<tool>[^:\[\r\n]*?)[ \t]*:[ \t]*)?error[ \t]+(?<code>[A-Z]+\d+)[ \t]*:[ \t]*(?<message>[^\r\n]*?)(?:[ \t]+\[(?<project>[^\]\r\n]+)\])?\r?$",
        RegexOptions.CultureInvariant | RegexOptions.Multiline);

    /// <summary>Where the gate writes its projects inside a package: Tools~/out/gate (ignored by git).</summary>
    public static string DefaultOutDir(string packageRoot) => Path.Combine(packageRoot, "Tools~", "out", "gate");

    /// <summary>
    /// Plans the configurations, writes their projects and builds them all in one MSBuild run. With
    /// <paramref name="onlyAssemblies"/>, only those assemblies and what they reference are built (for quick checks
    /// of one assembly); otherwise everything each configuration compiles.
    /// </summary>
    public static GateResult Run(string packageRoot, string nugetRoot, IEnumerable<UnityConfiguration> configurations, string outDir = null,
        IReadOnlyCollection<string> onlyAssemblies = null, string cacheDir = null)
    {
        var planner = new Planner(packageRoot, nugetRoot);
        var plans = configurations.Select(planner.Plan).ToList();
        if (onlyAssemblies != null) plans = plans.Select(p => Restrict(p, onlyAssemblies)).ToList();
        return Build(planner.PackageRoot, plans, outDir ?? DefaultOutDir(planner.PackageRoot), cacheDir);
    }

    /// <summary>The plan cut down to the named assemblies and their references.</summary>
    public static ConfigurationPlan Restrict(ConfigurationPlan plan, IReadOnlyCollection<string> names)
    {
        var keep = new HashSet<string>(names, StringComparer.Ordinal);
        foreach (AssemblyPlan a in plan.Assemblies.Reverse())
            if (keep.Contains(a.Name)) keep.UnionWith(a.References);
        return plan with { Assemblies = plan.Assemblies.Where(a => keep.Contains(a.Name)).ToList() };
    }

    /// <summary>Writes the plans' projects and builds them.</summary>
    public static GateResult Build(string packageRoot, IReadOnlyList<ConfigurationPlan> plans, string outDir, string cacheDir = null)
    {
        ProjectSet projects = ProjectWriter.Write(packageRoot, outDir, plans, cacheDir);
        string slnx = projects.Solution;
        var watch = Stopwatch.StartNew();
        double cpuBefore = ChildProcessorSeconds();
        var psi = new ProcessStartInfo("dotnet")
        {
            WorkingDirectory = outDir,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string arg in new[] { "build", slnx, "-c", "Release", "-nologo", "-v:q", "-tl:off", "-nodeReuse:false", "-clp:NoSummary" })
            psi.ArgumentList.Add(arg);
        psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        psi.Environment["DOTNET_NOLOGO"] = "1";
        psi.Environment["MSBUILDDISABLENODEREUSE"] = "1";
        using Process p = Process.Start(psi) ?? throw new InvalidOperationException("could not start dotnet");
        var stderr = p.StandardError.ReadToEndAsync();
        string output = p.StandardOutput.ReadToEnd();
        p.WaitForExit();
        output += stderr.Result;
        watch.Stop();
        double cpu = ChildProcessorSeconds() - cpuBefore;
        List<GateDiagnostic> errors = Parse(output, packageRoot, outDir, projects);
        if (cacheDir != null) Remember(projects, outDir, cacheDir, errors);
        return new GateResult(p.ExitCode, errors, output, watch.Elapsed.TotalSeconds, cpu)
        {
            Plans = plans,
            Projects = projects,
            OutDir = outDir,
            PackageRoot = packageRoot,
        };
    }

    // Every project that built with no error goes into the cache under its content key.
    private static void Remember(ProjectSet projects, string outDir, string cacheDir, List<GateDiagnostic> errors)
    {
        foreach (var (folder, key) in projects.ContentKeys)
        {
            if (projects.Cached.ContainsKey(folder)) continue;
            string assembly = folder.Substring(0, folder.LastIndexOf('.'));
            if (errors.Any(e => e.Assembly == assembly && projects.Configurations[folder].Any(c => e.Configuration.Split(',').Contains(c)))) continue;
            string dll = Path.Combine(outDir, folder, "bin", "Release", assembly + ".dll");
            if (!File.Exists(dll)) continue;
            string target = Path.Combine(cacheDir, key);
            Directory.CreateDirectory(target);
            // Builds running side by side may cache the same assembly: write to a temporary name, then move it in.
            string temp = Path.Combine(target, $"{assembly}.{Guid.NewGuid():N}.tmp");
            File.Copy(dll, temp);
            try
            {
                File.Move(temp, Path.Combine(target, assembly + ".dll"), overwrite: false);
            }
            catch (IOException)
            {
                File.Delete(temp); // another build cached the same bytes first
            }
        }
    }

    /// <summary>
    /// Processor time of this process's finished children and their waited-for descendants (Linux: cutime + cstime in
    /// /proc/self/stat); NaN elsewhere. The machine may be shared, so this says more about the gate's cost than wall time.
    /// </summary>
    public static double ChildProcessorSeconds()
    {
        try
        {
            string stat = File.ReadAllText("/proc/self/stat");
            string[] fields = stat.Substring(stat.LastIndexOf(')') + 2).Split(' ');
            // After "pid (comm) ", field 3 (state) is index 0, so cutime (16) and cstime (17) are at 13 and 14.
            return (long.Parse(fields[13]) + long.Parse(fields[14])) / 100.0;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or FormatException or IndexOutOfRangeException)
        {
            return double.NaN;
        }
    }

    /// <summary>The distinct errors in MSBuild console output.</summary>
    public static List<GateDiagnostic> Parse(string output, string packageRoot, string outDir, ProjectSet projects)
    {
        var errors = new List<GateDiagnostic>();
        string root = Path.GetFullPath(packageRoot).TrimEnd('/') + "/";
        string outRoot = Path.GetFullPath(outDir).TrimEnd('/') + "/";
        foreach (Match m in ErrorLine.Matches(output))
        {
            string project = m.Groups["project"].Value;
            string configuration = "", assembly = "";
            if (project.StartsWith(outRoot, StringComparison.Ordinal))
            {
                string[] parts = project.Substring(outRoot.Length).Split('/');
                if (parts.Length >= 2)
                {
                    assembly = parts[0].Contains('.') ? parts[0].Substring(0, parts[0].LastIndexOf('.')) : parts[0];
                    if (projects.Configurations.TryGetValue(parts[0], out IReadOnlyList<string> configs)) configuration = string.Join(",", configs);
                }
            }
            string file = m.Groups["file"].Success ? m.Groups["file"].Value.Trim() : m.Groups["tool"].Value.Trim();
            if (file.StartsWith(root, StringComparison.Ordinal)) file = file.Substring(root.Length);
            int line = m.Groups["line"].Success ? int.Parse(m.Groups["line"].Value) : 0;
            var d = new GateDiagnostic(configuration, assembly, file, line, m.Groups["code"].Value, m.Groups["message"].Value.Trim());
            if (!errors.Contains(d)) errors.Add(d);
        }
        return errors;
    }
}
