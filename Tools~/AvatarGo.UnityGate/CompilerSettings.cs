using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace AvatarGo.UnityGate;

/// <summary>
/// The compiler settings of one planned assembly, in one place for both ways the gate compiles: the generated MSBuild
/// project writes them as properties (<see cref="ProjectWriter"/>), the in-process compiler turns them into Roslyn
/// options (<see cref="RoslynCompiler"/>). Each property below names the csc switch MSBuild passes for it, as read
/// from a generated project's command line (dotnet build -v:n) with the .NET 10 SDK.
/// </summary>
public sealed class CompilerSettings
{
    /// <summary>The C# version Unity 2021.3 compiles with (and later editors accept): /langversion:9.0.</summary>
    public const string LangVersion = "9.0";

    /// <summary>
    /// Warnings never reported (/nowarn): 1701 and 1702 are assembly-version unification notes the SDK silences in
    /// every project; 2008 ("no source files") is the command-line warning of a surface with no declaration yet.
    /// </summary>
    public IReadOnlyList<int> NoWarn { get; private init; }

    /// <summary>Scripting symbols, exactly the plan's (/define); the SDK's implicit ones (RELEASE, NETSTANDARD2_1_OR_GREATER, ...) are switched off.</summary>
    public IReadOnlyList<string> Defines { get; private init; }

    /// <summary>Unsafe code allowed (/unsafe).</summary>
    public bool AllowUnsafe { get; private init; }

    /// <summary>
    /// XML documentation generated (/doc), which also makes the compiler diagnose documentation comments, missing ones
    /// included (CS1591). Without it the compiler treats /// comments as plain comments.
    /// </summary>
    public bool Documentation { get; private init; }

    /// <summary>The settings Unity's compile of the planned assembly corresponds to.</summary>
    public static CompilerSettings For(AssemblyPlan a) => new()
    {
        NoWarn = a.Sources.Count == 0 ? new[] { 1701, 1702, 2008 } : new[] { 1701, 1702 },
        Defines = a.Defines,
        AllowUnsafe = a.AllowUnsafeCode,
        Documentation = a.RequireDocs,
    };

    /// <summary>The MSBuild properties, in the order the generated project lists them.</summary>
    public IEnumerable<(string Name, string Value)> MSBuildProperties()
    {
        yield return ("TargetFramework", "netstandard2.1");
        yield return ("LangVersion", LangVersion);
        yield return ("DefineConstants", string.Join(";", Defines));
        // Unity defines no RELEASE/DEBUG for the configuration nor NETSTANDARD2_1_OR_GREATER and the like.
        yield return ("DisableImplicitConfigurationDefines", "true");
        yield return ("DisableImplicitFrameworkDefines", "true");
        // /warnaserror+: every warning (obsolete API, CS0612/CS0618, included) is an error; CS0619 is one anyway.
        yield return ("TreatWarningsAsErrors", "true");
        yield return ("NoWarn", string.Join(";", NoWarn));
        yield return ("AllowUnsafeBlocks", AllowUnsafe ? "true" : "false");
        yield return ("GenerateDocumentationFile", Documentation ? "true" : "false");
        yield return ("Nullable", "disable");
        yield return ("ImplicitUsings", "disable");
        yield return ("Deterministic", "true");
        yield return ("Optimize", "false");
    }

    /// <summary>Parse options: C# 9, the symbols, and documentation comments diagnosed only with /doc.</summary>
    public CSharpParseOptions ParseOptions() =>
        new(LanguageVersion.CSharp9, Documentation ? DocumentationMode.Diagnose : DocumentationMode.None, SourceCodeKind.Regular, Defines);

    /// <summary>
    /// Compilation options as csc builds them from the generated project's switches: a library, /optimize-,
    /// /checked-, /deterministic+, /nullable:disable, warning level 4 (no /warn), /warnaserror+ with the /nowarn list
    /// suppressed, and the desktop assembly identity comparer csc uses (it unifies the framework versions NUnit's
    /// net35 build refers to, reported as the silenced CS1701).
    /// </summary>
    public CSharpCompilationOptions CompilationOptions() =>
        new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary,
                optimizationLevel: OptimizationLevel.Debug,
                checkOverflow: false,
                allowUnsafe: AllowUnsafe,
                deterministic: true,
                warningLevel: 4,
                generalDiagnosticOption: ReportDiagnostic.Error,
                specificDiagnosticOptions: NoWarn.Select(n => new KeyValuePair<string, ReportDiagnostic>($"CS{n:0000}", ReportDiagnostic.Suppress)),
                nullableContextOptions: NullableContextOptions.Disable)
            .WithAssemblyIdentityComparer(DesktopAssemblyIdentityComparer.Default);
}
