using System;
using System.Collections.Generic;
using System.Linq;

namespace AvatarGo.UnityGate;

/// <summary>
/// One setup a user of the package can have: an editor version, Editor or player build, and which optional packages
/// the project holds. Gives the scripting symbols Unity defines for it.
/// </summary>
/// <param name="Name">Short name used for folders and messages, e.g. "editor-2021.3".</param>
/// <param name="Unity">The editor version, e.g. 2021.3.0f1.</param>
/// <param name="Editor">True for the Editor's own compile (UNITY_EDITOR, UnityEditor referenced everywhere); false for a player build.</param>
/// <param name="PlayerPlatform">The build target's asmdef platform name ("WindowsStandalone64"); also the Editor's active target.</param>
/// <param name="Packages">Optional packages present (name to version); built-in modules (com.unity.modules.*) are always present.</param>
/// <param name="IncludeTestAssemblies">For a player build: true when it is built with test assemblies (BuildOptions.IncludeTestAssemblies).</param>
/// <param name="Description">What a reader should know about this configuration.</param>
public sealed record UnityConfiguration(
    string Name,
    UnityVersion Unity,
    bool Editor,
    string PlayerPlatform,
    IReadOnlyDictionary<string, string> Packages,
    bool IncludeTestAssemblies,
    string Description)
{
    /// <summary>Assemblies of plug-ins imported into Assets (the SteamVR Unity Plugin: "SteamVR"), which versionDefines cannot detect.</summary>
    public IReadOnlyList<string> AssetsAssemblies { get; init; } = Array.Empty<string>();

    /// <summary>Scripting define symbols set in Player Settings (AVATARGO_STEAMVR), defined for every assembly.</summary>
    public IReadOnlyList<string> ScriptingDefines { get; init; } = Array.Empty<string>();

    /// <summary>The oldest editor the package supports ("unity": "2021.3" in package.json, no unityRelease).</summary>
    public static readonly UnityVersion Oldest = UnityVersion.Parse("2021.3.0f1");

    /// <summary>The current editor the gate also compiles for: the newest release (f) tag in UnityCsReference when the surface was checked.</summary>
    public static readonly UnityVersion Current = UnityVersion.Parse("6000.5.2f1");

    /// <summary>The configurations CI compiles (see Documentation~/building.md).</summary>
    public static IReadOnlyList<UnityConfiguration> Standard { get; } = new[]
    {
        new UnityConfiguration("editor-2021.3", Oldest, true, "WindowsStandalone64", UnityCatalog.OptionalPackages(Oldest), false,
            "Unity 2021.3.0f1 Editor with every optional package the package knows, at the oldest versions it accepts (Test Framework, Input System, OpenXR, XR Core Utilities, XR Interaction Toolkit 2.x, OpenVR XR plug-in; the SteamVR plug-in in Assets with AVATARGO_STEAMVR)")
            { AssetsAssemblies = UnityCatalog.OptionalAssetsAssemblies, ScriptingDefines = new[] { UnityCatalog.SteamVRDefine } },
        new UnityConfiguration("editor-2021.3-bare", Oldest, true, "WindowsStandalone64", new Dictionary<string, string>(), false,
            "Unity 2021.3.0f1 Editor with no optional package, only the built-in modules: test and integration assemblies are skipped by their defineConstraints"),
        new UnityConfiguration("editor-2021.3-partial", Oldest, true, "WindowsStandalone64",
            new Dictionary<string, string> { ["com.unity.xr.core-utils"] = "2.0.0" }, false,
            "Unity 2021.3.0f1 Editor with XR Core Utilities alone (an XR Origin without the XR Interaction Toolkit or the Input System) and the SteamVR plug-in in Assets without the OpenVR XR plug-in: the integrations compile without the packages they only use when present")
            { AssetsAssemblies = UnityCatalog.OptionalAssetsAssemblies, ScriptingDefines = new[] { UnityCatalog.SteamVRDefine } },
        new UnityConfiguration("player-2021.3", Oldest, false, "WindowsStandalone64", UnityCatalog.OptionalPackages(Oldest), false,
            "Unity 2021.3.0f1 Windows 64-bit player build: runtime assemblies without UNITY_EDITOR and without the UnityEditor surface")
            { AssetsAssemblies = UnityCatalog.OptionalAssetsAssemblies, ScriptingDefines = new[] { UnityCatalog.SteamVRDefine } },
        new UnityConfiguration("editor-6000.5", Current, true, "WindowsStandalone64", UnityCatalog.OptionalPackages(Current), false,
            "Unity 6000.5.2f1 Editor with every optional package at its newest version (XR Interaction Toolkit 3.x; the 6000.x surface: obsolete-as-error members)")
            { AssetsAssemblies = UnityCatalog.OptionalAssetsAssemblies, ScriptingDefines = new[] { UnityCatalog.SteamVRDefine } },
        new UnityConfiguration("player-6000.5", Current, false, "WindowsStandalone64", UnityCatalog.OptionalPackages(Current), false,
            "Unity 6000.5.2f1 Windows 64-bit player build")
            { AssetsAssemblies = UnityCatalog.OptionalAssetsAssemblies, ScriptingDefines = new[] { UnityCatalog.SteamVRDefine } },
    };

    /// <summary>The configuration of <see cref="Standard"/> with this name.</summary>
    public static UnityConfiguration Named(string name) =>
        Standard.FirstOrDefault(c => c.Name == name) ?? throw new ArgumentException($"no configuration '{name}'; known: {string.Join(", ", Standard.Select(c => c.Name))}");

    /// <summary>True when the package (or built-in module) is in the project.</summary>
    public bool HasPackage(string name) => name.StartsWith("com.unity.modules.", StringComparison.Ordinal) || Packages.ContainsKey(name);

    /// <summary>The version of a present package ("1.0.0" for built-in modules), or null.</summary>
    public string PackageVersion(string name) =>
        Packages.TryGetValue(name, out string v) ? v : name.StartsWith("com.unity.modules.", StringComparison.Ordinal) ? "1.0.0" : null;

    /// <summary>
    /// The symbols Unity defines for an assembly in this configuration, before its versionDefines. The sources:
    /// CSHARP_7_3_OR_NEWER and CSHARP_7_OR_LATER are added to every assembly in UnityCsReference@2021.3
    /// Editor/Mono/Scripting/ScriptCompilation/EditorBuildRules.cs; editor-only assemblies get the defines of the
    /// .NET Framework 4.8 API level, the others those of .NET Standard 2.1 (EditorCompilation.GetTargetAssemblyDefines).
    /// The rest is native (InternalEditorUtility.GetCompilationDefines): the names follow Unity's "scripting symbol
    /// reference" manual page, for a Windows editor with the Mono backend and a Windows 64-bit standalone target, and
    /// UNITY_INCLUDE_TESTS is defined when the Test Framework is present in the Editor, or in a player built with test
    /// assemblies (shared/unity/engine-api.md §5.3). Not verifiable from C# sources.
    /// </summary>
    public SortedSet<string> Defines(bool editorOnlyAssembly)
    {
        var d = new SortedSet<string>(StringComparer.Ordinal) { "CSHARP_7_3_OR_NEWER", "CSHARP_7_OR_LATER", "ENABLE_VR" };
        foreach (string v in VersionSymbols(Unity)) d.Add(v);
        d.UnionWith(new[] { "UNITY_STANDALONE", "UNITY_STANDALONE_WIN", "PLATFORM_STANDALONE", "PLATFORM_STANDALONE_WIN", "UNITY_64" });
        if (Editor)
        {
            d.UnionWith(new[] { "UNITY_EDITOR", "UNITY_EDITOR_64", "UNITY_EDITOR_WIN", "UNITY_ASSERTIONS", "DEBUG", "TRACE", "ENABLE_MONO" });
            if (HasPackage("com.unity.test-framework")) d.Add("UNITY_INCLUDE_TESTS");
        }
        else
        {
            d.Add("ENABLE_IL2CPP");
            if (IncludeTestAssemblies) d.Add("UNITY_INCLUDE_TESTS");
        }
        d.UnionWith(ScriptingDefines);
        if (editorOnlyAssembly) d.UnionWith(new[] { "NET_4_6", "NET_UNITY_4_8" });
        else d.UnionWith(new[] { "NET_STANDARD", "NET_STANDARD_2_0", "NET_STANDARD_2_1", "NETSTANDARD", "NETSTANDARD2_1" });
        return d;
    }

    /// <summary>UNITY_X_Y_OR_NEWER for every release series up to the version, plus UNITY_X, UNITY_X_Y and UNITY_X_Y_Z.</summary>
    public static IEnumerable<string> VersionSymbols(UnityVersion v)
    {
        foreach ((int major, int minor) in UnityCatalog.ReleaseSeries)
            if (major < v.Major || (major == v.Major && minor <= v.Minor))
                yield return $"UNITY_{major}_{minor}_OR_NEWER";
        yield return $"UNITY_{v.Major}";
        yield return $"UNITY_{v.Major}_{v.Minor}";
        yield return $"UNITY_{v.Major}_{v.Minor}_{v.Revision}";
    }

    /// <inheritdoc />
    public override string ToString() => Name;
}
