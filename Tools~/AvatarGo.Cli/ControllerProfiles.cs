using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using AvatarGo.Core;

namespace AvatarGo.Cli;

/// <summary>The controller profiles the package ships (Runtime/ControllerProfiles/*.json), found above the tool's folder.</summary>
internal static class ControllerProfiles
{
    /// <summary>The profile simulate, evaluate, demo and bench use unless told otherwise.</summary>
    public const string Default = "vive-wand";

    /// <summary>The folder of the package's profiles.</summary>
    public static string Folder()
    {
        for (string dir = AppContext.BaseDirectory; dir != null; dir = Path.GetDirectoryName(dir))
        {
            string candidate = Path.Combine(dir, "Runtime", "ControllerProfiles");
            if (Directory.Exists(candidate)) return candidate;
        }
        throw new DirectoryNotFoundException("Runtime/ControllerProfiles not found above the tool's folder");
    }

    /// <summary>Every profile, by file name.</summary>
    public static IReadOnlyList<ControllerProfile> All() =>
        Directory.GetFiles(Folder(), "*.json").OrderBy(f => f, StringComparer.Ordinal).Select(f => ControllerProfile.Load(f)).ToList();

    /// <summary>The profile named <paramref name="name"/> (file name without .json), or null for "none".</summary>
    /// <exception cref="UsageException">No such profile.</exception>
    public static ControllerProfile Named(string name)
    {
        if (name == "none") return null;
        string path = Path.Combine(Folder(), name + ".json");
        if (!File.Exists(path))
            throw new UsageException($"no controller profile '{name}' (have: {string.Join(", ", All().Select(p => p.Name))}, or none)");
        return ControllerProfile.Load(path);
    }
}
