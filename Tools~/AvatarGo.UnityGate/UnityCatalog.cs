using System;
using System.Collections.Generic;
using System.Linq;

namespace AvatarGo.UnityGate;

/// <summary>
/// A Unity assembly the package may reference, declared compile-only in Tools~/UnitySurface/&lt;Name&gt;/.
/// </summary>
/// <param name="Name">The real assembly name (what an asmdef writes in "references").</param>
/// <param name="Package">The package that provides it, or null for the engine's own assemblies.</param>
/// <param name="EditorOnly">True when it exists only in the Editor (never in a player).</param>
/// <param name="References">Other surface assemblies it references.</param>
/// <param name="UsesNUnit">True when it references nunit.framework.dll (the Test Framework's assemblies).</param>
/// <param name="Source">Where its asmdef (or, for engine assemblies, its definition) was read.</param>
public sealed record SurfaceAssembly(string Name, string Package, bool EditorOnly, IReadOnlyList<string> References, bool UsesNUnit, string Source);

/// <summary>What the gate knows about Unity beyond the package: surface assemblies, optional packages, release series.</summary>
public static class UnityCatalog
{
    /// <summary>The package that provides nunit.framework.dll (a dependency of com.unity.test-framework).</summary>
    public const string NUnitPackage = "com.unity.ext.nunit";

    /// <summary>The precompiled DLL test assemblies name in precompiledReferences.</summary>
    public const string NUnitDll = "nunit.framework.dll";

    /// <summary>The NuGet NUnit version standing in for Unity's fork of NUnit 3.5: the oldest 3.x the mirror serves.</summary>
    public const string NUnitNuGetVersion = "3.6.0";

    /// <summary>Every Unity assembly there is a surface for.</summary>
    public static IReadOnlyList<SurfaceAssembly> SurfaceAssemblies { get; } = new[]
    {
        new SurfaceAssembly("UnityEngine", null, false, Array.Empty<string>(), false,
            "the engine's runtime API (UnityEngine.CoreModule and the other UnityEngine.*Module assemblies, merged)"),
        new SurfaceAssembly("UnityEditor", null, true, new[] { "UnityEngine" }, false,
            "the Editor API (UnityEditor.dll and UnityEditor.*Module)"),
        new SurfaceAssembly("UnityEngine.TestRunner", "com.unity.test-framework", false, new[] { "UnityEngine" }, true,
            "com.unity.test-framework@1.1.33 UnityEngine.TestRunner/UnityEngine.TestRunner.asmdef (overrideReferences, nunit.framework.dll)"),
        new SurfaceAssembly("UnityEditor.TestRunner", "com.unity.test-framework", true, new[] { "UnityEngine", "UnityEditor", "UnityEngine.TestRunner" }, true,
            "com.unity.test-framework@1.1.33 UnityEditor.TestRunner/UnityEditor.TestRunner.asmdef (includePlatforms Editor)"),
    };

    /// <summary>The surface assembly with this name, or null.</summary>
    public static SurfaceAssembly Surface(string name) => SurfaceAssemblies.FirstOrDefault(s => s.Name == name);

    /// <summary>
    /// The optional packages an "everything installed" project holds, at the versions that editor ships with or
    /// resolves: Test Framework 1.1.33 (the released version for 2021.3) with ext.nunit 1.0.6 (its dependency);
    /// in 6000.x the Test Framework is a core package fixed to the editor (1.4.6 and ext.nunit 2.0.5 stand in).
    /// </summary>
    public static IReadOnlyDictionary<string, string> OptionalPackages(UnityVersion unity) =>
        unity.Major >= 6000
            ? new Dictionary<string, string> { ["com.unity.test-framework"] = "1.4.6", [NUnitPackage] = "2.0.5" }
            : new Dictionary<string, string> { ["com.unity.test-framework"] = "1.1.33", [NUnitPackage] = "1.0.6" };

    /// <summary>
    /// The NUnit build folder matching Unity's: ext.nunit 1.0.x ships a net35 build, 2.0.x a net40 build
    /// (needle-mirror/com.unity.ext.nunit tags 1.0.6 and 2.0.3).
    /// </summary>
    public static string NUnitFramework(string extNUnitVersion) =>
        extNUnitVersion.StartsWith("1.", StringComparison.Ordinal) ? "net35" : "net40";

    /// <summary>Release series in order, for UNITY_X_Y_OR_NEWER (2023.3 shipped as 6000.0).</summary>
    public static IReadOnlyList<(int Major, int Minor)> ReleaseSeries { get; } = new (int, int)[]
    {
        (5, 3), (5, 4), (5, 5), (5, 6), (2017, 1), (2017, 2), (2017, 3), (2017, 4), (2018, 1), (2018, 2), (2018, 3), (2018, 4),
        (2019, 1), (2019, 2), (2019, 3), (2019, 4), (2020, 1), (2020, 2), (2020, 3), (2021, 1), (2021, 2), (2021, 3),
        (2022, 1), (2022, 2), (2022, 3), (2023, 1), (2023, 2), (2023, 3), (6000, 0), (6000, 1), (6000, 2), (6000, 3), (6000, 4), (6000, 5),
    };
}
