using System;
using System.Collections.Generic;
using System.Linq;
using System.Text;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// Hand-made edge cases per target (deep nesting, huge counts, absurd numbers, long lines: what random mutation
/// rarely reaches) and the tokens of each format that mutations insert.
/// </summary>
internal static class CraftedInputs
{
    /// <summary>Numbers at the edges: of float and double, of int, of what a human body or a tracking space can be.</summary>
    public static readonly string[] Numbers =
    {
        "0", "-0", "1", "-1", "0.5", "2", "1e39", "-1e39", "1e-50", "1e308", "1e309", "-1e309", "3.4028235e38", "3.4028236e38",
        "1.4e-45", "1e-45", "NaN", "nan", "Infinity", "-Infinity", "inf", "2147483647", "2147483648", "-2147483648", "-2147483649",
        "4294967296", "99999999999999999999", "1e5", "1e7", "1e10", "1e20", "65536", "65537", "1024", "1025", "0x10", "1,5", "+1", ".5",
        "5.", "1e", "--1", "1e+", "\u0661", "\uFF11", "0.000001", "1e-7", "360", "-360", "1e30", "100001", "6", "7", "-0.0",
        new string('9', 400), "1." + new string('0', 400) + "1", "0." + new string('0', 400) + "1",
    };

    public static readonly string[] BvhDictionary =
    {
        "HIERARCHY", "ROOT", "JOINT", "End", "Site", "End Site", "{", "}", "OFFSET", "CHANNELS", "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",
        "CHANNELS 3 Zrotation Xrotation Yrotation", "CHANNELS 0", "Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation",
        "MOTION", "Frames:", "Frame Time:", "OFFSET 0 0 0", "JOINT Hips\n{\nOFFSET 0 1 0\nCHANNELS 3 Xrotation Yrotation Zrotation\n}",
        "End Site\n{\nOFFSET 0 1 0\n}", "Hips", "LeftHand", "Left Arm", "mixamorig:Head",
    };

    public static readonly string[] SessionDictionary =
    {
        "avatargo-session 1.0", "avatargo-session 1.9", "avatargo-session 2.0", "units m s", "handedness left y-up z-forward", "rate 90",
        "device", "device 9 tracker T-9 none", "truth-role", "truth-role 0 head", "truth-joint", "truth-joint 0 -1 Hips joint Hips 0 1 0 0 0 0 1",
        "end-header", "frame", "frame 0", "pose", "pose 0 tracked 0 1.7 0 0 0 0 1", "pose 0 lost 0 0 0 0 0 0 0", "tracked", "lost", "input", "input 1 0.5 -",
        "event", "event 1 trigger-pressed", "trigger-pressed", "trigger-released", "truth", "truth Head 0 1.6 0 0 0 0 1", "end", "end 0", "#", "-",
        "hmd", "controller", "tracker", "none", "head", "left-hand", "right-hand", "pelvis", "left-foot", "right-foot", "Hips", "LeftHand", "LastBone", "joint",
    };

    private static readonly string[] JsonCommon =
    {
        "{", "}", "[", "]", ",", ":", "\"", "\\", "\\u", "\\uD83D", "\\uDE00", "\\u0000", "true", "false", "null", "{}", "[]", "\"\"", "[[[[", "]]]]",
        "\"format\"", "\"version\"", "1", "\"x\": 1,",
    };

    public static readonly string[] JsonDictionary = JsonCommon;

    public static readonly string[] ProfileDictionary = JsonCommon.Concat(new[]
    {
        "\"avatarScale\"", "\"wearerEyeHeight\"", "\"avatarEyeHeight\"", "\"floorHeight\"", "\"placement\"", "\"rootToHead\"", "\"roles\"", "\"mode\"",
        "\"exact\"", "\"fixed\"", "\"head\"", "\"leftHand\"", "\"pelvis\"", "\"deviceId\"", "\"serial\"", "\"deviceAtCalibration\"", "\"jointAtCalibration\"",
        "\"jointInDevice\"", "\"position\"", "\"rotation\"", "[0, 0, 0]", "[0, 0, 0, 1]", "[0, 0, 0, 0]", "\"avatargo-calibration-profile\"",
    }).ToArray();

    public static readonly string[] ControllerDictionary = JsonCommon.Concat(new[]
    {
        "\"shapes\"", "\"type\"", "\"capsule\"", "\"sphere\"", "\"box\"", "\"roundedBox\"", "\"a\"", "\"b\"", "\"radius\"", "\"centre\"", "\"halfExtents\"",
        "\"eulerDegrees\"", "\"trigger\"", "\"thumbRest\"", "\"name\"", "\"displayName\"", "[0, 0, 0]", "[1e39, 0, 0]", "\"avatargo-controller-profile\"",
        "{ \"type\": \"sphere\", \"centre\": [0, 0, 0], \"radius\": 0.01 },",
    }).ToArray();

    // ---- BVH -----------------------------------------------------------------------------------------

    private const string Channels3 = "CHANNELS 3 Zrotation Xrotation Yrotation";
    private const string Channels6 = "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation";

    private static string BvhHeader(string rootChannels = Channels6) => $"HIERARCHY\nROOT Hips\n{{\n\tOFFSET 0 0 0\n\t{rootChannels}\n";

    private static string Motion(int frames, string frameTime, int channels, int frameLines)
    {
        var sb = new StringBuilder($"MOTION\nFrames: {frames}\nFrame Time: {frameTime}\n");
        string line = string.Join(" ", Enumerable.Repeat("0", channels));
        for (int f = 0; f < frameLines; f++) sb.Append(line).Append('\n');
        return sb.ToString();
    }

    public static IEnumerable<CraftedInput> Bvh(IReadOnlyList<string> seeds)
    {
        foreach (int depth in new[] { 1000, 20000, 100000 })
        {
            var sb = new StringBuilder(BvhHeader());
            for (int i = 0; i < depth; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\n").Append(Channels3).Append('\n');
            sb.Append(new string('}', 0));
            for (int i = 0; i < depth; i++) sb.Append("}\n");
            sb.Append("}\n").Append(Motion(1, "0.033", 6 + 3 * depth, 1));
            yield return new CraftedInput($"nested {depth} joints deep", sb.ToString());
        }
        foreach (int count in new[] { 20000, 100000 })
        {
            var sb = new StringBuilder(BvhHeader());
            for (int i = 0; i < count; i++) sb.Append("End Site\n{\nOFFSET 0 1 0\n}\n");
            sb.Append("}\n").Append(Motion(1, "0.033", 6, 1));
            yield return new CraftedInput($"{count} End Sites under one joint", sb.ToString());
        }
        {
            var sb = new StringBuilder(BvhHeader());
            for (int i = 0; i < 100000; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\n");
            sb.Append("}\n").Append(Motion(2, "0.033", 6, 2));
            yield return new CraftedInput("100000 sibling joints", sb.ToString());
        }
        {
            var sb = new StringBuilder(BvhHeader());
            for (int i = 0; i < 2000; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\n").Append(Channels6).Append("\n}\n");
            sb.Append("}\n").Append(Motion(2000000000, "0.033", 6 + 6 * 2000, 1));
            yield return new CraftedInput("a header claiming 2e9 frames of 12006 channels", sb.ToString());
        }
        {
            var sb = new StringBuilder(BvhHeader());
            for (int i = 0; i < 100000; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\n").Append(Channels6).Append("\n}\n");
            sb.Append("}\n").Append(Motion(int.MaxValue, "0.033", 6, 0)).Append("0 0 0\n");
            yield return new CraftedInput("int.MaxValue frames of 600006 channels", sb.ToString());
        }
        yield return new CraftedInput("Frames: 0", BvhHeader() + "}\n" + Motion(0, "0.033", 6, 0));
        yield return new CraftedInput("Frames: -1", BvhHeader() + "}\n" + Motion(-1, "0.033", 6, 0));
        foreach (string time in new[] { "0", "-0", "1e-45", "1e38", "1e-30", "3600", "Infinity", "1e39" })
            yield return new CraftedInput($"Frame Time: {time}", BvhHeader() + "}\n" + Motion(2, time, 6, 2));
        foreach (string number in new[] { "1e38", "3.4e38", "-3.4e38", "1e30", "1e20" })
        {
            var sb = new StringBuilder(BvhHeader().Replace("OFFSET 0 0 0", $"OFFSET {number} {number} {number}"));
            for (int i = 0; i < 8; i++) sb.Append("JOINT j").Append(i).Append($"\n{{\nOFFSET {number} {number} 0\n").Append(Channels6).Append('\n');
            for (int i = 0; i < 8; i++) sb.Append("}\n");
            sb.Append("}\nMOTION\nFrames: 1\nFrame Time: 0.033\n").Append(string.Join(" ", Enumerable.Repeat(number, 54))).Append('\n');
            yield return new CraftedInput($"offsets and positions of {number}", sb.ToString());
        }
        yield return new CraftedInput("a 20 MB frame line", BvhHeader() + "}\nMOTION\nFrames: 1\nFrame Time: 0.033\n" + new string('0', 20 << 20) + "\n");
        yield return new CraftedInput("a 20 MB joint name", BvhHeader().Replace("ROOT Hips", "ROOT " + new string('H', 20 << 20)) + "}\n" + Motion(1, "0.033", 6, 1));
        yield return new CraftedInput("a million blank lines", BvhHeader() + new string('\n', 1000000) + "}\n" + Motion(1, "0.033", 6, 1));
        yield return new CraftedInput("a million frames of one channel", "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 1 Xrotation\n}\n" + Motion(1000000, "0.01", 1, 1000000));
        yield return new CraftedInput("CR line ends", (BvhHeader() + "}\n" + Motion(2, "0.033", 6, 2)).Replace('\n', '\r'));
        yield return new CraftedInput("a byte-order mark and NULs", "\uFEFF" + BvhHeader() + "\0}\n" + Motion(1, "0.033", 6, 1));
        yield return new CraftedInput("a second ROOT", BvhHeader() + "}\n" + BvhHeader() + "}\n" + Motion(1, "0.033", 12, 1));
        yield return new CraftedInput("empty", "");
        yield return new CraftedInput("white space", " \t\r\n\u00A0\u2028");
    }

    // ---- Sessions --------------------------------------------------------------------------------------

    private const string SessionStart = "avatargo-session 1.0\nunits m s\nhandedness left y-up z-forward\nrate 90\n";

    public static IEnumerable<CraftedInput> Session(IReadOnlyList<string> seeds)
    {
        foreach (int count in new[] { 10000, 100000 })
        {
            var sb = new StringBuilder(SessionStart);
            for (int i = 0; i < count; i++) sb.Append("device ").Append(i).Append(" tracker S").Append(i).Append(" none\n");
            for (int i = 0; i < count; i++) sb.Append("truth-role ").Append(i).Append(" none\n");
            sb.Append("end-header\nframe 0\n");
            for (int i = 0; i < count; i++) sb.Append("pose ").Append(i).Append(" tracked 0 1 0 0 0 0 1\n");
            sb.Append("end 1\n");
            yield return new CraftedInput($"{count} devices", sb.ToString());
        }
        foreach (int count in new[] { 10000, 100000 })
        {
            var sb = new StringBuilder(SessionStart + "device 0 hmd H none\n");
            for (int i = 0; i < count; i++) sb.Append("truth-joint ").Append(i).Append(' ').Append(i - 1).Append(" - joint J").Append(i).Append(" 0 0.01 0 0 0 0 1\n");
            sb.Append("end-header\nframe 0\npose 0 tracked 0 1 0 0 0 0 1\nend 1\n");
            yield return new CraftedInput($"{count} truth joints in a chain", sb.ToString());
        }
        {
            var sb = new StringBuilder(SessionStart + "device 0 hmd H none\nend-header\nframe 0\npose 0 tracked 0 1 0 0 0 0 1\n");
            for (int i = 0; i < 200000; i++) sb.Append("event 0 trigger-pressed\n");
            sb.Append("end 1\n");
            yield return new CraftedInput("200000 events in one frame", sb.ToString());
        }
        foreach (string rate in new[] { "1e-45", "1e-30", "3.4e38", "1e10", "0.001" })
            yield return new CraftedInput($"rate {rate}", SessionStart.Replace("rate 90", "rate " + rate) + "device 0 hmd H none\nend-header\nframe 0\npose 0 tracked 0 1 0 0 0 0 1\nend 1\n");
        foreach (string time in new[] { "1e300", "-1e300", "1e20", "1.7976931348623157e308" })
            yield return new CraftedInput($"time {time}", SessionStart + "device 0 hmd H none\nend-header\nframe " + time + "\npose 0 tracked 0 1 0 0 0 0 1\nend 1\n");
        foreach (string p in new[] { "3e38", "1e30", "1e20" })
            yield return new CraftedInput($"positions of {p}", SessionStart + "device 0 hmd H none\ntruth-joint 0 -1 Hips joint Hips " + p + " " + p + " 0 0 0 0 1\nend-header\nframe 0\npose 0 tracked " + p + " " + p + " 0 0 0 0 1\ntruth Hips " + p + " 0 0 0 0 0 1\nend 1\n");
        yield return new CraftedInput("a 5 MB line", SessionStart + "# " + new string('x', 5 << 20) + "\n");
        yield return new CraftedInput("a million comment lines", SessionStart + string.Concat(Enumerable.Repeat("#\n", 1000000)) + "device 0 hmd H none\nend-header\nend 0\n");
        yield return new CraftedInput("a newer minor version with a million unknown lines", SessionStart.Replace("1.0", "1.5") + string.Concat(Enumerable.Repeat("colour 0 red\n", 1000000)) + "device 0 hmd H none\nend-header\nend 0\n");
        yield return new CraftedInput("NUL and a byte-order mark", "\uFEFF" + SessionStart + "\0device 0 hmd H none\nend-header\nend 0\n");
        yield return new CraftedInput("empty", "");
    }

    // ---- JSON, profiles, controllers ---------------------------------------------------------------------

    public static IEnumerable<CraftedInput> Json(IReadOnlyList<string> seeds)
    {
        yield return new CraftedInput("100000 nested arrays", new string('[', 100000) + new string(']', 100000));
        yield return new CraftedInput("100000 nested objects", string.Concat(Enumerable.Repeat("{\"a\":", 100000)) + "1" + new string('}', 100000));
        yield return new CraftedInput("a 20 MB string", "[\"" + new string('x', 20 << 20) + "\"]");
        yield return new CraftedInput("a 1 MB number", "[" + new string('1', 1 << 20) + "]");
        yield return new CraftedInput("a 1 MB fraction", "[0." + new string('1', 1 << 20) + "]");
        yield return new CraftedInput("100000 members", "{" + string.Join(",", Enumerable.Range(0, 100000).Select(i => $"\"k{i}\": {i}")) + "}");
        yield return new CraftedInput("500000 items", "[" + string.Join(",", Enumerable.Repeat("0", 500000)) + "]");
        yield return new CraftedInput("unpaired surrogates", "[\"\\uD83D\", \"\\uDE00x\", \"\\uD83D\\u0041\"]");
        yield return new CraftedInput("empty", "");
    }

    public static IEnumerable<CraftedInput> Profile(IReadOnlyList<string> seeds)
    {
        foreach (CraftedInput c in Json(seeds)) yield return c;
        string p = seeds[0];
        foreach (string member in new[] { "avatarScale", "wearerEyeHeight", "avatarEyeHeight", "floorHeight" })
            foreach (string v in new[] { "1e39", "-1e39", "1e-50", "0", "-1", "1e30", "1e300", "3.4e38" })
                yield return new CraftedInput($"{member} {v}", ReplaceNumber(p, member, v));
        foreach (string v in new[] { "1e39", "1e30", "1e20", "3e38" })
        {
            yield return new CraftedInput($"positions of {v}", p.Replace("\"position\": [", $"\"position\": [{v}, {v}, {v}], \"was\": ["));
            yield return new CraftedInput($"rootToHead of {v}", p.Replace("\"rootToHead\": [", $"\"rootToHead\": [{v}, {v}, {v}], \"was\": ["));
        }
        foreach (string v in new[] { "1e10", "-1", "2.5", "2147483648", "1e300", "-0" })
            yield return new CraftedInput($"deviceId {v}", ReplaceNumber(p, "deviceId", v));
        yield return new CraftedInput("a 20 MB serial", ReplaceString(p, "serial", new string('s', 20 << 20)));
        yield return new CraftedInput("an unpaired surrogate in a serial", ReplaceString(p, "serial", "\\uD83D"));
        yield return new CraftedInput("every serial empty", System.Text.RegularExpressions.Regex.Replace(p, "\"serial\": \"[^\"]*\"", "\"serial\": \"\""));
        yield return new CraftedInput("every serial the same", System.Text.RegularExpressions.Regex.Replace(p, "\"serial\": \"[^\"]*\"", "\"serial\": \"X\""));
    }

    public static IEnumerable<CraftedInput> Controller(IReadOnlyList<string> seeds)
    {
        foreach (CraftedInput c in Json(seeds)) yield return c;
        string c0 = seeds[0];
        foreach (string v in new[] { "1e39", "-1", "1e30", "1e-50", "2", "1e300" })
            yield return new CraftedInput($"radius {v}", ReplaceNumber(c0, "radius", v));
        foreach (string v in new[] { "1e39", "1e30", "1e20", "3e38", "-3e38" })
        {
            yield return new CraftedInput($"points of {v}", c0.Replace("\"trigger\": [", $"\"trigger\": [{v}, {v}, {v}], \"was\": [").Replace("\"a\": [", $"\"a\": [{v}, 0, 0], \"was\": ["));
            yield return new CraftedInput($"a box of {v}", c0.Replace("\"shapes\": [", $"\"shapes\": [{{ \"type\": \"box\", \"centre\": [0, 0, 0], \"halfExtents\": [{v}, {v}, {v}], \"eulerDegrees\": [{v}, {v}, {v}] }},"));
        }
        yield return new CraftedInput("a box with negative half extents", c0.Replace("\"shapes\": [", "\"shapes\": [{ \"type\": \"box\", \"centre\": [0, 0, 0], \"halfExtents\": [-1, -1, -1] },"));
        yield return new CraftedInput("100000 shapes", c0.Replace("\"shapes\": [", "\"shapes\": [" + string.Concat(Enumerable.Repeat("{ \"type\": \"sphere\", \"centre\": [0, 0, 0], \"radius\": 0.01 },", 100000))));
        yield return new CraftedInput("shapes that are not objects", c0.Replace("\"shapes\": [", "\"shapes\": [1, [], null, \"x\","));
    }

    private static string ReplaceNumber(string json, string member, string value) =>
        System.Text.RegularExpressions.Regex.Replace(json, $"\"{member}\": -?[0-9.eE+-]+", $"\"{member}\": {value}");

    private static string ReplaceString(string json, string member, string value) =>
        System.Text.RegularExpressions.Regex.Replace(json, $"\"{member}\": \"[^\"]*\"", $"\"{member}\": \"{value}\"");
}
