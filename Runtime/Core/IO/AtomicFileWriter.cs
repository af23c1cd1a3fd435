using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using System.Threading;

namespace AvatarGo.Core
{
    /// <summary>
    /// Writes a file whole or not at all. The content goes to a temporary file beside the target
    /// (<c>.NAME.PID-RANDOM.tmp</c>, in the same folder so that the final rename stays on one volume);
    /// <see cref="Commit"/> flushes it to disk and then replaces the target in one rename. Until then the target is
    /// untouched: disposing without committing (an exception while writing) deletes the temporary file and leaves the
    /// previous file byte for byte as it was.
    /// </summary>
    /// <remarks>
    /// <para>A process killed mid-write cannot delete its temporary file; the next writer of the same target deletes
    /// such leftovers: temporary files of that target whose process no longer runs (or, where the platform cannot
    /// list processes, that were last written more than an hour ago). Temporary files of writers still at work, in
    /// this process or another, are left alone, so concurrent writers of one target never break each other: each
    /// rename replaces the target whole, the last one wins, and a writer that finds the target created or replaced
    /// under it (two first saves racing) retries.</para>
    /// <para>Kept from the target: on Windows its attributes and access rights (the replacement uses the system's
    /// file replace); on Linux and macOS its Unix permissions, where the runtime can read and set them (.NET 7 and
    /// newer). A symbolic link is followed (its final target is replaced, the link stays) where the runtime can read
    /// links (.NET 6 and newer). Unity's Mono and IL2CPP can do neither: there a replaced file gets the process's
    /// default permissions and a link is replaced by a regular file (the file it pointed to is left unchanged).
    /// See Documentation~/robustness.md.</para>
    /// <para>The data is on disk before the rename; the rename itself is atomic against a crash of the process and,
    /// on journaling file systems, of the machine, which may still lose the rename (the old file stays) but never
    /// leaves a torn one.</para>
    /// </remarks>
    public sealed class AtomicFileWriter : IDisposable
    {
        private const string TemporarySuffix = ".tmp";
        private const int ReplaceAttempts = 50;
        private static readonly TimeSpan UnknownOwnerAge = TimeSpan.FromHours(1);
        private static readonly HashSet<string> LiveTemporaries = new HashSet<string>(StringComparer.Ordinal);

        private FileStream _stream;
        private bool _committed;
        private bool _disposed;

        /// <summary>Starts writing <paramref name="path"/>: creates the temporary file beside it.</summary>
        /// <exception cref="UnauthorizedAccessException">The target is read-only, or the folder cannot be written.</exception>
        /// <exception cref="IOException">The target is a folder, the folder does not exist, or links loop.</exception>
        public AtomicFileWriter(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (path.Length == 0) throw new ArgumentException("The path is empty.", nameof(path));
            TargetPath = FileSystemFeatures.FinalTarget(Path.GetFullPath(path));
            if (Directory.Exists(TargetPath)) throw new IOException($"{path} is a folder, not a file.");
            if (File.Exists(TargetPath) && (File.GetAttributes(TargetPath) & FileAttributes.ReadOnly) != 0)
                throw new UnauthorizedAccessException($"{path} is read-only.");
            string folder = Path.GetDirectoryName(TargetPath);
            string name = Path.GetFileName(TargetPath);
            if (!Directory.Exists(folder)) throw new DirectoryNotFoundException($"The folder of {path} does not exist.");
            DeleteStaleTemporaries(folder, name);

            TemporaryPath = Path.Combine(folder, TemporaryPrefix(name) + FileSystemFeatures.ProcessId.ToString(CultureInfo.InvariantCulture)
                + "-" + Guid.NewGuid().ToString("N") + TemporarySuffix);
            lock (LiveTemporaries) LiveTemporaries.Add(TemporaryPath);
            try
            {
                _stream = new FileStream(TemporaryPath, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16);
            }
            catch
            {
                lock (LiveTemporaries) LiveTemporaries.Remove(TemporaryPath);
                throw;
            }
        }

        /// <summary>The file that <see cref="Commit"/> replaces: the full path, or a symbolic link's final target.</summary>
        public string TargetPath { get; }

        /// <summary>The temporary file the content goes to until <see cref="Commit"/>.</summary>
        public string TemporaryPath { get; }

        /// <summary>Where to write the content (a stream of the temporary file; do not close it, dispose this writer).</summary>
        public Stream Stream => _stream ?? throw new ObjectDisposedException(nameof(AtomicFileWriter));

        /// <summary>
        /// Flushes the content to disk and replaces the target with it (keeping what the platform allows, see the
        /// remarks). On failure the target is left as it was and the temporary file is deleted.
        /// </summary>
        /// <exception cref="InvalidOperationException">Already committed or disposed.</exception>
        /// <exception cref="IOException">The file could not be written or replaced.</exception>
        public void Commit()
        {
            if (_disposed || _committed) throw new InvalidOperationException("The file was already committed or abandoned.");
            try
            {
                _stream.Flush(true);
                _stream.Dispose();
                _stream = null;
                if (File.Exists(TargetPath)) FileSystemFeatures.TryCopyUnixMode(TargetPath, TemporaryPath);
                Replace(TemporaryPath, TargetPath);
                _committed = true;
            }
            finally
            {
                if (!_committed) Dispose();
            }
            Dispose();
        }

        /// <summary>Ends the write. Without <see cref="Commit"/>, abandons it: the temporary file is deleted, the target untouched.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            try
            {
                _stream?.Dispose();
            }
            catch (IOException)
            {
                // Flushing the abandoned content failed (a full disk): it is being thrown away anyway.
            }
            _stream = null;
            if (!_committed)
            {
                try { File.Delete(TemporaryPath); }
                catch (IOException) { }
                catch (UnauthorizedAccessException) { }
            }
            lock (LiveTemporaries) LiveTemporaries.Remove(TemporaryPath);
        }

        /// <summary>Writes <paramref name="bytes"/> to <paramref name="path"/> whole or not at all.</summary>
        public static void WriteAllBytes(string path, byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            using (var file = new AtomicFileWriter(path))
            {
                file.Stream.Write(bytes, 0, bytes.Length);
                file.Commit();
            }
        }

        /// <summary>Writes <paramref name="text"/> as UTF-8 (without a byte-order mark) whole or not at all.</summary>
        public static void WriteAllText(string path, string text)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            WriteAllBytes(path, new UTF8Encoding(false).GetBytes(text));
        }

        /// <summary>
        /// Writes the text <paramref name="write"/> produces as UTF-8 (without a byte-order mark) whole or not at all:
        /// if <paramref name="write"/> throws, the target is left as it was.
        /// </summary>
        public static void WriteText(string path, Action<TextWriter> write)
        {
            if (write == null) throw new ArgumentNullException(nameof(write));
            using (var file = new AtomicFileWriter(path))
            {
                using (var text = new StreamWriter(file.Stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true))
                {
                    write(text);
                }
                file.Commit();
            }
        }

        /// <summary>The start of every temporary file name of target <paramref name="fileName"/>: <c>.NAME.</c></summary>
        internal static string TemporaryPrefix(string fileName) => "." + fileName + ".";

        /// <summary>
        /// The process id in a temporary file name of target <paramref name="fileName"/>
        /// (<c>.NAME.PID-32HEX.tmp</c>), or -1 when <paramref name="candidate"/> is not one.
        /// </summary>
        internal static int TemporaryOwner(string candidate, string fileName)
        {
            string prefix = TemporaryPrefix(fileName);
            if (!candidate.StartsWith(prefix, StringComparison.Ordinal) || !candidate.EndsWith(TemporarySuffix, StringComparison.Ordinal)) return -1;
            int start = prefix.Length, end = candidate.Length - TemporarySuffix.Length;
            int dash = candidate.IndexOf('-', start);
            if (dash <= start || end - dash - 1 != 32) return -1;
            for (int i = dash + 1; i < end; i++)
            {
                char c = candidate[i];
                if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return -1;
            }
            return int.TryParse(candidate.Substring(start, dash - start), NumberStyles.None, CultureInfo.InvariantCulture, out int pid) ? pid : -1;
        }

        private static void DeleteStaleTemporaries(string folder, string name)
        {
            string[] candidates;
            try
            {
                candidates = Directory.GetFiles(folder, TemporaryPrefix(name) + "*" + TemporarySuffix);
            }
            catch (IOException) { return; }
            catch (UnauthorizedAccessException) { return; }
            int self = FileSystemFeatures.ProcessId;
            foreach (string path in candidates)
            {
                int owner = TemporaryOwner(Path.GetFileName(path), name);
                if (owner < 0) continue;
                bool stale;
                if (owner == self && self > 0)
                {
                    lock (LiveTemporaries) stale = !LiveTemporaries.Contains(path);
                }
                else
                {
                    bool? running = FileSystemFeatures.IsProcessRunning(owner);
                    stale = running == false || (running == null && DateTime.UtcNow - File.GetLastWriteTimeUtc(path) > UnknownOwnerAge);
                }
                if (!stale) continue;
                try { File.Delete(path); }
                catch (IOException) { }
                catch (UnauthorizedAccessException) { }
            }
        }

        // Rename over the target. Two first saves may race (the target appears between the check and the move), another
        // writer may replace the target under us, and Windows refuses to replace a file that is open elsewhere for a
        // moment: each is retried with the other operation or after a short wait.
        private static void Replace(string temporary, string target)
        {
            for (int attempt = 1; ; attempt++)
            {
                try
                {
                    if (File.Exists(target)) File.Replace(temporary, target, null, ignoreMetadataErrors: true);
                    else File.Move(temporary, target);
                    return;
                }
                catch (Exception e) when ((e is IOException || e is UnauthorizedAccessException) && attempt < ReplaceAttempts && File.Exists(temporary))
                {
                    if (attempt > 2) Thread.Sleep(Math.Min(attempt, 20));
                }
            }
        }
    }
}
