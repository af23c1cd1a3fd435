using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// The decisions of the Editor's <c>Assets &gt; AvatarGo &gt; Import Session or BVH...</c> menu, engine-free: what the
    /// file is, whether the core readers (<see cref="SessionReader"/>, <see cref="BvhReader"/>) accept all of it, what the
    /// text asset is called and where it goes without overwriting another. The menu only opens the file panel, copies
    /// the file and refreshes the asset database.
    /// </summary>
    public static class RecordingImport
    {
        /// <summary>The ending of an imported session (Unity imports <c>.txt</c> files as <c>TextAsset</c>s).</summary>
        public const string SessionAssetSuffix = AvatarGoFiles.SessionExtension + ".txt";

        /// <summary>The ending of an imported BVH clip.</summary>
        public const string BvhAssetSuffix = ".bvh.txt";

        /// <summary>The project folder imported files are copied to.</summary>
        public const string DefaultFolder = "Assets/AvatarGo/Recordings";

        /// <summary>The extensions the file panel offers (comma-separated, without dots, as <c>EditorUtility.OpenFilePanel</c> takes them).</summary>
        public const string PanelExtensions = "agsession,bvh,txt";

        /// <summary>Reads the file at <paramref name="path"/> and plans its import; a file that cannot be read is not valid (never throws for I/O).</summary>
        public static RecordingImportPlan PlanFile(string path)
        {
            if (string.IsNullOrEmpty(path)) throw new ArgumentException("No file was given.", nameof(path));
            string name = Path.GetFileName(path);
            try
            {
                using (var reader = new StreamReader(path))
                    return Plan(name, reader);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is NotSupportedException || e is System.Security.SecurityException)
            {
                return Invalid(KindFromName(name) ?? RecordingFileKind.Session, $"{name}: the file cannot be read: {e.Message}");
            }
        }

        /// <summary>
        /// Plans the import of the text <paramref name="reader"/> holds, the file being called <paramref name="fileName"/>:
        /// the kind from the name (<c>.agsession</c>, <c>.bvh</c>, either with <c>.txt</c>), else from the first word
        /// (<c>avatargo-session</c> or <c>HIERARCHY</c>); then the whole file read by the core reader.
        /// </summary>
        public static RecordingImportPlan Plan(string fileName, TextReader reader)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            string name = string.IsNullOrEmpty(fileName) ? "recording" : Path.GetFileName(fileName);
            string text = reader.ReadToEnd();
            RecordingFileKind? kind = KindFromName(name) ?? KindFromContent(text);
            if (kind == null)
                return Invalid(RecordingFileKind.Session, $"{name}: not a recorded session (first line '{SessionText.Magic} 1') or a BVH clip (first word 'HIERARCHY'). Give the file the extension .agsession or .bvh.");
            try
            {
                string summary;
                if (kind == RecordingFileKind.Session)
                {
                    using (var session = new SessionReader(new StringReader(text), name))
                    {
                        SessionFrame frame = session.CreateFrame();
                        while (session.ReadFrame(frame)) { }
                        summary = string.Format(CultureInfo.InvariantCulture, "a session of {0} frames, {1} devices, at {2} Hz", session.FrameCount, session.Header.Devices.Count, session.Header.Rate);
                    }
                }
                else
                {
                    BvhClip clip = BvhReader.Read(new StringReader(text), name);
                    summary = string.Format(CultureInfo.InvariantCulture, "a BVH clip of {0} frames, {1} channels, {2:0.###} s a frame", clip.FrameCount, clip.ChannelCount, clip.FrameTime);
                }
                return new RecordingImportPlan(true, kind.Value, TargetFileName(name, kind.Value), summary, null);
            }
            catch (FormatException e)
            {
                return Invalid(kind.Value, e.Message);
            }
        }

        /// <summary>
        /// The text asset's file name for <paramref name="fileName"/>: its stem (the name without <c>.txt</c> and the
        /// kind's extension), characters other than letters, digits, '-', '_', '.' and ' ' made '_', plus
        /// <see cref="SessionAssetSuffix"/> or <see cref="BvhAssetSuffix"/>.
        /// </summary>
        public static string TargetFileName(string fileName, RecordingFileKind kind)
        {
            string stem = Path.GetFileName(fileName ?? string.Empty);
            if (stem.EndsWith(".txt", StringComparison.OrdinalIgnoreCase)) stem = stem.Substring(0, stem.Length - 4);
            string extension = kind == RecordingFileKind.Session ? AvatarGoFiles.SessionExtension : ".bvh";
            if (stem.EndsWith(extension, StringComparison.OrdinalIgnoreCase)) stem = stem.Substring(0, stem.Length - extension.Length);
            var s = new StringBuilder(stem.Length);
            foreach (char c in stem.Trim())
                s.Append(c < 128 && (char.IsLetterOrDigit(c) || c == '-' || c == '_' || c == '.' || c == ' ') ? c : '_');
            string clean = s.ToString().Trim('.', ' ');
            if (clean.Length == 0) clean = kind == RecordingFileKind.Session ? "session" : "clip";
            return clean + (kind == RecordingFileKind.Session ? SessionAssetSuffix : BvhAssetSuffix);
        }

        /// <summary>
        /// <paramref name="folder"/>/<paramref name="fileName"/> (with '/' as Unity's asset paths have it), or, when
        /// <paramref name="exists"/> says that is taken, the first free <c>NAME 1.agsession.txt</c>, <c>NAME 2...</c>.
        /// </summary>
        public static string UniqueAssetPath(string folder, string fileName, Func<string, bool> exists)
        {
            if (string.IsNullOrEmpty(fileName)) throw new ArgumentException("No file name was given.", nameof(fileName));
            if (exists == null) throw new ArgumentNullException(nameof(exists));
            string prefix = string.IsNullOrEmpty(folder) ? string.Empty : folder.Replace('\\', '/').TrimEnd('/') + "/";
            string candidate = prefix + fileName;
            if (!exists(candidate)) return candidate;
            string suffix = fileName.EndsWith(SessionAssetSuffix, StringComparison.OrdinalIgnoreCase) ? SessionAssetSuffix
                : fileName.EndsWith(BvhAssetSuffix, StringComparison.OrdinalIgnoreCase) ? BvhAssetSuffix
                : Path.GetExtension(fileName);
            string stem = fileName.Substring(0, fileName.Length - suffix.Length);
            for (int n = 1; ; n++)
            {
                candidate = prefix + stem + " " + n.ToString(CultureInfo.InvariantCulture) + suffix;
                if (!exists(candidate)) return candidate;
            }
        }

        private static RecordingFileKind? KindFromName(string name)
        {
            string n = name.EndsWith(".txt", StringComparison.OrdinalIgnoreCase) ? name.Substring(0, name.Length - 4) : name;
            if (n.EndsWith(AvatarGoFiles.SessionExtension, StringComparison.OrdinalIgnoreCase)) return RecordingFileKind.Session;
            if (n.EndsWith(".bvh", StringComparison.OrdinalIgnoreCase)) return RecordingFileKind.Bvh;
            return null;
        }

        private static RecordingFileKind? KindFromContent(string text)
        {
            string start = text.TrimStart('\uFEFF', ' ', '\t', '\r', '\n');
            if (start.StartsWith(SessionText.Magic, StringComparison.Ordinal)) return RecordingFileKind.Session;
            if (start.StartsWith("HIERARCHY", StringComparison.OrdinalIgnoreCase)) return RecordingFileKind.Bvh;
            return null;
        }

        private static RecordingImportPlan Invalid(RecordingFileKind kind, string error) => new RecordingImportPlan(false, kind, null, null, error);
    }
}
