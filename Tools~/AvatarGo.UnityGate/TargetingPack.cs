using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using Microsoft.CodeAnalysis;

namespace AvatarGo.UnityGate;

/// <summary>
/// The .NET Standard 2.1 reference assemblies (NETStandard.Library.Ref 2.1.0), found where the .NET SDK's
/// ResolveTargetingPackAssets finds them for a netstandard2.1 project: in the packs folder of the running dotnet
/// installation, or else in the NuGet packages folder the gate was restored with (the SDK downloads the pack there
/// when the installation lacks it, as on this project's machines). Every DLL of the pack's ref folder is referenced,
/// as the generated projects' csc command lines show. Loaded once per process.
/// </summary>
public static class TargetingPack
{
    private const string Pack = "NETStandard.Library.Ref", Version = "2.1.0";

    private static readonly Lazy<IReadOnlyList<MetadataReference>> Loaded = new(Load);

    /// <summary>The reference assemblies, in the order csc receives them (by file name, ignoring case).</summary>
    public static IReadOnlyList<MetadataReference> NetStandard21 => Loaded.Value;

    /// <summary>The folder holding the reference DLLs.</summary>
    public static string Folder()
    {
        var candidates = new List<string>();
        if (DotnetRoot() is string root) candidates.Add(Path.Combine(root, "packs", Pack, Version, "ref", "netstandard2.1"));
        candidates.Add(Path.Combine(Program.NuGetPackageRoot, Pack.ToLowerInvariant(), Version, "ref", "netstandard2.1"));
        return candidates.FirstOrDefault(d => File.Exists(Path.Combine(d, "netstandard.dll")))
               ?? throw new GateException($"no {Pack} {Version} in {string.Join(" or ", candidates)} (restore Tools~/AvatarGo.slnx)");
    }

    /// <summary>The dotnet installation this process runs on: the runtime lives in &lt;root&gt;/shared/Microsoft.NETCore.App/&lt;version&gt;/.</summary>
    public static string DotnetRoot()
    {
        var runtime = new DirectoryInfo(RuntimeEnvironment.GetRuntimeDirectory().TrimEnd(Path.DirectorySeparatorChar));
        return runtime.Parent?.Parent?.Parent?.FullName;
    }

    private static IReadOnlyList<MetadataReference> Load() =>
        Directory.GetFiles(Folder(), "*.dll")
            .OrderBy(Path.GetFileName, StringComparer.OrdinalIgnoreCase)
            .Select(f => (MetadataReference)MetadataReference.CreateFromFile(f))
            .ToList();
}
