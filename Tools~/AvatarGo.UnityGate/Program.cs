using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;

namespace AvatarGo.UnityGate;

/// <summary>
/// avatargo-gate: generate (write the projects), build (write them and compile the same plan in-process, or build them
/// with MSBuild with --msbuild), plan (print what each configuration compiles), verify-surface (check the surface
/// against a UnityCsReference checkout).
/// </summary>
public static class Program
{
    /// <summary>The NuGet packages folder this tool was restored with (where NUnit 3.6.0 was downloaded).</summary>
    public static string NuGetPackageRoot =>
        typeof(Program).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>().First(a => a.Key == "NuGetPackageRoot").Value;

    /// <summary>Entry point.</summary>
    public static int Main(string[] args)
    {
        try
        {
            return Run(args, Console.Out, Console.Error);
        }
        catch (GateException e)
        {
            Console.Error.WriteLine("gate: " + e.Message);
            return 1;
        }
    }

    /// <summary>Runs a command, writing to the given writers.</summary>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        string command = args.Length > 0 ? args[0] : "--help";
        string package = Option(args, "--package") ?? FindPackageRoot();
        string outDir = Option(args, "--out") ?? GateBuild.DefaultOutDir(package);
        IReadOnlyList<UnityConfiguration> configs = Option(args, "--config") is string c
            ? c.Split(',').Select(UnityConfiguration.Named).ToList()
            : UnityConfiguration.Standard;
        switch (command)
        {
            case "plan":
            {
                var planner = new Planner(package, NuGetPackageRoot);
                foreach (UnityConfiguration config in configs)
                {
                    ConfigurationPlan plan = planner.Plan(config);
                    stdout.WriteLine($"{config.Name}: {config.Description}");
                    foreach (AssemblyPlan a in plan.Assemblies)
                        stdout.WriteLine($"  {a.Kind,-7} {a.Name}: {a.Sources.Count} file(s); references {string.Join(", ", a.References.Concat(a.PrecompiledReferences.Select(Path.GetFileName)))}" +
                                         string.Concat(a.Notes.Where(_ => a.Kind == PlanKind.Package).Select(n => "; " + n)));
                    foreach (SkippedAssembly s in plan.Skipped)
                        stdout.WriteLine($"  skipped {s.Name}: {s.Reason}");
                }
                return 0;
            }
            case "generate":
            {
                var planner = new Planner(package, NuGetPackageRoot);
                AssemblyGraph graph = AssemblyGraph.Of(planner.PackageRoot, configs.Select(planner.Plan).ToList());
                string slnx = ProjectWriter.Write(planner.PackageRoot, outDir, graph).Solution;
                stdout.WriteLine($"wrote {slnx}");
                return 0;
            }
            case "build":
            {
                GateCompiler compiler = args.Contains("--msbuild") ? GateCompiler.MSBuild : GateCompiler.Roslyn;
                GateResult result = GateBuild.Run(package, NuGetPackageRoot, configs, outDir, compiler: compiler);
                if (compiler == GateCompiler.Roslyn) stdout.Write(result.Output); // one line per compilation
                stdout.WriteLine(result.Describe());
                return result.Succeeded ? 0 : 1;
            }
            case "verify-surface":
            {
                string unitySource = Option(args, "--unity-cs-reference") ?? throw new GateException("verify-surface needs --unity-cs-reference <git dir of Unity-Technologies/UnityCsReference>");
                var sources = new Dictionary<string, string>(StringComparer.Ordinal) { ["UnityCsReference"] = unitySource };
                foreach (string extra in Options(args, "--source"))
                {
                    int eq = extra.IndexOf('=');
                    if (eq > 0) sources[extra.Substring(0, eq)] = extra.Substring(eq + 1);
                }
                List<string> problems = SurfaceVerifier.Verify(Path.Combine(package, "Tools~", "UnitySurface"), sources, stdout);
                foreach (string p in problems) stderr.WriteLine("  - " + p);
                stdout.WriteLine($"verify-surface: {problems.Count} problem(s)");
                return problems.Count == 0 ? 0 : 1;
            }
            default:
                stdout.WriteLine("usage: avatargo-gate plan|generate|build [--config a,b] [--package DIR] [--out DIR] [--msbuild]");
                stdout.WriteLine("       build compiles in-process with Roslyn; --msbuild builds the generated projects with dotnet build instead");
                stdout.WriteLine("       avatargo-gate verify-surface --unity-cs-reference GITDIR [--source com.unity.test-framework=GITDIR]");
                stdout.WriteLine("configurations: " + string.Join(", ", UnityConfiguration.Standard.Select(x => x.Name)));
                return command is "--help" or "-h" ? 0 : 2;
        }
    }

    private static string Option(string[] args, string name)
    {
        int i = Array.IndexOf(args, name);
        return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
    }

    private static IEnumerable<string> Options(string[] args, string name)
    {
        for (int i = 0; i + 1 < args.Length; i++)
            if (args[i] == name) yield return args[i + 1];
    }

    private static string FindPackageRoot()
    {
        foreach (string start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            for (string dir = start; !string.IsNullOrEmpty(dir); dir = Path.GetDirectoryName(dir))
                if (File.Exists(Path.Combine(dir, "package.json")) && Directory.Exists(Path.Combine(dir, "Tools~", "UnitySurface")))
                    return dir;
        throw new GateException("no package root (a folder with package.json and Tools~/UnitySurface) above the current directory");
    }
}
