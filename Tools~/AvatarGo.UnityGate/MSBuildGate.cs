using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Microsoft.CodeAnalysis;

namespace AvatarGo.UnityGate;

/// <summary>
/// Builds written gate projects with the .NET SDK's MSBuild, in one dotnet build of gate.slnx, and reads the errors
/// from its console output. Each build starts MSBuild and fresh csc processes, so it costs seconds even for one small
/// project; the gate uses it to check that the generated projects compile as the in-process compiler says.
/// </summary>
public static class MSBuildGate
{
    private static readonly Regex ErrorLine = new(
        @"^(?:(?<file>[^\s(][^(\r\n]*?)\((?<line>\d+),(?<col>\d+)\)\s*:[ \t]*|(?<tool>[^:\[\r\n]*?)[ \t]*:[ \t]*)?error[ \t]+(?<code>[A-Z]+\d+)[ \t]*:[ \t]*(?<message>[^\r\n]*?)(?:[ \t]+\[(?<project>[^\]\r\n]+)\])?\r?$",
        RegexOptions.CultureInvariant | RegexOptions.Multiline);

    /// <summary>Builds the projects; successfully built ones go into <paramref name="cacheDir"/> when given.</summary>
    public static GateResult Build(string packageRoot, ProjectSet projects, string outDir, string cacheDir)
    {
        var watch = Stopwatch.StartNew();
        double cpuBefore = ChildProcessorSeconds();
        var psi = new ProcessStartInfo("dotnet")
        {
            WorkingDirectory = outDir,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string arg in new[] { "build", projects.Solution, "-c", "Release", "-nologo", "-v:q", "-tl:off", "-nodeReuse:false", "-clp:NoSummary" })
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
        return new GateResult(p.ExitCode, errors, output, watch.Elapsed.TotalSeconds, cpu) { Built = new Outputs(projects, outDir), Reused = projects.Cached.Count };
    }

    // The DLLs MSBuild wrote (or the cache held), read from disk.
    private sealed class Outputs(ProjectSet projects, string outDir) : IBuiltAssemblies
    {
        public MetadataReference Reference(GateAssembly assembly) => MetadataReference.CreateFromFile(projects.Output(outDir, assembly));
    }

    // Every project that built with no error goes into the cache under its content key.
    private static void Remember(ProjectSet projects, string outDir, string cacheDir, List<GateDiagnostic> errors)
    {
        foreach (GateAssembly a in projects.Graph.Assemblies)
        {
            if (projects.Cached.ContainsKey(a.Folder)) continue;
            string assembly = a.Plan.Name;
            if (errors.Any(e => e.Assembly == assembly && a.Configurations.Any(c => e.Configuration.Split(',').Contains(c)))) continue;
            string dll = Path.Combine(outDir, a.Folder, "bin", "Release", assembly + ".dll");
            if (!File.Exists(dll)) continue;
            string target = Path.Combine(cacheDir, a.ContentKey);
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
        var byFolder = projects.Graph.Assemblies.ToDictionary(a => a.Folder, StringComparer.Ordinal);
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
                    if (byFolder.TryGetValue(parts[0], out GateAssembly a)) configuration = string.Join(",", a.Configurations);
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
