using System;
using System.Collections.Generic;
using System.IO;
using AvatarGo.Core;

namespace AvatarGo.Cli;

/// <summary>
/// `--map FILE`: the humanoid bones of joints whose names the naming rules miss (<see cref="HumanoidNaming"/>), one
/// `joint name = Bone` a line (a <see cref="HumanoidBone"/> name, any case), `#` starting a comment. The bones given win;
/// the others are still found from the names.
/// </summary>
public static class BoneMapFile
{
    /// <summary>Reads the map at <paramref name="path"/>.</summary>
    /// <exception cref="FormatException">A line is not `joint = Bone`, names no humanoid bone, or gives a joint or a bone twice (the message names the line).</exception>
    /// <exception cref="IOException">The file cannot be read, or the path is a folder.</exception>
    public static IReadOnlyDictionary<string, HumanoidBone> Read(string path)
    {
        if (Directory.Exists(path)) throw new IOException($"{path} is a folder, not a file.");
        var map = new Dictionary<string, HumanoidBone>(StringComparer.Ordinal);
        var bones = new HashSet<HumanoidBone>();
        string[] lines = File.ReadAllLines(path);
        for (int i = 0; i < lines.Length; i++)
        {
            string line = lines[i];
            int comment = line.IndexOf('#');
            if (comment >= 0) line = line.Substring(0, comment);
            if (line.Trim().Length == 0) continue;
            string where = $"{Path.GetFileName(path)}:{i + 1}";
            int equals = line.LastIndexOf('=');
            string joint = equals > 0 ? line.Substring(0, equals).Trim() : "";
            string boneName = equals > 0 ? line.Substring(equals + 1).Trim() : "";
            if (joint.Length == 0 || boneName.Length == 0)
                throw new FormatException($"{where}: expected 'joint name = Bone', got '{lines[i].Trim()}'");
            if (!Enum.TryParse(boneName, true, out HumanoidBone bone) || bone == HumanoidBone.LastBone || int.TryParse(boneName, out _))
                throw new FormatException($"{where}: '{boneName}' is not a humanoid bone (Hips, Spine, LeftUpperArm, …)");
            if (map.ContainsKey(joint)) throw new FormatException($"{where}: joint '{joint}' is given twice");
            if (!bones.Add(bone)) throw new FormatException($"{where}: {bone} is given twice");
            map[joint] = bone;
        }
        return map;
    }

    /// <summary>
    /// The humanoid map of <paramref name="clip"/>: found from the names, or from the hierarchy and the motion when the
    /// names leave a required bone unfound (<see cref="HumanoidDetection"/>), with the bones of <paramref name="path"/>
    /// (none when null) first. <paramref name="note"/> says when the names did not find it (null when they did).
    /// </summary>
    /// <exception cref="ArgumentException">The file names a joint the skeleton does not have.</exception>
    public static HumanoidMap Detect(BvhClip clip, string path, out string note) =>
        HumanoidDetection.Detect(clip, path == null ? null : Read(path), out note);
}
