using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// The parsers under fuzzing and their oracles. Parsing may refuse an input only with a one-line
/// <see cref="FormatException"/>; what it accepts must then survive what the package does with it next (poses
/// computed, a humanoid map found, a profile restored and solved, a controller's surface evaluated, the value written
/// back and read again), with no exception and no NaN or infinity.
/// </summary>
internal static class FuzzTargets
{
    public static readonly string[] Names = { "bvh", "session", "profile", "controller", "json" };

    private const int LineFormatLength = 4 << 20;
    private const int JsonLength = 3 << 19;

    /// <summary>The target's corpus extension from a corpus file name, or null when the name fits no target.</summary>
    public static string TargetOfFile(string fileName)
    {
        if (fileName.EndsWith(".bvh", StringComparison.OrdinalIgnoreCase)) return "bvh";
        if (fileName.EndsWith(".agsession", StringComparison.OrdinalIgnoreCase)) return "session";
        if (fileName.EndsWith(".profile.json", StringComparison.OrdinalIgnoreCase)) return "profile";
        if (fileName.EndsWith(".controller.json", StringComparison.OrdinalIgnoreCase)) return "controller";
        if (fileName.EndsWith(".json", StringComparison.OrdinalIgnoreCase)) return "json";
        return null;
    }

    /// <summary>The target named <paramref name="name"/>, with its seeds (which <paramref name="seeds"/> provides).</summary>
    public static FuzzTarget Create(string name, FuzzSeeds seeds)
    {
        switch (name)
        {
            case "bvh": return new FuzzTarget(name, ".bvh", ParseBvh, UseBvh, seeds.Bvh(), CraftedInputs.BvhDictionary, CraftedInputs.Bvh, LineFormatLength);
            case "session": return new FuzzTarget(name, ".agsession", ParseSession, UseSession, seeds.Sessions(), CraftedInputs.SessionDictionary, CraftedInputs.Session, LineFormatLength);
            case "profile": return new FuzzTarget(name, ".profile.json", ParseProfile, UseProfile, seeds.Profiles(), CraftedInputs.ProfileDictionary, CraftedInputs.Profile, JsonLength);
            case "controller": return new FuzzTarget(name, ".controller.json", ParseController, UseController, seeds.Controllers(), CraftedInputs.ControllerDictionary, CraftedInputs.Controller, JsonLength);
            case "json": return new FuzzTarget(name, ".json", ParseJson, UseJson, seeds.Json(), CraftedInputs.JsonDictionary, CraftedInputs.Json, JsonLength);
            default: throw new UsageException($"--target must be one of {string.Join(", ", Names)} or all, got '{name}'");
        }
    }

    /// <summary>A target without seeds, for checking corpus files (its oracle only).</summary>
    public static FuzzTarget ForChecking(string name) => name switch
    {
        "bvh" => new FuzzTarget(name, ".bvh", ParseBvh, UseBvh, Array.Empty<string>(), Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 0),
        "session" => new FuzzTarget(name, ".agsession", ParseSession, UseSession, Array.Empty<string>(), Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 0),
        "profile" => new FuzzTarget(name, ".profile.json", ParseProfile, UseProfile, Array.Empty<string>(), Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 0),
        "controller" => new FuzzTarget(name, ".controller.json", ParseController, UseController, Array.Empty<string>(), Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 0),
        "json" => new FuzzTarget(name, ".json", ParseJson, UseJson, Array.Empty<string>(), Array.Empty<string>(), _ => Array.Empty<CraftedInput>(), 0),
        _ => throw new ArgumentException($"unknown fuzz target '{name}'", nameof(name)),
    };

    // ---- BVH ---------------------------------------------------------------------------------------

    private static object ParseBvh(string text) => BvhReader.Read(new StringReader(text), "fuzz.bvh");

    private static void UseBvh(object parsed)
    {
        var clip = (BvhClip)parsed;
        // What `avatargo bvh info`, `simulate` and `evaluate --avatar` do with a clip: metres, poses, a humanoid map.
        float metresPerUnit = clip.GuessMetresPerUnit();
        if (!(metresPerUnit > 0f)) throw new FuzzFailure("bad metres per unit", $"GuessMetresPerUnit gave {metresPerUnit}");
        BvhClip metres = clip.WithScale(metresPerUnit);
        int n = metres.Skeleton.JointCount;
        var local = new RigidPose[n];
        var world = new RigidPose[n];
        for (int f = 0; f < Math.Min(metres.FrameCount, 3); f++)
        {
            metres.GetWorldPoses(f, local, world);
            for (int j = 0; j < n; j++)
                if (!Vectors.IsFinite(world[j].Position) || !Rotations.IsFinite(world[j].Rotation))
                    throw new FuzzFailure("non-finite world pose", $"frame {f}: joint {metres.Skeleton.GetName(j)} has a non-finite world pose {world[j]}");
        }
        // The names, and where they fall short the hierarchy and the motion (HumanoidStructure), as `simulate` reads them.
        HumanoidDetection.Detect(metres, null, out _);
        // Written back, it reads again as the same clip.
        var text = new StringWriter();
        BvhWriter.Write(text, clip);
        BvhClip again;
        try { again = BvhReader.Read(new StringReader(text.ToString()), "written.bvh"); }
        catch (FormatException e) { throw new FuzzFailure("BvhWriter output does not read back", "BvhWriter's output does not read back: " + e.Message, e); }
        if (again.Skeleton.JointCount != clip.Skeleton.JointCount || again.FrameCount != clip.FrameCount || again.ChannelCount != clip.ChannelCount)
            throw new FuzzFailure("BvhWriter round trip differs", "BvhWriter's output reads back as another clip");
    }

    // ---- Sessions ----------------------------------------------------------------------------------

    private static object ParseSession(string text)
    {
        // The whole file: header and every frame (a session is read as a stream, but all of it is content).
        using var reader = new SessionReader(new StringReader(text), "fuzz.agsession");
        var frames = new List<SessionFrame>();
        SessionFrame frame = reader.CreateFrame();
        while (reader.ReadFrame(frame))
        {
            if (frames.Count < 4) frames.Add(Copy(frame, reader.Header));
        }
        return (reader.Header, frames, reader.FrameCount);
    }

    private static void UseSession(object parsed)
    {
        var (header, frames, count) = ((SessionHeader, List<SessionFrame>, int))parsed;
        foreach (SessionFrame f in frames)
            for (int d = 0; d < f.Samples.Length; d++)
                if (!f.Samples[d].Pose.IsValid) throw new FuzzFailure("invalid pose delivered", $"device {header.Devices[d].Id}: the reader delivered an invalid pose {f.Samples[d].Pose}");
        // Written back, the frames read again.
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, header))
            foreach (SessionFrame f in frames) writer.WriteFrame(f);
        try
        {
            using var reader = new SessionReader(new StringReader(text.ToString()), "written.agsession");
            SessionFrame frame = reader.CreateFrame();
            int n = 0;
            while (reader.ReadFrame(frame)) n++;
            if (n != frames.Count || reader.Header.Devices.Count != header.Devices.Count) throw new FuzzFailure("SessionWriter round trip differs", "SessionWriter's output reads back as another session");
        }
        catch (FormatException e) { throw new FuzzFailure("SessionWriter output does not read back", "SessionWriter's output does not read back: " + e.Message, e); }
        _ = count;
    }

    private static SessionFrame Copy(SessionFrame f, SessionHeader header)
    {
        var c = new SessionFrame(header) { Time = f.Time };
        Array.Copy(f.Samples, c.Samples, f.Samples.Length);
        Array.Copy(f.Trigger, c.Trigger, f.Trigger.Length);
        Array.Copy(f.Grip, c.Grip, f.Grip.Length);
        Array.Copy(f.Truth, c.Truth, f.Truth.Length);
        Array.Copy(f.HasTruth, c.HasTruth, f.HasTruth.Length);
        c.Events.AddRange(f.Events);
        return c;
    }

    // ---- Calibration profiles ----------------------------------------------------------------------

    private static object ParseProfile(string text) => CalibrationProfileStore.FromJson(text, "fuzz.profile.json");

    private static HumanoidMap _avatar;

    private static void UseProfile(object parsed)
    {
        var profile = (CalibrationProfile)parsed;
        // Saved again, it loads again.
        string json = CalibrationProfileStore.ToJson(profile);
        try { CalibrationProfileStore.FromJson(json); }
        catch (FormatException e) { throw new FuzzFailure("ToJson output does not load back", "ToJson's output does not load back: " + e.Message, e); }
        profile.WithFixedOffsets();
        profile.WithAvatarScale(profile.AvatarScale);

        // Restored on the devices it names (by serial) and solved for one frame, as an app does at start-up.
        var devices = new DeviceInfo[BodyRoles.All.Length];
        var samples = new DeviceSample[devices.Length];
        for (int i = 0; i < devices.Length; i++)
        {
            DeviceRole role = BodyRoles.All[i];
            DeviceClass c = role == DeviceRole.Head ? DeviceClass.Hmd : role == DeviceRole.LeftHand || role == DeviceRole.RightHand ? DeviceClass.Controller : DeviceClass.Tracker;
            devices[i] = new DeviceInfo(100 + i, c, profile.Serial(role));
            samples[i] = new DeviceSample(profile.DeviceAtCalibration(role), true);
        }
        _avatar ??= FuzzSeeds.Avatar();
        var pipeline = new SelfAvatarPipeline(devices, _avatar);
        if (!pipeline.TryRestore(profile)) return; // a profile whose serials repeat or are empty matches no device set
        pipeline.Update(0, samples, new float[devices.Length], new float[devices.Length], Array.Empty<DeviceEvent>());
        BodyTargets targets = pipeline.Targets;
        foreach (RigidPose p in new[] { targets.Hips, targets.Head, targets.LeftHand.Goal, targets.RightHand.Goal, targets.LeftFoot.Goal, targets.RightFoot.Goal })
            if (!Vectors.IsFinite(p.Position) || !Rotations.IsFinite(p.Rotation)) throw new FuzzFailure("non-finite solved target", $"a restored profile solves to a non-finite target {p}");
        SkeletonPose pose = pipeline.Pose;
        for (int j = 0; j < pose.Skeleton.JointCount; j++)
            if (!Vectors.IsFinite(pose.World[j].Position) || !Rotations.IsFinite(pose.World[j].Rotation)) throw new FuzzFailure("non-finite bone", $"a restored profile puts joint {pose.Skeleton.GetName(j)} at a non-finite pose");
    }

    // ---- Controller profiles -----------------------------------------------------------------------

    private static object ParseController(string text) => ControllerProfile.Parse(text, "fuzz.controller.json");

    private static void UseController(object parsed)
    {
        var profile = (ControllerProfile)parsed;
        foreach (Vector3 p in new[] { Vector3.Zero, profile.Trigger, profile.ThumbRest, new Vector3(0.05f, 0.02f, -0.03f) })
        {
            float d = profile.Shape.Evaluate(p, out Vector3 gradient);
            if (!Vectors.IsFinite(d) || !Vectors.IsFinite(gradient)) throw new FuzzFailure("non-finite surface distance", $"the surface's distance at {p} is {d}, gradient {gradient}");
        }
    }

    // ---- JSON ---------------------------------------------------------------------------------------

    private static object ParseJson(string text) => JsonNode.Parse(text, "fuzz.json");

    private static void UseJson(object parsed)
    {
        // Walk the whole tree (without recursion) and read every value the typed getters can.
        var stack = new Stack<JsonNode>();
        stack.Push((JsonNode)parsed);
        while (stack.Count > 0)
        {
            JsonNode node = stack.Pop();
            if (node.Kind == JsonKind.Number && !double.IsFinite(node.Number)) throw new FuzzFailure("non-finite JSON number", $"a JSON number parsed as {node.Number}");
            foreach (JsonNode item in node.Items) stack.Push(item);
            foreach (string key in node.Keys) stack.Push(node[key]);
        }
    }
}
