using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>
/// The valid files mutations start from: the package's own mocap clips (Tests/Core/Data~), a session simulated from
/// one of them, the calibration profile saved from calibrating that session, and the bundled controller profiles
/// (Runtime/ControllerProfiles). Files are cut short (a few frames) so that a million inputs take minutes, not hours;
/// what matters most (headers, hierarchies, every kind of line) is all there.
/// </summary>
internal sealed class FuzzSeeds
{
    private const int FramesKept = 3;
    private readonly string _root;
    private string _session;
    private string _profile;

    public FuzzSeeds(string packageRoot = null)
    {
        _root = packageRoot ?? FindPackageRoot();
    }

    /// <summary>The package root: the folder holding Runtime/ControllerProfiles and Tests/Core/Data~, above the tool.</summary>
    public static string FindPackageRoot()
    {
        foreach (string start in new[] { AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
            for (string dir = start; dir != null; dir = Path.GetDirectoryName(dir))
                if (Directory.Exists(Path.Combine(dir, "Runtime", "ControllerProfiles")) && Directory.Exists(Path.Combine(dir, "Tests", "Core", "Data~")))
                    return dir;
        throw new DirectoryNotFoundException("the package (Runtime/ControllerProfiles, Tests/Core/Data~) was not found above the tool's folder");
    }

    /// <summary>The package's default fuzz corpus folder.</summary>
    public string DefaultCorpus => Path.Combine(_root, "Tests", "Core", "Data~", "fuzz-corpus");

    private string Data(string file) => Path.Combine(_root, "Tests", "Core", "Data~", file);

    public IReadOnlyList<string> Bvh()
    {
        var seeds = new List<string>();
        foreach (string file in Directory.GetFiles(Path.Combine(_root, "Tests", "Core", "Data~"), "*.bvh").OrderBy(f => f, StringComparer.Ordinal))
        {
            string text = File.ReadAllText(file);
            seeds.Add(KeepFrames(text, FramesKept));
            seeds.Add(KeepFrames(text, 0));
        }
        return seeds;
    }

    /// <summary>The BVH text with only its first <paramref name="frames"/> frames (and its 'Frames:' line saying so).</summary>
    private static string KeepFrames(string bvh, int frames)
    {
        string[] lines = bvh.Replace("\r\n", "\n").Split('\n');
        var sb = new StringBuilder();
        int i = 0;
        for (; i < lines.Length; i++)
        {
            string t = lines[i].Trim();
            if (t.StartsWith("Frames:", StringComparison.OrdinalIgnoreCase)) { sb.Append("Frames: ").Append(frames).Append('\n'); continue; }
            sb.Append(lines[i]).Append('\n');
            if (t.StartsWith("Frame Time:", StringComparison.OrdinalIgnoreCase)) { i++; break; }
        }
        for (int f = 0; f < frames && i < lines.Length; f++, i++) sb.Append(lines[i]).Append('\n');
        return sb.ToString();
    }

    public IReadOnlyList<string> Sessions()
    {
        string full = SimulatedSession();
        var seeds = new List<string> { CutSession(full, new[] { 0, 1, 2 }, decorate: false), CutSession(full, new[] { 0, 1, 2 }, decorate: true) };
        // The frames around the first trigger press (its event line), decorated with inputs, lost poses and comments.
        using (var reader = new SessionReader(new StringReader(full), "sim"))
        {
            SessionFrame f = reader.CreateFrame();
            int index = 0;
            while (reader.ReadFrame(f) && f.Events.Count == 0) index++;
            seeds.Add(CutSession(full, new[] { index - 1, index, index + 1 }, decorate: true));
        }
        // A header without ground truth.
        var h = new SessionHeader(72f, new[] { new DeviceInfo(0, DeviceClass.Hmd, "HMD-1"), new DeviceInfo(7, DeviceClass.Controller, "C-7", DeviceRole.LeftHand) });
        var text = new StringWriter();
        using (var w = new SessionWriter(text, h))
        {
            var frame = new SessionFrame(h);
            for (int i = 0; i < 3; i++)
            {
                frame.Clear();
                frame.Time = i / 72.0;
                frame.Samples[0] = new DeviceSample(new RigidPose(new Vector3(0, 1.7f, 0), Quaternion.Identity), true);
                frame.Samples[1] = new DeviceSample(new RigidPose(new Vector3(-0.7f, 1.4f, 0.1f), Rotations.AngleAxis(30, Vector3.UnitY)), i != 1);
                frame.Trigger[1] = i * 0.4f;
                if (i == 2) frame.Events.Add(new DeviceEvent(7, DeviceEventKind.TriggerPressed));
                w.WriteFrame(frame);
            }
        }
        seeds.Add(text.ToString());
        return seeds;
    }

    // A session with only the frames at `indices` (in order), and, when decorated, analog input, a lost pose and comments.
    private static string CutSession(string full, int[] indices, bool decorate)
    {
        using var reader = new SessionReader(new StringReader(full), "sim");
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, reader.Header))
        {
            SessionFrame f = reader.CreateFrame();
            int index = 0, next = 0;
            while (next < indices.Length && reader.ReadFrame(f))
            {
                if (index++ != indices[next]) continue;
                if (decorate)
                {
                    f.Trigger[1] = 0.25f * next;
                    f.Grip[2] = 1f;
                    if (next == 1) f.Samples[5] = new DeviceSample(f.Samples[5].Pose, false);
                }
                writer.WriteFrame(f);
                next++;
            }
        }
        string s = text.ToString();
        if (decorate) s = s.Replace("units m s\n", "# comment\nunits m s\r\n").Replace("end-header\n", "end-header\n\n   # indented comment\n");
        return s;
    }

    private string SimulatedSession()
    {
        if (_session != null) return _session;
        BvhClip clip = BvhReader.ReadFile(Data("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 3 });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        return _session = text.ToString();
    }

    public IReadOnlyList<string> Profiles()
    {
        if (_profile == null)
        {
            using var reader = new SessionReader(new StringReader(SimulatedSession()), "sim");
            var calibrator = new Calibrator(reader.Header.Devices, reader.Header.TruthHumanoid);
            SessionFrame f = reader.CreateFrame();
            while (calibrator.State != CalibrationState.Calibrated && reader.ReadFrame(f)) calibrator.Update(f.Time, f.Samples, f.Events);
            if (calibrator.State != CalibrationState.Calibrated) throw new InvalidOperationException("the seed session does not calibrate: " + calibrator.LastStep.Message);
            _profile = CalibrationProfileStore.ToJson(calibrator.Profile);
        }
        return new[] { _profile, CalibrationProfileStore.ToJson(CalibrationProfileStore.FromJson(_profile).WithFixedOffsets()) };
    }

    public IReadOnlyList<string> Controllers() =>
        Directory.GetFiles(Path.Combine(_root, "Runtime", "ControllerProfiles"), "*.json").OrderBy(f => f, StringComparer.Ordinal).Select(File.ReadAllText).ToList();

    public IReadOnlyList<string> Json()
    {
        var seeds = new List<string>(Controllers());
        seeds.AddRange(Profiles());
        seeds.Add("{\"a\": [1, -2.5e2, 0, 0.125, 1E-3, true, false, null], \"s\": \"x\\\"\\\\\\/\\b\\f\\n\\r\\t\\u00e9\\uD83D\\uDE00\", \"o\": {\"p\": {}}, \"e\": []}\n");
        return seeds;
    }

    /// <summary>The avatar restored profiles are tried on: the bundled mocap clip's skeleton.</summary>
    public static HumanoidMap Avatar()
    {
        string clip = Path.Combine(FindPackageRoot(), "Tests", "Core", "Data~", "mocapbank_30fps.bvh");
        return HumanoidNaming.Detect(BvhReader.ReadFile(clip, new BvhReadOptions { ToMetres = true }).Skeleton);
    }
}
