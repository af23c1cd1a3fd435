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
public sealed record SurfaceAssembly(string Name, string Package, bool EditorOnly, IReadOnlyList<string> References, bool UsesNUnit, string Source)
{
    /// <summary>
    /// True for an assembly a plug-in imported into the project's Assets folder provides (the SteamVR Unity Plugin): it
    /// exists only in a configuration that lists it in <see cref="UnityConfiguration.AssetsAssemblies"/>, as Unity's
    /// versionDefines cannot see it.
    /// </summary>
    public bool ImportedIntoAssets { get; init; }

    /// <summary>
    /// The versionDefines of the real assembly's own asmdef that change its API (SteamVR.asmdef's OPENVR_XR_API), plus
    /// symbols naming package versions from which the surface declares a member (OPENXR_1_9_OR_NEWER): the surface
    /// sees them as Unity compiles the real assembly, so a member that exists only in some versions is declared under
    /// its symbol.
    /// </summary>
    public IReadOnlyList<VersionDefine> VersionDefines { get; init; } = Array.Empty<VersionDefine>();
}

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
        new SurfaceAssembly("Unity.InputSystem", "com.unity.inputsystem", false, new[] { "UnityEngine" }, false,
            "com.unity.inputsystem@1.0.2 InputSystem/Unity.InputSystem.asmdef (its XR types compile with com.unity.modules.xr, which AvatarGo depends on)")
        {
            VersionDefines = new[] { new VersionDefine("com.unity.inputsystem", "1.1.1", "INPUT_SYSTEM_1_1_OR_NEWER") },
        },
        new SurfaceAssembly("Unity.XR.OpenXR", "com.unity.xr.openxr", false, new[] { "UnityEngine", "Unity.InputSystem" }, false,
            "com.unity.xr.openxr@1.0.2 Runtime/Unity.XR.OpenXR.asmdef (its OpenXRFeatureAttribute compiles in the Editor only)")
        {
            VersionDefines = new[] { new VersionDefine("com.unity.xr.openxr", "1.9.1", "OPENXR_1_9_OR_NEWER") },
        },
        new SurfaceAssembly("Unity.XR.CoreUtils", "com.unity.xr.core-utils", false, new[] { "UnityEngine" }, false,
            "com.unity.xr.core-utils@2.0.0 Runtime/Unity.XR.CoreUtils.asmdef"),
        new SurfaceAssembly("Unity.XR.Interaction.Toolkit", "com.unity.xr.interaction.toolkit", false, new[] { "UnityEngine", "Unity.InputSystem", "Unity.XR.CoreUtils" }, false,
            "com.unity.xr.interaction.toolkit@2.0.0 Runtime/Unity.XR.Interaction.Toolkit.asmdef")
        {
            VersionDefines = new[]
            {
                new VersionDefine("com.unity.xr.interaction.toolkit", "2.4.0", "XRI_2_4_OR_NEWER"),
                new VersionDefine("com.unity.xr.interaction.toolkit", "3.0.0", "XRI_3_OR_NEWER"),
            },
        },
        new SurfaceAssembly("Unity.XR.OpenVR", "com.valvesoftware.unity.openvr", false, new[] { "UnityEngine" }, false,
            "unity-xr-plugin@v1.1.4 com.valve.openvr/Runtime/Unity.XR.OpenVR.asmdef (the OpenVR XR plug-in; holds openvr_api.cs's Valve.VR types)"),
        new SurfaceAssembly("SteamVR", null, false, new[] { "UnityEngine", "Unity.XR.OpenVR" }, false,
            "steamvr_unity_plugin@2.7.3 Assets/SteamVR/SteamVR.asmdef (imported into Assets; its openvr_api.cs compiles only without OPENVR_XR_API)")
        {
            ImportedIntoAssets = true,
            VersionDefines = new[] { new VersionDefine("com.valvesoftware.unity.openvr", "", "OPENVR_XR_API") },
        },
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
            ? new Dictionary<string, string>
            {
                ["com.unity.test-framework"] = "1.4.6", [NUnitPackage] = "2.0.5",
                // The newest releases in the mirrors the surface was checked against (XRI 3.5 and later require Unity 6000.0).
                ["com.unity.inputsystem"] = "1.14.0", ["com.unity.xr.openxr"] = "1.17.1", ["com.unity.xr.core-utils"] = "2.5.3",
                ["com.unity.xr.interaction.toolkit"] = "3.5.1", ["com.valvesoftware.unity.openvr"] = "1.2.4",
            }
            : new Dictionary<string, string>
            {
                ["com.unity.test-framework"] = "1.1.33", [NUnitPackage] = "1.0.6",
                // The oldest versions AvatarGo's asmdefs accept that resolve together: XRI 2.0.0 needs inputsystem 1.2.0 and
                // core-utils 2.0.0; OpenXR 1.0.2 needs inputsystem 1.0.2; the OpenVR XR plug-in 1.1.4 is the one SteamVR 2.7.3 bundles.
                ["com.unity.inputsystem"] = "1.2.0", ["com.unity.xr.openxr"] = "1.0.2", ["com.unity.xr.core-utils"] = "2.0.0",
                ["com.unity.xr.interaction.toolkit"] = "2.0.0", ["com.valvesoftware.unity.openvr"] = "1.1.4",
            };

    /// <summary>What "every optional package" also holds outside Packages/: the SteamVR Unity Plugin in Assets, and the define that enables AvatarGo's SteamVR source.</summary>
    public static IReadOnlyList<string> OptionalAssetsAssemblies { get; } = new[] { "SteamVR" };

    /// <summary>The Player Settings scripting define that enables AvatarGo's SteamVR assembly (Documentation~/tracking-sources.md).</summary>
    public const string SteamVRDefine = "AVATARGO_STEAMVR";

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
