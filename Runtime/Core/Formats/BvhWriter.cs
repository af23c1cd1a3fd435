using System;
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
        /// <summary>Writes the clip to a file (replacing it).</summary>
        public static void WriteFile(string path, BvhClip clip)
        {
            using (var writer = new StreamWriter(path, false, new UTF8Encoding(false)))
                Write(writer, clip);
        }

        /// <summary>Writes the clip as BVH text.</summary>
        public static void Write(TextWriter writer, BvhClip clip)
        {
            if (writer == null) throw new ArgumentNullException(nameof(writer));
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            writer.NewLine = "\n";
            Skeleton s = clip.Skeleton;
            writer.WriteLine("HIERARCHY");
            for (int root = 0; root < s.JointCount; root++)
                if (s.GetParent(root) < 0) WriteJoint(writer, clip, root, 0);
            writer.WriteLine("MOTION");
            writer.WriteLine("Frames:\t" + clip.FrameCount.ToString(CultureInfo.InvariantCulture));
            writer.WriteLine("Frame Time:\t" + clip.FrameTime.ToString("R", CultureInfo.InvariantCulture));
            var line = new StringBuilder(clip.ChannelCount * 10);
            for (int f = 0; f < clip.FrameCount; f++)
            {
                line.Clear();
                for (int c = 0; c < clip.ChannelCount; c++)
                {
                    if (c > 0) line.Append(' ');
                    line.Append(clip.GetValue(f, c).ToString("R", CultureInfo.InvariantCulture));
                }
                writer.WriteLine(line.ToString());
            }
        }

        private static void WriteJoint(TextWriter w, BvhClip clip, int joint, int depth)
        {
            Skeleton s = clip.Skeleton;
            string indent = new string('\t', depth);
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
            for (int child = joint + 1; child < s.JointCount; child++)
                if (s.GetParent(child) == joint) WriteJoint(w, clip, child, depth + 1);
            w.WriteLine(indent + "}");
        }

        private static string F(float v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
