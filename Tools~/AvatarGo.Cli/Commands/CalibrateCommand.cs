using System;
using System.Globalization;
using System.IO;
using System.Text.Json;
using AvatarGo.Core;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo calibrate SESSION`: runs the calibration flow over a session and prints the outcome.</summary>
public sealed class CalibrateCommand : ICommand
{
    public string Name => "calibrate";
    public string Summary => "Run the Walk-In-Avatar calibration over a session and print roles, scale and offsets";
    public string Help => """
        avatargo calibrate SESSION [--json] [--avatar FILE [--avatar-map FILE]] [--save PROFILE]

        Feeds the session's frames to the calibration state machine (trigger 1: identify devices,
        validate the T-pose, scale and place the avatar; trigger 2: exact offsets) and prints the
        outcome: status, the error and its message when a step was refused, the role found for each
        device, the scale, and the offsets (each joint's position and rotation in its device's frame).
          --avatar FILE    the avatar (a BVH skeleton); default: the wearer's skeleton in the session
          --avatar-map FILE  the humanoid bones of the avatar's joints the naming rules miss ('joint name =
                           Bone' lines, as simulate's --map)
          --json           print the outcome as JSON (the profile format, plus status)
          --save PROFILE   save the calibration profile (atomic write)
        Exit codes: 0 calibrated, 1 unreadable session or calibration not completed, 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "json");
        string path = a.Positional0("SESSION");
        bool json = a.Flag("json");
        string avatarFile = a.String("avatar");
        string avatarMap = AvatarMapArgument(a, avatarFile);
        string save = a.String("save");
        a.ThrowOnUnknown(1);
        OutputFiles.RefuseClashes(new[] { ("the session", path), ("--avatar", avatarFile), ("--avatar-map", avatarMap) }, new[] { ("--save", save) });

        using SessionReader reader = SessionReader.Open(path);
        HumanoidMap avatar = avatarFile != null
            ? AvatarFrom(avatarFile, avatarMap)
            : reader.Header.TruthHumanoid ?? throw new UsageException("the session has no wearer skeleton; give --avatar FILE");
        var calibrator = new Calibrator(reader.Header.Devices, avatar);
        SessionFrame frame = reader.CreateFrame();
        int presses = 0;
        string lastRefusal = null, lastIgnored = null;
        while (calibrator.State != CalibrationState.Calibrated && reader.ReadFrame(frame))
        {
            CalibrationStep step = calibrator.Update(frame.Time, frame.Samples, frame.Events);
            foreach (DeviceEvent e in frame.Events)
                if (e.Kind == DeviceEventKind.TriggerPressed) presses++;
            if (step.Outcome == CalibrationStepOutcome.Refused) lastRefusal = $"{step.Error}: {step.Message}";
            if (step.Outcome == CalibrationStepOutcome.PressIgnored) lastIgnored = step.Explanation;
        }
        bool ok = calibrator.State == CalibrationState.Calibrated;
        var inv = CultureInfo.InvariantCulture;
        if (json)
        {
            string profile = ok ? CalibrationProfileStore.ToJson(calibrator.Profile) : "null";
            stdout.WriteLine("{");
            stdout.WriteLine($"  \"status\": \"{(ok ? "calibrated" : calibrator.State.ToString())}\",");
            stdout.WriteLine($"  \"error\": {JsonSerializer.Serialize(calibrator.LastStep.Error.ToString())},");
            stdout.WriteLine($"  \"message\": {JsonSerializer.Serialize(calibrator.LastStep.Message)},");
            stdout.WriteLine($"  \"profile\": {profile.TrimEnd().Replace("\n", "\n  ")}");
            stdout.WriteLine("}");
        }
        else
        {
            stdout.WriteLine($"status: {(ok ? "calibrated" : "not calibrated (" + calibrator.State + ")")} after {presses} trigger press(es)");
            if (lastRefusal != null) stdout.WriteLine($"last refusal: {lastRefusal}");
            if (lastIgnored != null) stdout.WriteLine($"last ignored press: {lastIgnored}");
            if (!ok) stdout.WriteLine($"message: {calibrator.LastStep.Message}");
            if (calibrator.LastStep.Explanation.Length > 0) stdout.WriteLine($"note: {calibrator.LastStep.Explanation.Trim()}");
            if (calibrator.Profile != null)
            {
                CalibrationProfile p = calibrator.Profile;
                stdout.WriteLine(string.Create(inv, $"scale: {p.AvatarScale:0.0000} (wearer eye height {p.WearerEyeHeight:0.000} m, avatar {p.AvatarEyeHeight:0.000} m, floor {p.FloorHeight:0.###} m)"));
                foreach (DeviceRole role in BodyRoles.All)
                {
                    DeviceInfo d = reader.Header.Devices[calibrator.DeviceIndexOf(role)];
                    string line = $"  {role,-10} device {d.Id} ({d.Class}, {d.Serial})";
                    if (ok)
                    {
                        RigidPose o = p.JointInDevice(role);
                        line += string.Create(inv, $": joint at ({o.Position.X * 1000:0.0}, {o.Position.Y * 1000:0.0}, {o.Position.Z * 1000:0.0}) mm in the device frame, rotated {Rotations.AngleDegrees(System.Numerics.Quaternion.Identity, o.Rotation):0.0} deg");
                    }
                    stdout.WriteLine(line);
                }
                if (ok) stdout.WriteLine(string.Create(inv, $"  w0 (pelvis tracker -> HMD): ({p.RootToHead.X:0.000}, {p.RootToHead.Y:0.000}, {p.RootToHead.Z:0.000}) m"));
            }
        }
        if (ok && save != null)
        {
            try
            {
                CalibrationProfileStore.Save(calibrator.Profile, save); // atomic: a failure leaves an older PROFILE as it was
            }
            catch (ArgumentException e) when (e.ParamName == "profile")
            {
                // Only a profile that would not load back; other failures (the path) are the usual file errors.
                stderr.WriteLine($"avatargo calibrate: the profile was not saved: {e.Message.Split(" (Parameter '")[0]}");
                return 1;
            }
            if (!json) stdout.WriteLine($"profile saved to {save}");
        }
        return ok ? 0 : 1;
    }

    /// <summary>
    /// The humanoid avatar of a BVH file (its rest pose, in metres; its bones from the names, else from its hierarchy and
    /// motion, <see cref="HumanoidDetection"/>), or a one-line <see cref="FormatException"/> naming the file when it cannot
    /// be one (a skeleton without the required humanoid bones).
    /// </summary>
    // --avatar-map FILE: only with --avatar (the session's own skeleton was mapped when it was simulated).
    internal static string AvatarMapArgument(ArgReader a, string avatarFile)
    {
        string avatarMap = a.String("avatar-map");
        if (avatarMap != null && avatarFile == null) throw new UsageException("--avatar-map needs --avatar FILE (the session's own skeleton was mapped by simulate --map)");
        return avatarMap;
    }

    internal static HumanoidMap AvatarFrom(string file, string mapFile = null)
    {
        // The bones of the map file first, then the names, else the hierarchy and the file's motion (an avatar file with
        // only its rest pose cannot show its knees and elbows: then the names or the map must find them).
        HumanoidMap map = BoneMapFile.Detect(BvhReader.ReadFile(file, new BvhReadOptions { ToMetres = true }), mapFile, out string note);
        var missing = map.MissingRequired();
        if (missing.Count > 0)
            throw new FormatException($"{Path.GetFileName(file)}: not a humanoid avatar: its skeleton lacks {string.Join(", ", missing)}{(note != null ? "; " + note : "")}"
                + (mapFile == null ? " (give their joints' bones with --avatar-map FILE)" : ""));
        return map;
    }
}
