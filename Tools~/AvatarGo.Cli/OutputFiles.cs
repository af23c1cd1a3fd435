using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using AvatarGo.Core;

namespace AvatarGo.Cli;

/// <summary>
/// The files one run writes. <see cref="RefuseClashes"/> refuses, before any work, an output that is also an input or
/// another output (`evaluate S --json S` replaced the session with its report). Files opened here are written whole and
/// together: each goes to a temporary file beside its target (<see cref="AtomicFileWriter"/>), and none replaces its
/// target until <see cref="CommitAll"/>, after every one is complete; a run that fails before that (a plot that cannot
/// be drawn after the JSON was written) leaves every existing file as it was.
/// </summary>
internal sealed class OutputFiles : IDisposable
{
    private readonly List<AtomicFileWriter> _files = new();

    /// <summary>
    /// Throws a usage error when an output names the same file as an input or as another output (after following
    /// symbolic links). Null paths (options not given) are skipped.
    /// </summary>
    public static void RefuseClashes(IEnumerable<(string what, string path)> inputs, IEnumerable<(string what, string path)> outputs)
    {
        var named = new List<(string what, string path, string resolved)>();
        foreach (var (what, path) in inputs)
            if (path != null) named.Add((what, path, Resolved(path)));
        foreach (var (what, path) in outputs)
        {
            if (path == null) continue;
            string resolved = Resolved(path);
            foreach (var (otherWhat, otherPath, otherResolved) in named)
                if (string.Equals(resolved, otherResolved, PathComparison))
                    throw new UsageException($"{what} {path} is the same file as {otherWhat} {otherPath}");
            named.Add((what, path, resolved));
        }
    }

    /// <summary>Starts writing <paramref name="path"/> (checked now: its folder exists, it is no folder, it can be written).</summary>
    public AtomicFileWriter Open(string path)
    {
        var file = new AtomicFileWriter(path);
        _files.Add(file);
        return file;
    }

    /// <summary>Writes <paramref name="text"/> as UTF-8 (without a byte-order mark) into <paramref name="file"/>, not yet committed.</summary>
    public static void WriteText(AtomicFileWriter file, Action<TextWriter> write)
    {
        using var text = new StreamWriter(file.Stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
        write(text);
    }

    /// <summary>Replaces every target with what was written to it.</summary>
    public void CommitAll()
    {
        foreach (AtomicFileWriter file in _files) file.Commit();
    }

    /// <summary>Abandons what was not committed: temporary files deleted, targets untouched.</summary>
    public void Dispose()
    {
        foreach (AtomicFileWriter file in _files) file.Dispose();
    }

    private static StringComparison PathComparison => OperatingSystem.IsWindows() || OperatingSystem.IsMacOS() ? StringComparison.OrdinalIgnoreCase : StringComparison.Ordinal;

    // The full path, a symbolic link's final target where the path is one.
    // The file a path names once every symbolic link on it is followed: the folders along it (`link/s.agsession` where
    // link points at the session's folder) as well as the file itself.
    private static string Resolved(string path)
    {
        try
        {
            return Real(Path.GetFullPath(path), 0);
        }
        catch (IOException)
        {
            return Path.GetFullPath(path); // a link loop: the write reports it
        }
    }

    private const int MaxLinkDepth = 40; // as Linux's ELOOP limit: a longer chain is a loop

    private static string Real(string full, int depth)
    {
        if (depth > MaxLinkDepth) throw new IOException("too many levels of symbolic links: " + full);
        string root = Path.GetPathRoot(full) ?? "";
        string current = root;
        foreach (string part in full.Substring(root.Length).Split(Path.DirectorySeparatorChar, StringSplitOptions.RemoveEmptyEntries))
        {
            current = Path.Combine(current, part);
            FileSystemInfo info = Directory.Exists(current) ? new DirectoryInfo(current) : new FileInfo(current);
            if (info.LinkTarget == null) continue;
            FileSystemInfo target = info.ResolveLinkTarget(returnFinalTarget: true);
            // The target's own path may pass through links too.
            if (target != null) current = Real(target.FullName, depth + 1);
        }
        return current;
    }
}
