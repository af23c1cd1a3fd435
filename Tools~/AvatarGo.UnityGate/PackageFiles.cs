using System;
using System.Collections.Generic;
using System.IO;

namespace AvatarGo.UnityGate;

/// <summary>
/// The files of a package that Unity compiles and imports: everything outside `~` folders and dot entries, plus each
/// sample (`Samples~/NAME/...`, by the same rules inside it), which the Package Manager copies into the project's
/// Assets when the user imports it and which must then compile against the package as it is.
/// </summary>
public static class PackageFiles
{
    /// <summary>The folder that holds the samples, one folder each.</summary>
    public const string SamplesFolder = "Samples~";

    /// <summary>Imported files, package-relative with '/', in ordinal order.</summary>
    public static List<string> Imported(string packageRoot)
    {
        var files = new List<string>();
        Walk(packageRoot, "", files);
        string samples = Path.Combine(packageRoot, SamplesFolder);
        if (Directory.Exists(samples))
            foreach (string sample in Directory.GetDirectories(samples))
            {
                string name = Path.GetFileName(sample);
                if (!name.StartsWith('.') && !name.EndsWith('~')) Walk(sample, SamplesFolder + "/" + name + "/", files);
            }
        files.Sort(StringComparer.Ordinal);
        return files;
    }

    private static void Walk(string dir, string prefix, List<string> files)
    {
        foreach (string f in Directory.GetFiles(dir))
        {
            string name = Path.GetFileName(f);
            if (!name.StartsWith('.') && !name.EndsWith('~')) files.Add(prefix + name);
        }
        foreach (string d in Directory.GetDirectories(dir))
        {
            string name = Path.GetFileName(d);
            if (name.StartsWith('.') || name.EndsWith('~')) continue;
            Walk(d, prefix + name + "/", files);
        }
    }
}
