using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace AvatarGo.UnityGate;

/// <summary>A declaration of the surface: a type or a member, with where Unity declares it.</summary>
/// <param name="Id">The documentation-comment id (T:UnityEngine.Transform, P:UnityEngine.Transform.position, ...).</param>
/// <param name="Assembly">The surface assembly.</param>
/// <param name="Module">The module folder (CoreModule, AnimationModule, ...) or "" for assemblies without modules.</param>
/// <param name="File">The surface file, package-relative.</param>
/// <param name="Source">The Unity source it names (inherited from its type when the member names none).</param>
public sealed record SurfaceDeclaration(string Id, string Assembly, string Module, string File, string Source);

/// <summary>
/// Reads the surface's declarations and finds which of them the package's code references, with Roslyn's semantic
/// model over the same compilations the gate builds. Members are properties, methods, constructors, operators,
/// fields and events; enum values are part of their enum, and a type counts as used when the package names it, uses
/// one of its members, or derives from it through a used type. An operator C# only accepts in a pair (== and !=)
/// is used when its partner is.
/// </summary>
public static class SurfaceUsage
{
    /// <summary>The comment that names a declaration's source: "// Repo@ref path".</summary>
    public static readonly System.Text.RegularExpressions.Regex SourceComment =
        new(@"^//\s*(?<repo>UnityCsReference|com\.unity\.[a-z0-9.\-]+|steamvr_unity_plugin|unity-xr-plugin)@(?<ref>[\w.\-]+)\s+(?<path>\S+)\s*$",
            System.Text.RegularExpressions.RegexOptions.CultureInvariant);

    /// <summary>Every public type and member the surface declares, in any version flavour (both sides of every #if).</summary>
    public static List<SurfaceDeclaration> Declarations(string packageRoot, IEnumerable<UnityConfiguration> configurations)
    {
        var found = new Dictionary<string, SurfaceDeclaration>(StringComparer.Ordinal);
        string surfaceRoot = Path.Combine(packageRoot, "Tools~", "UnitySurface");
        foreach (UnityConfiguration config in configurations)
        {
            // Each surface is compiled against the ones it references (SteamVR's names Unity.XR.OpenVR's types), so that the
            // ids of members whose signatures name another surface's types resolve as in the package's compilations.
            var compiled = new Dictionary<string, CSharpCompilation>(StringComparer.Ordinal);
            foreach (SurfaceAssembly assembly in UnityCatalog.SurfaceAssemblies)
            {
                // As the surface is compiled in this configuration (its own versionDefines included), but always with
                // UNITY_EDITOR, so that the Editor-only declarations are seen too.
                var symbols = Planner.SurfaceDefines(assembly, config).Append("UNITY_EDITOR").ToArray();
                var options = new CSharpParseOptions(LanguageVersion.CSharp9, preprocessorSymbols: symbols);
                string dir = Path.Combine(surfaceRoot, assembly.Name);
                var trees = (Directory.Exists(dir) ? Directory.GetFiles(dir, "*.cs", SearchOption.AllDirectories) : Array.Empty<string>())
                    .OrderBy(f => f, StringComparer.Ordinal)
                    .Select(f => CSharpSyntaxTree.ParseText(File.ReadAllText(f), options, f)).ToList();
                var references = TargetingPack.NetStandard21.Concat(assembly.References
                    .Where(compiled.ContainsKey).Select(r => (MetadataReference)compiled[r].ToMetadataReference()));
                var compilation = CSharpCompilation.Create(assembly.Name, trees, references,
                    new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary));
                compiled[assembly.Name] = compilation;
                foreach (SyntaxTree tree in trees)
                {
                    SemanticModel model = compilation.GetSemanticModel(tree);
                    string rel = Path.GetRelativePath(packageRoot, tree.FilePath).Replace('\\', '/');
                    string[] parts = Path.GetRelativePath(dir, tree.FilePath).Replace('\\', '/').Split('/');
                    string module = parts.Length > 1 ? parts[0] : "";
                    foreach (MemberDeclarationSyntax node in tree.GetRoot().DescendantNodes().OfType<MemberDeclarationSyntax>())
                    {
                        if (node is BaseNamespaceDeclarationSyntax) continue;
                        ISymbol symbol = node is BaseFieldDeclarationSyntax field
                            ? model.GetDeclaredSymbol(field.Declaration.Variables[0])
                            : model.GetDeclaredSymbol(node);
                        if (symbol == null || symbol.DeclaredAccessibility != Accessibility.Public || symbol is IFieldSymbol { ContainingType.TypeKind: TypeKind.Enum })
                            continue;
                        IEnumerable<ISymbol> all = node is BaseFieldDeclarationSyntax f2
                            ? f2.Declaration.Variables.Select(v => model.GetDeclaredSymbol(v))
                            : new[] { symbol };
                        foreach (ISymbol s in all)
                        {
                            string id = s.GetDocumentationCommentId();
                            if (id != null && !found.ContainsKey(id))
                                found[id] = new SurfaceDeclaration(id, assembly.Name, module, rel, SourceOf(node));
                        }
                    }
                }
            }
        }
        return found.Values.OrderBy(d => d.Id, StringComparer.Ordinal).ToList();
    }

    /// <summary>The source comment in front of a declaration, or of the nearest type around it; null when none.</summary>
    public static string SourceOf(SyntaxNode node)
    {
        for (SyntaxNode n = node; n != null; n = n.Parent)
        {
            if (n is not MemberDeclarationSyntax) continue;
            foreach (SyntaxTrivia t in n.GetLeadingTrivia().Reverse())
                if (t.IsKind(SyntaxKind.SingleLineCommentTrivia) && SourceComment.IsMatch(t.ToString().Trim()))
                    return t.ToString().Trim().Substring(2).Trim();
        }
        return null;
    }

    /// <summary>
    /// The documentation-comment ids of surface declarations the package's code uses in the built configurations:
    /// each package assembly that references the surface is compiled again in memory (its sources, symbols and the
    /// gate's built references) and every name, operator, conversion and foreach in it is resolved.
    /// </summary>
    public static SortedSet<string> Used(GateResult built)
    {
        lock (UsedCache)
        {
            if (!UsedCache.TryGetValue(built, out SortedSet<string> known))
                UsedCache.Add(built, known = ComputeUsed(built));
            return new SortedSet<string>(known, StringComparer.Ordinal);
        }
    }

    private static readonly System.Runtime.CompilerServices.ConditionalWeakTable<GateResult, SortedSet<string>> UsedCache = new();

    private static SortedSet<string> ComputeUsed(GateResult built)
    {
        if (!built.Succeeded) throw new InvalidOperationException("the gate build failed: " + built.Describe());
        var used = new SortedSet<string>(StringComparer.Ordinal);
        var surfaceNames = new HashSet<string>(UnityCatalog.SurfaceAssemblies.Select(s => s.Name), StringComparer.Ordinal);
        var done = new HashSet<string>(StringComparer.Ordinal);
        string packageRoot = built.PackageRoot;
        foreach (ConfigurationPlan plan in built.Plans)
            foreach (AssemblyPlan a in plan.Assemblies.Where(a => a.Kind == PlanKind.Package && a.References.Any(surfaceNames.Contains)))
            {
                if (!done.Add(built.Projects.Graph.Of(plan.Configuration.Name, a.Name).Folder)) continue;
                var options = new CSharpParseOptions(LanguageVersion.CSharp9, preprocessorSymbols: a.Defines);
                var trees = a.Sources.Select(s => CSharpSyntaxTree.ParseText(File.ReadAllText(Path.Combine(packageRoot, s)), options, s)).ToList();
                var references = TargetingPack.NetStandard21
                    .Concat(a.References.Select(r => built.Built.Reference(built.Projects.Graph.Of(plan.Configuration.Name, r))))
                    .Concat(a.PrecompiledReferences.Select(p => MetadataReference.CreateFromFile(p)));
                var compilation = CSharpCompilation.Create(a.Name, trees, references,
                    new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, allowUnsafe: a.AllowUnsafeCode));
                foreach (SyntaxTree tree in trees)
                {
                    SemanticModel model = compilation.GetSemanticModel(tree);
                    foreach (SyntaxNode node in tree.GetRoot().DescendantNodes())
                    {
                        SymbolInfo info = model.GetSymbolInfo(node);
                        Add(info.Symbol);
                        foreach (ISymbol c in info.CandidateSymbols) Add(c);
                        if (node is ExpressionSyntax e) Add(model.GetConversion(e).MethodSymbol);
                        if (node is CommonForEachStatementSyntax fe)
                        {
                            ForEachStatementInfo fi = model.GetForEachStatementInfo(fe);
                            Add(fi.GetEnumeratorMethod);
                            Add(fi.MoveNextMethod);
                            Add(fi.CurrentProperty);
                        }
                        // An override needs the virtual member it overrides (an Editor's OnInspectorGUI).
                        if (node is MethodDeclarationSyntax or PropertyDeclarationSyntax or EventDeclarationSyntax)
                            switch (model.GetDeclaredSymbol(node))
                            {
                                case IMethodSymbol { OverriddenMethod: not null } om: Add(om.OverriddenMethod); break;
                                case IPropertySymbol { OverriddenProperty: not null } op: Add(op.OverriddenProperty); break;
                                case IEventSymbol { OverriddenEvent: not null } oe: Add(oe.OverriddenEvent); break;
                            }
                        if (node is BaseTypeDeclarationSyntax or DelegateDeclarationSyntax)
                            for (ITypeSymbol t = (model.GetDeclaredSymbol(node) as INamedTypeSymbol)?.BaseType; t != null; t = t.BaseType) Add(t);
                    }
                }
            }
        return used;

        void Add(ISymbol s)
        {
            if (s == null) return;
            if (s is IMethodSymbol { ReducedFrom: not null } reduced) s = reduced.ReducedFrom;
            if (s is IMethodSymbol { AssociatedSymbol: IPropertySymbol or IEventSymbol } accessor) s = accessor.AssociatedSymbol;
            s = s.OriginalDefinition;
            if (s.ContainingAssembly == null || !surfaceNames.Contains(s.ContainingAssembly.Name)) return;
            if (s is IFieldSymbol { ContainingType.TypeKind: TypeKind.Enum } enumValue) s = enumValue.ContainingType;
            string id = s.GetDocumentationCommentId();
            if (id != null) used.Add(id);
            // The types a used member's signature names exist with it (CommonUsages.devicePosition is an InputFeatureUsage<Vector3>).
            switch (s)
            {
                case IMethodSymbol m:
                    AddType(m.ReturnType);
                    foreach (IParameterSymbol p in m.Parameters) AddType(p.Type);
                    break;
                case IPropertySymbol p:
                    AddType(p.Type);
                    foreach (IParameterSymbol ip in p.Parameters) AddType(ip.Type);
                    break;
                case IFieldSymbol f:
                    AddType(f.Type);
                    break;
                case IEventSymbol e:
                    AddType(e.Type);
                    break;
            }
            // C# only accepts some operators in pairs (CS0216): using one keeps its partner.
            if (s is IMethodSymbol { MethodKind: MethodKind.UserDefinedOperator } op && PairedOperators.TryGetValue(op.Name, out string partner))
                foreach (ISymbol p in op.ContainingType.GetMembers(partner))
                    if (p.GetDocumentationCommentId() is string pid) used.Add(pid);
            for (INamedTypeSymbol t = s as INamedTypeSymbol ?? s.ContainingType; t != null; t = t.ContainingType ?? t.BaseType)
            {
                if (t.ContainingAssembly != null && surfaceNames.Contains(t.ContainingAssembly.Name)) used.Add(t.OriginalDefinition.GetDocumentationCommentId());
                // A base type's type arguments are part of it (SteamVR_Action_Pose's base names its source-map types).
                foreach (ITypeSymbol arg in t.TypeArguments) AddType(arg);
            }
        }

        // A type (and its type arguments, element type, containing types) that belongs to the surface.
        void AddType(ITypeSymbol type)
        {
            switch (type)
            {
                case IArrayTypeSymbol array:
                    AddType(array.ElementType);
                    return;
                case INamedTypeSymbol named:
                    foreach (ITypeSymbol arg in named.TypeArguments) AddType(arg);
                    // Its containing and base types too: a type cannot be declared without them (Material's base, Object).
                    for (INamedTypeSymbol t = named.OriginalDefinition; t != null; t = t.ContainingType ?? t.BaseType)
                        if (t.ContainingAssembly != null && surfaceNames.Contains(t.ContainingAssembly.Name)) used.Add(t.OriginalDefinition.GetDocumentationCommentId());
                    return;
            }
        }
    }


    private static readonly Dictionary<string, string> PairedOperators = new(StringComparer.Ordinal)
    {
        ["op_Equality"] = "op_Inequality", ["op_Inequality"] = "op_Equality",
        ["op_LessThan"] = "op_GreaterThan", ["op_GreaterThan"] = "op_LessThan",
        ["op_LessThanOrEqual"] = "op_GreaterThanOrEqual", ["op_GreaterThanOrEqual"] = "op_LessThanOrEqual",
        ["op_True"] = "op_False", ["op_False"] = "op_True",
    };
}
