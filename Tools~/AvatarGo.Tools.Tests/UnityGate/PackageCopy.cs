using System;
using System.IO;
using System.Linq;

namespace AvatarGo.Tools.Tests.UnityGate;

/// <summary>
/// A temporary copy of the real package (Runtime, Editor, Tests, package.json and the Unity surface; no data, docs
/// or build output) for planting one defect and running the gate on it. Disposing deletes it.
/// </summary>
public sealed class PackageCopy : IDisposable
{
    private static readonly string[] Copied = { "package.json", "Runtime", "Editor", "Tests", "Samples~", "Tools~/UnitySurface" };

    /// <summary>Copies the package at <see cref="Paths.PackageRoot"/>.</summary>
    public PackageCopy()
    {
        Root = Path.Combine(Path.GetTempPath(), "avatargo-gate-" + Guid.NewGuid().ToString("N"));
        foreach (string entry in Copied)
        {
            string from = Path.Combine(Paths.PackageRoot, entry), to = Path.Combine(Root, entry);
            if (File.Exists(from))
            {
                Directory.CreateDirectory(Path.GetDirectoryName(to));
                File.Copy(from, to);
                if (File.Exists(from + ".meta")) File.Copy(from + ".meta", to + ".meta");
            }
            else CopyFolder(from, to);
        }
    }

    /// <summary>The copy's root.</summary>
    public string Root { get; }

    /// <summary>Where the gate writes its projects for the copy.</summary>
    public string OutDir => Path.Combine(Root, "Tools~", "out", "gate");

    /// <summary>Writes a file (package-relative, '/'), creating folders.</summary>
    public void Write(string relative, string text)
    {
        string path = Path.Combine(Root, relative);
        Directory.CreateDirectory(Path.GetDirectoryName(path));
        File.WriteAllText(path, text.Replace("\r\n", "\n"));
    }

    /// <summary>Reads a file.</summary>
    public string Read(string relative) => File.ReadAllText(Path.Combine(Root, relative));

    /// <summary>Replaces one exact occurrence of <paramref name="old"/> in a file; fails when it is not there once.</summary>
    public void Replace(string relative, string old, string replacement)
    {
        string text = Read(relative);
        int at = text.IndexOf(old, StringComparison.Ordinal);
        if (at < 0 || text.IndexOf(old, at + 1, StringComparison.Ordinal) >= 0)
            throw new InvalidOperationException($"{relative} does not hold exactly one '{old}'");
        Write(relative, text.Substring(0, at) + replacement + text.Substring(at + old.Length));
    }

    private static void CopyFolder(string from, string to)
    {
        Directory.CreateDirectory(to);
        foreach (string f in Directory.GetFiles(from)) File.Copy(f, Path.Combine(to, Path.GetFileName(f)));
        foreach (string d in Directory.GetDirectories(from))
        {
            string name = Path.GetFileName(d);
            if (name is "bin" or "obj" || name.StartsWith('.') || (name.EndsWith('~') && name != "UnitySurface~")) continue;
            CopyFolder(d, Path.Combine(to, name));
        }
    }

    /// <summary>Deletes the copy.</summary>
    public void Dispose()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A leftover temp folder is harmless.
        }
    }
}
