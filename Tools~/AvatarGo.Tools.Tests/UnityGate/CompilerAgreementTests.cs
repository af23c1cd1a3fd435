using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection.Metadata;
using System.Text.RegularExpressions;
using AvatarGo.UnityGate;
using Microsoft.CodeAnalysis;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// The generated MSBuild projects, built by dotnet build, against the in-process compiler every other gate test uses:
/// on the package and on planted copies they must report the same errors (configuration, assembly, file, line, code
/// and message), and on the package emit assemblies with the same types, members and assembly references. Slow
/// (MSBuild and a csc process per project): run with AVATARGO_SLOW=1.
/// </summary>
[TestFixture]
[Category("Slow")]
public class CompilerAgreementTests
{
    private static GateResult Build(string packageRoot, GateCompiler compiler, string outDir) =>
        GateBuild.Run(packageRoot, AvatarGo.UnityGate.Program.NuGetPackageRoot, UnityConfiguration.Standard, outDir, compiler: compiler,
            cacheDir: compiler == GateCompiler.MSBuild ? GateCache.Dir : null);

    private static string TempOut() => Path.Combine(Path.GetTempPath(), "avatargo-gate-out-" + Guid.NewGuid().ToString("N"));

    // Builds the package both ways, checks both, then deletes what they wrote (MSBuild's DLLs are read by the check).
    private static void BuildBothWays(string packageRoot, Action<GateResult, GateResult> check)
    {
        string msbuildOut = TempOut(), roslynOut = TempOut();
        try
        {
            GateResult msbuild = Build(packageRoot, GateCompiler.MSBuild, msbuildOut);
            GateResult roslyn = Build(packageRoot, GateCompiler.Roslyn, roslynOut);
            TestContext.Progress.WriteLine($"MSBuild {msbuild.Seconds:0.0} s wall, {msbuild.CpuSeconds:0.0} s processor; " +
                                           $"in-process {roslyn.Seconds:0.0} s wall, {roslyn.CpuSeconds:0.0} s processor");
            Assert.That(Regex.IsMatch(msbuild.Output, @"\bwarning [A-Z]+\d+"), Is.False, "MSBuild warned (the in-process compiler sees no MSBuild warning): " + msbuild.Output);
            AssertSameErrors(msbuild, roslyn);
            check(msbuild, roslyn);
        }
        finally
        {
            foreach (string dir in new[] { msbuildOut, roslynOut })
                if (Directory.Exists(dir)) Directory.Delete(dir, recursive: true);
        }
    }

    private static void AssertSameErrors(GateResult msbuild, GateResult roslyn)
    {
        var fromMSBuild = msbuild.Errors.Select(e => e.ToString()).OrderBy(e => e, StringComparer.Ordinal).ToList();
        var inProcess = roslyn.Errors.Select(e => e.ToString()).OrderBy(e => e, StringComparer.Ordinal).ToList();
        Assert.That(inProcess, Is.EqualTo(fromMSBuild), $"MSBuild: {msbuild.Describe()}\nin-process: {roslyn.Describe()}");
        Assert.That(roslyn.Succeeded, Is.EqualTo(msbuild.Succeeded));
    }

    [Test]
    public void BothCompilersBuildThePackageAlike() => BuildBothWays(Paths.PackageRoot, (msbuild, roslyn) =>
    {
        Assert.That(msbuild.Succeeded, Is.True, msbuild.Describe());
        Assert.That(roslyn.Projects.Graph.Assemblies.Select(a => a.Folder), Is.EqualTo(msbuild.Projects.Graph.Assemblies.Select(a => a.Folder)));
        foreach (GateAssembly a in roslyn.Projects.Graph.Assemblies)
        {
            GateAssembly built = msbuild.Projects.Graph.Assemblies.Single(b => b.Folder == a.Folder);
            Assert.That(Contents(roslyn.Built.Reference(a)), Is.EqualTo(Contents(msbuild.Built.Reference(built))), a.Folder);
        }
    });

    [Test]
    public void BothCompilersReportTheSameErrorsOnPlantedDefects()
    {
        using var copy = new PackageCopy();
        // A misspelled member (a method-body error) beside a public type without XML docs in the same assembly: csc
        // stops after the bodies, so CS1591 must not be reported there...
        copy.Replace("Runtime/Bridge/UnityConversions.cs", "transform.localPosition = pose.Position.ToUnity();", "transform.localPositon = pose.Position.ToUnity();");
        copy.Write("Runtime/Bridge/PlantedUndocumented.cs", "namespace AvatarGo\n{\n    public static class PlantedUndocumented\n    {\n        public static int Value => 1;\n    }\n}\n");
        // ...while in an assembly whose bodies compile (a planted one, that nothing references), the missing docs are
        // errors: warnings as errors.
        copy.Write("Runtime/Planted/AvatarGo.Planted.asmdef", "{ \"name\": \"AvatarGo.Planted\", \"references\": [\"AvatarGo.Core\"], \"noEngineReferences\": true }\n");
        copy.Write("Runtime/Planted/PlantedUndocumented.cs", "namespace AvatarGo.Planted\n{\n    public static class PlantedUndocumented\n    {\n    }\n}\n");
        // An obsolete member used in a test: CS0618, a warning made an error.
        copy.Write("Tests/Core/Planted/PlantedObsoleteTests.cs",
            "namespace AvatarGo.Core.Tests\n{\n    public class PlantedObsoleteTests\n    {\n        [System.Obsolete(\"use New\")]\n        private static int Old() => 1;\n\n" +
            "        public int UsesOld() => Old();\n    }\n}\n");
        // Symbols Unity does not define, and MSBuild adds unless told not to.
        copy.Write("Runtime/Core/PlantedSymbols.cs",
            "#if RELEASE || NETSTANDARD2_0_OR_GREATER || NETSTANDARD2_1_OR_GREATER\n#error the SDK's implicit symbols reached the compiler\n#endif\n");
        BuildBothWays(copy.Root, (_, roslyn) =>
            Assert.That(roslyn.Errors.Select(e => $"{e.Code} {e.File}").Distinct(), Is.EquivalentTo(new[]
            {
                "CS1061 Runtime/Bridge/UnityConversions.cs", "CS1591 Runtime/Planted/PlantedUndocumented.cs", "CS0618 Tests/Core/Planted/PlantedObsoleteTests.cs",
            }), roslyn.Describe()));
    }

    [Test]
    public void BothCompilersStopAtSyntaxErrorsAndSkipWhatDependsOnAFailedAssembly()
    {
        using var copy = new PackageCopy();
        copy.Write("Runtime/Core/PlantedSyntax.cs", "namespace AvatarGo.Core\n{\n    internal static class PlantedSyntax\n    {\n        internal static int Value => 1\n    }\n}\n");
        copy.Write("Runtime/Core/PlantedBinding.cs", "namespace AvatarGo.Core\n{\n    internal static class PlantedBinding\n    {\n        internal static int Value => Missing;\n    }\n}\n");
        BuildBothWays(copy.Root, (_, roslyn) =>
            Assert.That(roslyn.Errors.Select(e => $"{e.Assembly} {e.Code} {e.File}").Distinct(), Is.EqualTo(new[] { "AvatarGo.Core CS1002 Runtime/Core/PlantedSyntax.cs" }),
                "a syntax error stops csc before binding (no CS0103), and nothing that references the core is compiled: " + roslyn.Describe()));
    }

    // What an assembly declares and references: its types with their fields, methods and properties, and the assemblies it refers to.
    private static List<string> Contents(MetadataReference reference)
    {
        var metadata = (AssemblyMetadata)((PortableExecutableReference)reference).GetMetadata();
        MetadataReader reader = metadata.GetModules()[0].GetMetadataReader();
        var contents = new List<string>();
        foreach (AssemblyReferenceHandle h in reader.AssemblyReferences)
        {
            AssemblyReference r = reader.GetAssemblyReference(h);
            contents.Add($"references {reader.GetString(r.Name)} {r.Version}");
        }
        foreach (TypeDefinitionHandle h in reader.TypeDefinitions)
        {
            TypeDefinition t = reader.GetTypeDefinition(h);
            string type = $"{reader.GetString(t.Namespace)}.{reader.GetString(t.Name)}";
            contents.Add($"type {type} {t.Attributes}");
            contents.AddRange(t.GetFields().Select(f => $"  field {type}.{reader.GetString(reader.GetFieldDefinition(f).Name)}"));
            contents.AddRange(t.GetMethods().Select(m => $"  method {type}.{reader.GetString(reader.GetMethodDefinition(m).Name)}"));
            contents.AddRange(t.GetProperties().Select(p => $"  property {type}.{reader.GetString(reader.GetPropertyDefinition(p).Name)}"));
        }
        return contents;
    }
}
