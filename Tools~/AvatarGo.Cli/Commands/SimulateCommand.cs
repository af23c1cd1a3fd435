using System;
using System.Globalization;
using System.IO;
using System.Numerics;
using AvatarGo.Core;
using AvatarGo.Simulation;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo simulate`: mocap → synthetic session with devices and ground truth.</summary>
public sealed class SimulateCommand : ICommand
{
    public string Name => "simulate";
    public string Summary => "Turn a BVH mocap clip into a synthetic VR session";
    public string Help => """
        avatargo simulate --bvh FILE --out SESSION [options]

        Writes a complete synthetic session (session format v1): the wearer (the clip's skeleton, in
        metres) stands in T-pose and presses the trigger, walks into the avatar and presses again, then
        blends from the T-pose into the clip and performs it. Six virtual devices are mounted on the
        skeleton with a random but realistic mounting (Documentation~/calibration.md); the ground truth
        (true roles, the wearer's skeleton and joint poses) is recorded.
          --seed N            mounting, noise and starting place (default 1)
          --rate HZ           session frame rate (default 90)
          --noise-mm MM       position noise, standard deviation per coordinate (default 1)
          --noise-deg DEG     rotation noise, standard deviation (default 0.1)
          --misalign-mm MM    the wearer ends the walk-in MM to the avatar's right (default 0; beyond 300 the
                              calibration refuses the walk-in: the wearer is not inside the avatar)
          --misalign-deg DEG  and turned by DEG (default 0)
          --controller NAME   the controller held in the palm: a profile of Runtime/ControllerProfiles
                              (default vive-wand) or none for a generic 2 cm handle; evaluate with the same
          --exercise-seconds S  after the walk-in, S seconds of the refinement exercise (arm circles and reaches
                              with the arms stretched, then squats) before the clip (default 0: none); evaluate
                              with --refine --exercise-seconds S
          --keep-up           simulate the clip with +Y up as it is; by default a clip recorded with another
                              axis up (a Z-up export) is stood up first, and the command says so
          --map FILE          the humanoid bones of joints the naming rules miss: 'joint name = Bone' lines
                              (LeftUpperArm, Hips, ...; # comments); the others are found from their names
          --units U           the clip's length unit: auto (default: guessed from the longest chain of bones,
                              'bvh info' says which), m, cm, mm, in, or cmu (the CMU database's BVH unit,
                              0.0254/0.45 m); a chain of 60 to 94 units is a person in centimetres and in inches
                              alike, and the guess takes centimetres
          --keep-sides        simulate the clip as it is even if its knees bend backward; by default such a clip
                              (a left-handed export, or its sides named the wrong way round) is mirrored left to
                              right first, and the command says so
        Exit codes: 0 ok, 1 unreadable input, 2 bad arguments.
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, OptionFlags);
        string bvh = a.String("bvh") ?? throw new UsageException("missing --bvh FILE");
        string output = a.String("out") ?? throw new UsageException("missing --out SESSION");
        var options = Options(a);
        string mapPath = a.String("map");
        BvhReadOptions read = ReadOptions(a);
        a.ThrowOnUnknown(0);
        OutputFiles.RefuseClashes(new[] { ("--bvh", bvh), ("--map", mapPath) }, new[] { ("--out", output) });
        BvhClip clip = BvhReader.ReadFile(bvh, read);
        SessionSimulator simulator;
        string note = null;
        HumanoidMap map = null;
        try
        {
            map = BoneMapFile.Detect(clip, mapPath, out note);
            simulator = new SessionSimulator(clip, options, map);
        }
        catch (ArgumentException e)
        {
            stderr.WriteLine($"avatargo simulate: {Path.GetFileName(bvh)} cannot be simulated: {FirstLine(e).TrimEnd('.')}{MissingNote(map, note)}");
            return 1;
        }
        if (!WriteSession(simulator, output, stderr, "simulate")) return 1;
        stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"wrote {output}: {simulator.FrameCount} frames at {options.Rate:0.##} Hz"));
        PrintClipNotes(simulator, stdout);
        if (note != null) stdout.WriteLine(note);
        return 0;
    }

    /// <summary>Why the bones were not found (the detection's note), when they were not: appended to a refusal.</summary>
    internal static string MissingNote(HumanoidMap map, string note) =>
        map != null && !map.IsComplete && note != null ? "; " + note : "";

    /// <summary>Says what the simulator changed about the clip before wearing it: mirrored it, stood it up.</summary>
    internal static void PrintClipNotes(SessionSimulator simulator, TextWriter stdout)
    {
        if (simulator.Mirrored)
            stdout.WriteLine("the clip's knees bend backward (a left-handed export, or its sides named the wrong way round): it was mirrored left to right");
        if (simulator.Upright != Quaternion.Identity)
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"the clip's up is not +Y: its motion was turned {Rotations.AngleDegrees(Quaternion.Identity, simulator.Upright):0} deg to stand it up"));
    }

    /// <summary>
    /// Simulates into a session file, whole or not at all: the file appears only when the session is complete, and a
    /// failure (a skeleton the format cannot hold, an exception mid-way) leaves a file already at the path untouched.
    /// False (with the reason on stderr) when the clip's skeleton cannot be written as a session.
    /// </summary>
    internal static bool WriteSession(SessionSimulator simulator, string path, TextWriter stderr, string command, Action<float> progress = null)
    {
        SessionWriter writer;
        try
        {
            writer = SessionWriter.Create(path, simulator.CreateHeader());
        }
        catch (ArgumentException e)
        {
            stderr.WriteLine($"avatargo {command}: the session cannot hold this clip's skeleton: {FirstLine(e)} ({path} was not written)");
            return false;
        }
        using (writer)
        {
            try
            {
                simulator.Run(writer, progress);
                writer.Complete();
            }
            catch
            {
                writer.Discard();
                throw;
            }
        }
        return true;
    }

    /// <summary>
    /// Simulates into memory (demo's session, which no one keeps: a file under a fixed name in the shared temporary
    /// folder replaced, then deleted, whatever was there). Null (with the reason on stderr) when the clip's skeleton
    /// cannot be written as a session.
    /// </summary>
    internal static string SimulateToText(SessionSimulator simulator, TextWriter stderr, string command, Action<float> progress = null)
    {
        var text = new StringWriter();
        SessionWriter writer;
        try
        {
            writer = new SessionWriter(text, simulator.CreateHeader());
        }
        catch (ArgumentException e)
        {
            stderr.WriteLine($"avatargo {command}: the session cannot hold this clip's skeleton: {FirstLine(e)}");
            return null;
        }
        using (writer) simulator.Run(writer, progress);
        return text.ToString();
    }

    // The message of an ArgumentException without its "(Parameter 'x')" line.
    private static string FirstLine(ArgumentException e)
    {
        string m = e.Message;
        int parameter = m.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return (parameter >= 0 ? m.Substring(0, parameter) : m).Split('\n')[0].TrimEnd('\r');
    }

    /// <summary>
    /// How simulate and demo read the clip (--units): in metres, the unit guessed (auto) or given. Read it before
    /// <see cref="ArgReader.ThrowOnUnknown"/>.
    /// </summary>
    internal static BvhReadOptions ReadOptions(ArgReader a)
    {
        string units = a.String("units", "auto");
        float metres = units switch
        {
            "auto" => float.NaN,
            "m" => 1f,
            "cm" => 0.01f,
            "mm" => 0.001f,
            "in" => 0.0254f,
            "cmu" => 0.0254f / 0.45f,
            string other => throw new UsageException($"--units must be auto, m, cm, mm, in or cmu, got '{other}'"),
        };
        return float.IsNaN(metres) ? new BvhReadOptions { ToMetres = true } : new BvhReadOptions { Scale = metres };
    }

    /// <summary>The options of <see cref="Options"/> that take no value: an ArgReader must be told them.</summary>
    internal static readonly string[] OptionFlags = { "keep-up", "keep-sides" };

    /// <summary>The simulation options shared by simulate and demo.</summary>
    internal static SimulationOptions Options(ArgReader a)
    {
        var o = new SimulationOptions
        {
            Seed = a.Int("seed", 1),
            Rate = (float)a.Double("rate", 90),
            PositionNoise = (float)(a.Double("noise-mm", 1) / 1000.0),
            RotationNoiseDegrees = (float)a.Double("noise-deg", 0.1),
            Misalignment = new Vector3((float)(a.Double("misalign-mm", 0) / 1000.0), 0, 0),
            MisalignmentYawDegrees = (float)a.Double("misalign-deg", 0),
            Controller = ControllerProfiles.Named(a.String("controller", ControllerProfiles.Default)),
            ExerciseSeconds = (float)a.Double("exercise-seconds", 0),
            StandClipUp = !a.Flag("keep-up"),
            MirrorBackwardClip = !a.Flag("keep-sides"),
        };
        if (!(o.ExerciseSeconds >= 0 && o.ExerciseSeconds <= 60)) throw new UsageException("--exercise-seconds must be between 0 and 60");
        if (!(o.Rate >= 10 && o.Rate <= 1000)) throw new UsageException("--rate must be between 10 and 1000 Hz");
        if (o.PositionNoise < 0 || o.RotationNoiseDegrees < 0) throw new UsageException("noise must not be negative");
        // Within what a session can hold (positions within 10 km): beyond, the writer refused a device's pose (exit 1,
        // naming a device) on some seeds and not others.
        if (!(o.PositionNoise <= 1f)) throw new UsageException("--noise-mm must be at most 1000");
        if (!(o.RotationNoiseDegrees <= 180f)) throw new UsageException("--noise-deg must be at most 180");
        if (!(Math.Abs(o.Misalignment.X) <= 10f)) throw new UsageException("--misalign-mm must be within ±10000");
        if (!(Math.Abs(o.MisalignmentYawDegrees) <= 360f)) throw new UsageException("--misalign-deg must be within ±360");
        return o;
    }
}
