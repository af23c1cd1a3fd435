using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Writes a <see cref="BvhClip"/> as BVH text (tab-indented, LF line ends, invariant culture, values with
    /// float round-trip precision), so that reading it back gives the same hierarchy, channels and values.
    /// </summary>
    public static class BvhWriter
    {
        /// <summary>
        /// Writes the clip to a file, whole or not at all (<see cref="AtomicFileWriter"/>): if writing fails, a file
        /// already at <paramref name="path"/> is left as it was.
        /// </summary>
        public static void WriteFile(string path, BvhClip clip)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            AtomicFileWriter.WriteText(path, writer => Write(writer, clip));
        }

        /// <summary>Writes the clip as BVH text.</summary>
        /// <exception cref="ArgumentException">The clip cannot be written so that <see cref="BvhReader"/> reads it back the
        /// same (checked before anything is written): more than one root, a joint name that is empty or not words joined by single spaces,
        /// a joint named like the name the reader gives an End Site (its parent's name and "_End"), a frame time or a value
        /// outside what the reader takes.</exception>
        public static void Write(TextWriter writer, BvhClip clip)
        {
            if (writer == null) throw new ArgumentNullException(nameof(writer));
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            CheckReadable(clip);
            writer.NewLine = "\n";
            writer.WriteLine("HIERARCHY");
            List<int> written = WriteHierarchy(writer, clip);
            writer.WriteLine("MOTION");
            writer.WriteLine("Frames:\t" + clip.FrameCount.ToString(CultureInfo.InvariantCulture));
            writer.WriteLine("Frame Time:\t" + clip.FrameTime.ToString("R", CultureInfo.InvariantCulture));
            // The clip keeps its values in joint-index order; a reader takes them in the order the hierarchy lists the
            // joints (depth first), which differs when a joint was added after another branch (found in review: a clip
            // built with a joint appended read back scrambled, a knee 178 mm off). So each frame is written in that order.
            Skeleton s = clip.Skeleton;
            var start = new int[s.JointCount];
            for (int j = 0, total = 0; j < s.JointCount; j++)
            {
                start[j] = total;
                total += clip.GetChannels(j).Count; // as the clip counts them (an End Site's channels, which no file writes, too)
            }
            var line = new StringBuilder(clip.ChannelCount * 10);
            for (int f = 0; f < clip.FrameCount; f++)
            {
                line.Clear();
                foreach (int j in written)
                {
                    if (s.IsEndSite(j)) continue;
                    int count = clip.GetChannels(j).Count;
                    for (int c = 0; c < count; c++)
                    {
                        if (line.Length > 0) line.Append(' ');
                        line.Append(clip.GetValue(f, start[j] + c).ToString("R", CultureInfo.InvariantCulture));
                    }
                }
                writer.WriteLine(line.ToString());
            }
        }

        // What the reader would refuse or read otherwise, refused before the first line (found in review: a frame time of
        // 1e-5 s, a second root or a name with two spaces wrote a file that read back refused or renamed, and WriteFile
        // replaced a good file with it).
        private static void CheckReadable(BvhClip clip)
        {
            Skeleton s = clip.Skeleton;
            int roots = 0;
            var endSiteStems = new List<string>();
            if (s.JointCount > BvhReader.MaxJoints || clip.ChannelCount > BvhReader.MaxChannels || (long)clip.ChannelCount * clip.FrameCount > BvhReader.MaxValues)
                throw new ArgumentException($"The clip has {s.JointCount} joints, {clip.ChannelCount} channels and {clip.FrameCount} frames: beyond what a BVH reader takes ({BvhReader.MaxJoints} joints, {BvhReader.MaxChannels} channels, {BvhReader.MaxValues} values).", nameof(clip));
            for (int j = 0; j < s.JointCount; j++)
            {
                if (s.GetParent(j) < 0) roots++;
                if (s.IsEndSite(j))
                {
                    // An End Site is a leaf with no channels below a joint (found in review: one with channels lost them
                    // silently, one with children or as the root wrote a file the reader refuses).
                    if (s.GetParent(j) < 0) throw new ArgumentException($"The root '{s.GetName(j)}' is an End Site; a BVH file's ROOT is a joint.", nameof(clip));
                    if (clip.GetChannels(j).Count > 0) throw new ArgumentException($"End Site {j} ('{s.GetName(j)}') has {clip.GetChannels(j).Count} channels; a BVH End Site has none.", nameof(clip));
                    for (int c = j + 1; c < s.JointCount; c++)
                        if (s.GetParent(c) == j) throw new ArgumentException($"End Site {j} ('{s.GetName(j)}') has a child ('{s.GetName(c)}'); a BVH End Site has none.", nameof(clip));
                    endSiteStems.Add(s.GetName(s.GetParent(j)) + "_End");
                    continue;
                }
                IReadOnlyList<BvhChannel> channels = clip.GetChannels(j);
                if (channels.Count > 6) throw new ArgumentException($"Joint {j} ('{s.GetName(j)}') has {channels.Count} channels; a BVH joint has at most 6.", nameof(clip));
                for (int a = 0; a < channels.Count; a++)
                    for (int b = a + 1; b < channels.Count; b++)
                        if (channels[a] == channels[b]) throw new ArgumentException($"Joint {j} ('{s.GetName(j)}') lists channel {channels[a]} twice; a BVH reader refuses that.", nameof(clip));
                string name = s.GetName(j);
                if (!ReadsBack(name))
                    throw new ArgumentException($"Joint {j} is named '{name}': a BVH reader reads a name's words joined by single spaces, so it would read another name.", nameof(clip));
                CheckFinite(clip.GetFileOffset(j).X, $"joint {name}'s offset"); CheckFinite(clip.GetFileOffset(j).Y, $"joint {name}'s offset"); CheckFinite(clip.GetFileOffset(j).Z, $"joint {name}'s offset");
            }
            if (roots != 1) throw new ArgumentException($"The clip has {roots} roots; a BVH file holds one ROOT.", nameof(clip));
            foreach (string stem in endSiteStems)
                for (int j = 0; j < s.JointCount; j++)
                    if (!s.IsEndSite(j) && IsEndSiteName(s.GetName(j), stem))
                        throw new ArgumentException($"Joint '{s.GetName(j)}' would clash with the name the reader gives an End Site of '{stem.Substring(0, stem.Length - 4)}'.", nameof(clip));
            if (!(clip.FrameTime >= BvhReader.MinFrameTime && clip.FrameTime <= BvhReader.MaxFrameTime))
                throw new ArgumentException($"Frame time {clip.FrameTime.ToString("R", CultureInfo.InvariantCulture)} s is outside the {BvhReader.MinFrameTime.ToString(CultureInfo.InvariantCulture)}–{BvhReader.MaxFrameTime.ToString(CultureInfo.InvariantCulture)} s a BVH reader takes.", nameof(clip));
            for (int f = 0; f < clip.FrameCount; f++)
                for (int c = 0; c < clip.ChannelCount; c++)
                    CheckFinite(clip.GetValue(f, c), $"frame {f}, channel {c}");
        }

        // The reader names an End Site after its parent, "_End", made unique with a number (BvhReader's UniqueName).
        private static bool IsEndSiteName(string name, string stem)
        {
            if (!name.StartsWith(stem, StringComparison.Ordinal)) return false;
            for (int i = stem.Length; i < name.Length; i++)
                if (name[i] < '0' || name[i] > '9') return false;
            return true;
        }

        // A name the reader reads back as it is: words (no other white space than single spaces between them).
        private static bool ReadsBack(string name)
        {
            if (string.IsNullOrEmpty(name) || name[0] == ' ' || name[name.Length - 1] == ' ') return false;
            for (int i = 0; i < name.Length; i++)
            {
                char ch = name[i];
                if (ch == ' ' ? name[i - 1] == ' ' : char.IsWhiteSpace(ch)) return false;
            }
            return true;
        }

        private static void CheckFinite(float v, string where)
        {
            if (!(Math.Abs(v) <= BvhReader.MaxMagnitude))
                throw new ArgumentException($"{where}: {v.ToString("R", CultureInfo.InvariantCulture)} is not a number within ±{BvhReader.MaxMagnitude.ToString(CultureInfo.InvariantCulture)}, which is all a BVH reader takes.");
        }

        // Depth-first, children in index order, with an explicit stack (a deep chain must not overflow the thread's
        // stack) and children listed once up front (linear, not a scan of every joint per joint). Indentation stops
        // growing at MaxIndent tabs, so that a chain thousands of joints deep is not quadratic in tabs.
        private const int MaxIndent = 32;

        // Returns the joints in the order written.
        private static List<int> WriteHierarchy(TextWriter w, BvhClip clip)
        {
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var childStart = new int[n + 1];
            for (int j = 0; j < n; j++)
                if (s.GetParent(j) >= 0) childStart[s.GetParent(j) + 1]++;
            for (int j = 0; j < n; j++) childStart[j + 1] += childStart[j];
            var children = new int[Math.Max(0, childStart[n])];
            var fill = (int[])childStart.Clone();
            for (int j = 0; j < n; j++)
                if (s.GetParent(j) >= 0) children[fill[s.GetParent(j)]++] = j;

            // Each stack entry is a joint and how many of its children have been written; a joint is opened when pushed.
            var stack = new List<(int Joint, int NextChild)>();
            var order = new List<int>(n);
            for (int root = 0; root < n; root++)
            {
                if (s.GetParent(root) >= 0) continue;
                Open(w, clip, root, 0);
                order.Add(root);
                stack.Add((root, 0));
                while (stack.Count > 0)
                {
                    var (joint, next) = stack[stack.Count - 1];
                    if (childStart[joint] + next < childStart[joint + 1])
                    {
                        stack[stack.Count - 1] = (joint, next + 1);
                        int child = children[childStart[joint] + next];
                        Open(w, clip, child, stack.Count);
                        order.Add(child);
                        stack.Add((child, 0));
                    }
                    else
                    {
                        stack.RemoveAt(stack.Count - 1);
                        w.WriteLine(Indent(stack.Count) + "}");
                    }
                }
            }
            return order;
        }

        private static void Open(TextWriter w, BvhClip clip, int joint, int depth)
        {
            Skeleton s = clip.Skeleton;
            string indent = Indent(depth);
            bool endSite = s.IsEndSite(joint);
            w.WriteLine(indent + (endSite ? "End Site" : (s.GetParent(joint) < 0 ? "ROOT " : "JOINT ") + s.GetName(joint)));
            w.WriteLine(indent + "{");
            var o = clip.GetFileOffset(joint);
            w.WriteLine(indent + "\tOFFSET " + F(o.X) + " " + F(o.Y) + " " + F(o.Z));
            if (!endSite)
            {
                var channels = clip.GetChannels(joint);
                var sb = new StringBuilder(indent + "\tCHANNELS " + channels.Count.ToString(CultureInfo.InvariantCulture));
                foreach (BvhChannel c in channels) sb.Append(' ').Append(c.ToString());
                w.WriteLine(sb.ToString());
            }
        }

        private static readonly string[] Indents = BuildIndents();

        private static string[] BuildIndents()
        {
            var indents = new string[MaxIndent + 1];
            for (int i = 0; i <= MaxIndent; i++) indents[i] = new string('\t', i);
            return indents;
        }

        private static string Indent(int depth) => Indents[Math.Min(depth, MaxIndent)];

        private static string F(float v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
