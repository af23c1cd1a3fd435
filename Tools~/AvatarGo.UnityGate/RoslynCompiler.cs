using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.Emit;
using Microsoft.CodeAnalysis.Text;

namespace AvatarGo.UnityGate;

/// <summary>One compilation's outcome: the assembly image (when it compiled) and its errors.</summary>
public sealed class CompiledAssembly
{
    /// <summary>True when it compiled with no error.</summary>
    public bool Succeeded => Reference != null;

    /// <summary>The emitted assembly, or empty when it failed.</summary>
    public ImmutableArray<byte> Image { get; init; }

    /// <summary>A reference to the emitted image, for the compilations that reference it; null when it failed.</summary>
    public MetadataReference Reference { get; init; }

    /// <summary>Its errors, with package-relative files; <see cref="GateDiagnostic.Configuration"/> and <see cref="GateDiagnostic.Assembly"/> are empty.</summary>
    public IReadOnlyList<GateDiagnostic> Errors { get; init; }

    /// <summary>Wall-clock time the compilation took.</summary>
    public double Seconds { get; init; }
}

/// <summary>
/// Compiles one gate assembly in this process with Roslyn, as csc compiles the generated project: the same sources
/// (full paths), <see cref="CompilerSettings"/>, references in csc's order (.NET Standard 2.1 by file name, then the
/// others by file name, ignoring case) and csc's stages, so that it reports the same errors: parse errors stop it,
/// then declaration errors, then method bodies; documentation comments are diagnosed only when the method bodies
/// compiled (csc's CommonCompiler.CompileAndEmit; the Compilation.Emit API documents even after body errors).
/// </summary>
public static class RoslynCompiler
{
    /// <summary>Compiles <paramref name="assembly"/> against the .NET Standard 2.1 pack and the given references.</summary>
    /// <param name="packageRoot">The package its sources are in.</param>
    /// <param name="assembly">What to compile.</param>
    /// <param name="references">Its package and surface references, in any order (precompiled DLLs are added here).</param>
    public static CompiledAssembly Compile(string packageRoot, GateAssembly assembly, IEnumerable<(string FileName, MetadataReference Reference)> references)
    {
        var watch = Stopwatch.StartNew();
        AssemblyPlan plan = assembly.Plan;
        CompilerSettings settings = CompilerSettings.For(plan);
        CSharpParseOptions parseOptions = settings.ParseOptions();
        var trees = plan.Sources.Select(s => Parse(Path.GetFullPath(Path.Combine(packageRoot, s)), parseOptions)).ToList();
        var others = references.Concat(plan.PrecompiledReferences.Select(p => (Path.GetFileName(p), PrecompiledReferences.Get(p))))
            .OrderBy(r => r.Item1, StringComparer.OrdinalIgnoreCase).Select(r => r.Item2);
        CSharpCompilation compilation = CSharpCompilation.Create(plan.Name, trees, TargetingPack.NetStandard21.Concat(others), settings.CompilationOptions());

        ImmutableArray<Diagnostic> errors = Errors(compilation.GetParseDiagnostics());
        if (errors.IsEmpty) errors = Errors(compilation.GetDeclarationDiagnostics());
        ImmutableArray<byte> image = ImmutableArray<byte>.Empty;
        if (errors.IsEmpty)
        {
            using var pe = new MemoryStream();
            using MemoryStream xml = settings.Documentation ? new MemoryStream() : null;
            EmitResult emitted = compilation.Emit(pe, xmlDocumentationStream: xml);
            if (emitted.Success) image = ImmutableArray.Create(pe.ToArray());
            else if (settings.Documentation && MethodBodyErrors(compilation, parseOptions) is { IsEmpty: false } bodyErrors) errors = bodyErrors;
            else errors = Errors(emitted.Diagnostics);
        }
        string root = Path.GetFullPath(packageRoot).TrimEnd('/') + "/";
        return new CompiledAssembly
        {
            Image = image,
            Reference = image.IsEmpty ? null : MetadataReference.CreateFromImage(image, filePath: plan.Name + ".dll"),
            Errors = errors.Select(d => ToGateDiagnostic(d, root)).Distinct().ToList(),
            Seconds = watch.Elapsed.TotalSeconds,
        };
    }

    private static SyntaxTree Parse(string path, CSharpParseOptions options)
    {
        using FileStream stream = File.OpenRead(path);
        return CSharpSyntaxTree.ParseText(SourceText.From(stream), options, path);
    }

    private static ImmutableArray<Diagnostic> Errors(ImmutableArray<Diagnostic> diagnostics) =>
        diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error && !d.IsSuppressed).ToImmutableArray();

    // csc reports documentation-comment diagnostics only after the method bodies compiled; Emit reports them anyway.
    // The body errors alone are what the same compilation reports with documentation comments parsed but not diagnosed.
    private static ImmutableArray<Diagnostic> MethodBodyErrors(CSharpCompilation compilation, CSharpParseOptions parseOptions)
    {
        CSharpParseOptions quiet = parseOptions.WithDocumentationMode(DocumentationMode.Parse);
        var trees = compilation.SyntaxTrees.Select(t => CSharpSyntaxTree.ParseText(t.GetText(), quiet, t.FilePath));
        EmitResult bodies = compilation.RemoveAllSyntaxTrees().AddSyntaxTrees(trees).Emit(Stream.Null);
        return Errors(bodies.Diagnostics);
    }

    /// <summary>A compiler diagnostic as MSBuild's console shows it: mapped file and line, "CSC" when it has no location.</summary>
    private static GateDiagnostic ToGateDiagnostic(Diagnostic d, string packageRoot)
    {
        string file = "CSC";
        int line = 0;
        if (d.Location.IsInSource || d.Location.Kind == LocationKind.ExternalFile)
        {
            FileLinePositionSpan span = d.Location.GetMappedLineSpan();
            file = span.Path.StartsWith(packageRoot, StringComparison.Ordinal) ? span.Path.Substring(packageRoot.Length) : span.Path;
            line = span.StartLinePosition.Line + 1;
        }
        return new GateDiagnostic("", "", file, line, d.Id, d.GetMessage(CultureInfo.InvariantCulture).Trim());
    }
}

/// <summary>References to precompiled DLLs (NUnit from the NuGet cache), each loaded once per process.</summary>
public static class PrecompiledReferences
{
    private static readonly System.Collections.Concurrent.ConcurrentDictionary<string, MetadataReference> Loaded = new(StringComparer.Ordinal);

    /// <summary>The reference to the DLL at <paramref name="path"/>.</summary>
    public static MetadataReference Get(string path) => Loaded.GetOrAdd(path, p => MetadataReference.CreateFromFile(p));
}
