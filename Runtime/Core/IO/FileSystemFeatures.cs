using System;
using System.Diagnostics;
using System.IO;
using System.Reflection;
using System.Runtime.InteropServices;

namespace AvatarGo.Core
{
    /// <summary>
    /// File-system features that .NET Standard 2.1 (what Unity compiles against) lacks but newer runtimes have, used
    /// when the running runtime offers them: following a symbolic link (.NET 6+ <c>FileSystemInfo.ResolveLinkTarget</c>)
    /// and a file's Unix permissions (.NET 7+ <c>File.GetUnixFileMode</c>/<c>SetUnixFileMode</c>). Unity's Mono and
    /// IL2CPP have neither; there each call reports that it could not help, and callers carry on without.
    /// </summary>
    internal static class FileSystemFeatures
    {
        private static readonly MethodInfo ResolveLinkTargetMethod =
            typeof(FileSystemInfo).GetMethod("ResolveLinkTarget", new[] { typeof(bool) });
        private static readonly MethodInfo GetUnixFileModeMethod = typeof(File).GetMethod("GetUnixFileMode", new[] { typeof(string) });
        private static readonly MethodInfo SetUnixFileModeMethod = FindSetUnixFileMode();
        private static readonly bool IsWindows = RuntimeInformation.IsOSPlatform(OSPlatform.Windows);
        private static int _processId = -1;

        /// <summary>True when symbolic links can be followed on this runtime.</summary>
        public static bool CanFollowLinks => ResolveLinkTargetMethod != null;

        /// <summary>True when Unix permissions can be read and set on this runtime and platform.</summary>
        public static bool CanKeepUnixMode => !IsWindows && GetUnixFileModeMethod != null && SetUnixFileModeMethod != null;

        /// <summary>
        /// The file a path finally names: the path itself, or, when it is a symbolic link (or a chain of them), the
        /// link's final target (which need not exist yet). Without link support, the path itself.
        /// </summary>
        /// <exception cref="IOException">The links form a loop or cannot be read.</exception>
        public static string FinalTarget(string fullPath)
        {
            if (ResolveLinkTargetMethod == null) return fullPath;
            try
            {
                var target = (FileSystemInfo)ResolveLinkTargetMethod.Invoke(new FileInfo(fullPath), new object[] { true });
                return target == null ? fullPath : Path.GetFullPath(Path.Combine(Path.GetDirectoryName(fullPath) ?? "", target.FullName));
            }
            catch (TargetInvocationException e) when (e.InnerException is FileNotFoundException || e.InnerException is DirectoryNotFoundException)
            {
                return fullPath; // nothing there yet, so not a link
            }
            catch (TargetInvocationException e) when (e.InnerException != null)
            {
                ExceptionDispatchInfoThrow(e.InnerException);
                throw;
            }
        }

        /// <summary>Gives <paramref name="to"/> the Unix permissions of <paramref name="from"/>; false when that is not possible here.</summary>
        public static bool TryCopyUnixMode(string from, string to)
        {
            if (!CanKeepUnixMode) return false;
            try
            {
                object mode = GetUnixFileModeMethod.Invoke(null, new object[] { from });
                SetUnixFileModeMethod.Invoke(null, new[] { to, mode });
                return true;
            }
            catch (TargetInvocationException e) when (e.InnerException is IOException || e.InnerException is UnauthorizedAccessException || e.InnerException is PlatformNotSupportedException)
            {
                return false;
            }
        }

        /// <summary>This process's id, or 0 when the platform does not say.</summary>
        public static int ProcessId
        {
            get
            {
                if (_processId < 0)
                {
                    try
                    {
                        using (Process p = Process.GetCurrentProcess()) _processId = p.Id;
                    }
                    catch (Exception e) when (e is PlatformNotSupportedException || e is InvalidOperationException || e is NotSupportedException)
                    {
                        _processId = 0;
                    }
                }
                return _processId;
            }
        }

        /// <summary>True when a process with this id runs, false when none does, null when the platform cannot tell.</summary>
        public static bool? IsProcessRunning(int id)
        {
            if (id <= 0) return null;
            try
            {
                using (Process p = Process.GetProcessById(id)) return true;
            }
            catch (ArgumentException)
            {
                return false; // "no process with that id"
            }
            catch (Exception e) when (e is PlatformNotSupportedException || e is InvalidOperationException || e is NotSupportedException || e is System.ComponentModel.Win32Exception)
            {
                return null;
            }
        }

        private static MethodInfo FindSetUnixFileMode()
        {
            foreach (MethodInfo m in typeof(File).GetMethods(BindingFlags.Public | BindingFlags.Static))
            {
                if (m.Name != "SetUnixFileMode") continue;
                ParameterInfo[] p = m.GetParameters();
                if (p.Length == 2 && p[0].ParameterType == typeof(string) && p[1].ParameterType.IsEnum) return m;
            }
            return null;
        }

        private static void ExceptionDispatchInfoThrow(Exception e) => System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e).Throw();
    }
}
