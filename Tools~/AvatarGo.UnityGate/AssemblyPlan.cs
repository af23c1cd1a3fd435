using System.Collections.Generic;

namespace AvatarGo.UnityGate;

/// <summary>The kind of assembly a generated project builds.</summary>
public enum PlanKind
{
    /// <summary>An assembly of the package, from its asmdef.</summary>
    Package,

    /// <summary>A compile-only Unity assembly from Tools~/UnitySurface.</summary>
    Surface,
}

/// <summary>
/// One assembly as Unity would compile it in one configuration: what the generated MSBuild project holds.
/// </summary>
public sealed class AssemblyPlan
{
    /// <summary>The assembly name.</summary>
    public string Name { get; init; }

    /// <summary>Package or surface assembly.</summary>
    public PlanKind Kind { get; init; }

    /// <summary>The asmdef it comes from (package-relative), or the surface folder.</summary>
    public string Origin { get; init; }

    /// <summary>Source files, package-relative with '/'.</summary>
    public IReadOnlyList<string> Sources { get; init; }

    /// <summary>Scripting symbols, sorted.</summary>
    public IReadOnlyList<string> Defines { get; init; }

    /// <summary>Assemblies of this configuration it references (package or surface), by name.</summary>
    public IReadOnlyList<string> References { get; init; }

    /// <summary>Precompiled DLLs it references, as absolute paths.</summary>
    public IReadOnlyList<string> PrecompiledReferences { get; init; }

    /// <summary>True when unsafe code is allowed.</summary>
    public bool AllowUnsafeCode { get; init; }

    /// <summary>True when public API without XML docs is an error (package assemblies that are not tests).</summary>
    public bool RequireDocs { get; init; }

    /// <summary>True for an Editor-only assembly.</summary>
    public bool EditorOnly { get; init; }

    /// <summary>How the configuration's reasoning reached this plan, for the project's header comment and reports.</summary>
    public IReadOnlyList<string> Notes { get; init; }
}

/// <summary>An asmdef Unity would not compile in a configuration, and why.</summary>
/// <param name="Name">The assembly name.</param>
/// <param name="Asmdef">The asmdef path.</param>
/// <param name="Reason">Why it is skipped (no scripts, platform, define constraint, test assembly in a player).</param>
public sealed record SkippedAssembly(string Name, string Asmdef, string Reason);

/// <summary>Everything one configuration compiles, in dependency order, and what it skips.</summary>
/// <param name="Configuration">The configuration.</param>
/// <param name="Assemblies">Surface and package assemblies, each after the ones it references.</param>
/// <param name="Skipped">Package asmdefs not compiled here.</param>
public sealed record ConfigurationPlan(UnityConfiguration Configuration, IReadOnlyList<AssemblyPlan> Assemblies, IReadOnlyList<SkippedAssembly> Skipped);
