using System;
using System.Collections.Generic;
using System.IO;

namespace AvatarGo.UnityGate;

/// <summary>The files of a package that Unity imports: everything outside `~` folders and dot entries.</summary>
public static class PackageFiles
{
    /// <summary>Imported files, package-relative with '/', in ordinal order.</summary>
    public static List<string> Imported(string packageRoot)
    {
        var files = new List<string>();
        Walk(packageRoot, "", files);
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
