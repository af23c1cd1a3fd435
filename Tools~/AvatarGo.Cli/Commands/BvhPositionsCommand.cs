using System;
using System.Globalization;
using System.IO;
using System.Text;
using AvatarGo.Core;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo bvh positions FILE`: world joint positions per frame as CSV.</summary>
public sealed class BvhPositionsCommand : ICommand
{
    public string Name => "bvh positions";
    public string Summary => "World joint positions of every frame as CSV (Unity's frame)";
    public string Help => """
        avatargo bvh positions FILE [--frames A:B] [--scale S]

        Writes CSV to standard output: a header row, then one row per frame: the frame index, then
        x,y,z of every joint in file order (End Sites excluded), in world space, in Unity's frame
        (BVH is right-handed: x is negated), in the file's units times S.
          --frames A:B   frames A (inclusive) to B (exclusive); either side may be left out (default all)
          --scale S      multiply every length by S (default 1)
        Exit codes: 0 ok, 1 unreadable or malformed file, 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args);
        string path = a.Positional0("FILE");
        double scale = a.Double("scale", 1.0);
        string range = a.String("frames");
        a.ThrowOnUnknown(1);
        if (!((float)scale > 0f)) throw new UsageException("--scale must be positive (and at least a float's smallest, 1e-45)"); // 1e-50 was 0 as a float

        BvhClip clip = BvhReader.ReadFile(path, new BvhReadOptions { Scale = (float)scale });
        (int from, int to) = ParseRange(range, clip.FrameCount);
        Skeleton s = clip.Skeleton;
        var inv = CultureInfo.InvariantCulture;

        var line = new StringBuilder();
        line.Append("frame");
        for (int j = 0; j < s.JointCount; j++)
        {
            if (s.IsEndSite(j)) continue;
            string n = s.GetName(j);
            foreach (string axis in new[] { ".x", ".y", ".z" }) line.Append(',').Append(CsvField(n + axis));
        }
        stdout.WriteLine(line.ToString());

        var local = new RigidPose[s.JointCount];
        var world = new RigidPose[s.JointCount];
        for (int f = from; f < to; f++)
        {
            clip.GetWorldPoses(f, local, world);
            line.Clear();
            line.Append(f.ToString(inv));
            for (int j = 0; j < s.JointCount; j++)
            {
                if (s.IsEndSite(j)) continue;
                var p = world[j].Position;
                line.Append(',').Append(p.X.ToString("R", inv)).Append(',').Append(p.Y.ToString("R", inv)).Append(',').Append(p.Z.ToString("R", inv));
            }
            stdout.WriteLine(line.ToString());
        }
        return 0;
    }

    private static (int, int) ParseRange(string range, int count)
    {
        if (range == null) return (0, count);
        int colon = range.IndexOf(':');
        if (colon < 0) throw new UsageException($"--frames expects A:B, got '{range}'");
        int from = Bound(range.Substring(0, colon), 0, "A");
        int to = Bound(range.Substring(colon + 1), count, "B");
        if (from < 0 || to > count || from > to) throw new UsageException($"--frames {range} is outside 0:{count}");
        return (from, to);

        static int Bound(string text, int fallback, string what)
        {
            if (text.Length == 0) return fallback;
            if (!int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
                throw new UsageException($"--frames: {what} must be a whole number, got '{text}'");
            return v;
        }
    }

    // A header field as RFC 4180 has it: quoted, inner quotes doubled, when a BVH name holds a comma, a quote or a line
    // break (found in review: a joint named `Joint,A "q"` shifted every column after it).
    private static string CsvField(string field) =>
        field.IndexOfAny(new[] { ',', '"', '\n', '\r' }) < 0 ? field : "\"" + field.Replace("\"", "\"\"") + "\"";
}
