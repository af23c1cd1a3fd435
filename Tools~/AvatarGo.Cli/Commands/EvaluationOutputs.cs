using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text;
using AvatarGo.Core;
using AvatarGo.Simulation;
using ScottPlot;

namespace AvatarGo.Cli.Commands;

/// <summary>
/// What `avatargo evaluate` can write besides its figures: the solved and true joints per frame as CSV (--positions),
/// the solved avatar's motion as BVH (--bvh-out), and the per-frame errors over time as a PNG (--plot, drawn with
/// ScottPlot). Records every compared frame while the evaluator runs.
/// </summary>
internal sealed class EvaluationOutputs
{
    /// <summary>The end effectors the plot draws (the evaluator's end-effector set).</summary>
    private static readonly HumanoidBone[] EndEffectors = HumanoidBones.EndEffectors;

    // The evaluator's mid joints, knees first as the plot's panels are laid out.
    private static readonly HumanoidBone[] MidJoints =
        { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg, HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm };

    private readonly string _positions, _bvh, _plot;
    private AtomicFileWriter _positionsFile, _bvhFile, _plotFile;
    private readonly List<int> _frames = new();
    private readonly List<double> _times = new();
    private readonly List<Vector3[]> _solved = new(), _truth = new();
    private readonly List<RigidPose[]> _locals = new();
    private HumanoidBone[] _bones;
    private Skeleton _skeleton;
    private float _rate;
    private SessionReader _reader;

    private EvaluationOutputs(string positions, string bvh, string plot)
    {
        _positions = positions;
        _bvh = bvh;
        _plot = plot;
    }

    /// <summary>The help lines of the options.</summary>
    public const string Help = """
          --positions OUT.csv  the solved and true world position of every humanoid joint per compared frame
                               (header: frame,time,Bone.solved.x,Bone.solved.y,Bone.solved.z,Bone.truth.x,...;
                               frame = the session frame's index, time in s, positions in metres, Unity's frame;
                               the finger bones' columns too, which MPJPE leaves out; a truth the frame does
                               not give: empty cells)
          --bvh-out OUT.bvh    the solved avatar's motion (the scaled avatar, compared frames, centimetres)
          --plot OUT.png       per-frame errors over time: end effectors, knees and elbows (mm), and the knees'
                               and elbows' bend-plane angle error (deg)
        """;

    /// <summary>Reads the options (call before <see cref="ArgReader.ThrowOnUnknown"/>).</summary>
    public static EvaluationOutputs FromArgs(ArgReader a) => new(a.String("positions"), a.String("bvh-out"), a.String("plot"));

    /// <summary>True when an output is asked for (every compared frame is then recorded).</summary>
    public bool IsRecording => Recording;

    private bool Recording => _positions != null || _bvh != null || _plot != null;

    /// <summary>The output paths, by option, for <see cref="OutputFiles.RefuseClashes"/>.</summary>
    public IEnumerable<(string what, string path)> Paths => new[] { ("--positions", _positions), ("--bvh-out", _bvh), ("--plot", _plot) };

    /// <summary>Opens the files asked for in <paramref name="files"/> (before the evaluation: a folder that does not exist is said at once).</summary>
    public void Open(OutputFiles files)
    {
        if (_positions != null) _positionsFile = files.Open(_positions);
        if (_bvh != null) _bvhFile = files.Open(_bvh);
        if (_plot != null) _plotFile = files.Open(_plot);
    }

    /// <summary>Runs the evaluation, recording every compared frame when an output is asked for.</summary>
    public EvaluationReport Evaluate(SessionReader reader, PipelineSettings settings, HumanoidMap avatar, DisturbanceOptions disturbance)
    {
        if (!Recording) return SessionEvaluator.Evaluate(reader, settings, avatar, null, disturbance);
        _rate = reader.Header.Rate;
        _reader = reader;
        return SessionEvaluator.EvaluateWithTruth(reader, settings, avatar, Record, disturbance);
    }

    private void Record(SelfAvatarPipeline pipeline, SessionFrame frame)
    {
        HumanoidMap scaled = pipeline.ScaledAvatar;
        if (_bones == null)
        {
            _skeleton = scaled.Skeleton;
            // The truth skeleton's bones, not the first compared frame's: a frame may lack some bones' truth.
            HumanoidMap wearer = _reader.Header.TruthHumanoid;
            _bones = Enumerable.Range(0, HumanoidBones.Count).Select(b => (HumanoidBone)b)
                .Where(b => scaled.Has(b) && (wearer != null ? wearer.Has(b) : frame.HasTruth[(int)b])).ToArray();
        }
        var solved = new Vector3[_bones.Length];
        var truth = new Vector3[_bones.Length];
        for (int i = 0; i < _bones.Length; i++)
        {
            solved[i] = pipeline.Pose.World[scaled[_bones[i]]].Position;
            // Not given in this frame: NaN, written as empty cells (the frame buffer still holds an earlier frame's truth).
            truth[i] = frame.HasTruth[(int)_bones[i]] ? frame.Truth[(int)_bones[i]].Position : new Vector3(float.NaN);
        }
        // The index of the frame just read; its time times the rate was not one where the clock does not start at 0 (a
        // recording's unscaled time) or the frames are not evenly spaced.
        _frames.Add(_reader.FrameCount - 1);
        _times.Add(frame.Time);
        _solved.Add(solved);
        _truth.Add(truth);
        if (_bvh != null) _locals.Add((RigidPose[])pipeline.Pose.Local.Clone());
    }

    /// <summary>Writes the outputs asked for into the files <see cref="Open"/> opened (committed by the caller, with the others).</summary>
    public void Write()
    {
        if (!Recording || _bones == null) return;
        if (_positionsFile != null) OutputFiles.WriteText(_positionsFile, w => WritePositions(w, CultureInfo.InvariantCulture));
        if (_bvhFile != null)
        {
            BvhClip solved = BvhClip.FromPoses(_skeleton, _locals, 1f / _rate, 0.01f);
            OutputFiles.WriteText(_bvhFile, w => BvhWriter.Write(w, solved));
        }
        if (_plotFile != null) WritePlot(_plotFile);
    }

    /// <summary>Says where the outputs were written (after they were committed).</summary>
    public void Report(TextWriter stdout)
    {
        if (!Recording || _bones == null) return;
        if (_positions != null) stdout.WriteLine($"positions written to {_positions} ({_frames.Count} frames, {_bones.Length} joints)");
        if (_bvh != null) stdout.WriteLine($"solved avatar written to {_bvh} (centimetres, {_locals.Count} frames)");
        if (_plot != null) stdout.WriteLine($"plot written to {_plot}");
    }

    private void WritePositions(TextWriter w, CultureInfo inv)
    {
        w.NewLine = "\n";
        var line = new StringBuilder("frame,time");
        foreach (HumanoidBone b in _bones)
            foreach (string kind in new[] { "solved", "truth" })
                line.Append(',').Append(b).Append('.').Append(kind).Append(".x,")
                    .Append(b).Append('.').Append(kind).Append(".y,")
                    .Append(b).Append('.').Append(kind).Append(".z");
        w.WriteLine(line.ToString());
        for (int f = 0; f < _frames.Count; f++)
        {
            line.Clear();
            line.Append(_frames[f].ToString(inv)).Append(',').Append(_times[f].ToString("R", inv));
            for (int i = 0; i < _bones.Length; i++)
                foreach (Vector3 p in new[] { _solved[f][i], _truth[f][i] })
                {
                    if (float.IsNaN(p.X)) line.Append(",,,"); // a truth the frame does not give
                    else line.Append(',').Append(p.X.ToString("R", inv)).Append(',').Append(p.Y.ToString("R", inv)).Append(',').Append(p.Z.ToString("R", inv));
                }
            w.WriteLine(line.ToString());
        }
    }

    private void WritePlot(AtomicFileWriter file)
    {
        double[] t = _times.ToArray();
        var multiplot = new Multiplot();
        multiplot.AddPlots(3);
        Plot ends = multiplot.GetPlot(0), mids = multiplot.GetPlot(1), bends = multiplot.GetPlot(2);
        foreach (HumanoidBone b in EndEffectors) AddLine(ends, t, Errors(b), b.ToString());
        foreach (HumanoidBone b in MidJoints) AddLine(mids, t, Errors(b), b.ToString());
        foreach (HumanoidBone b in MidJoints) AddLine(bends, t, BendErrors(b), b.ToString());
        ends.Title("End effectors: position error (mm)");
        mids.Title("Knees and elbows: position error (mm)");
        bends.Title($"Knees and elbows: bend-plane angle error (deg; gaps: bent less than {BendPlaneReport.MinBendDegrees:0} deg)");
        bends.XLabel("time (s)");
        var flip = bends.Add.HorizontalLine(BendPlaneReport.FlippedDegrees);
        flip.LinePattern = LinePattern.Dashed;
        flip.Color = Colors.Gray;
        bends.Add.HorizontalLine(-BendPlaneReport.FlippedDegrees).LinePattern = LinePattern.Dashed;
        foreach (Plot p in new[] { ends, mids, bends }) p.ShowLegend(Alignment.UpperRight);
        // ScottPlot's multiplot only saves to a path: render to a scratch file, then copy it into OUT's pending file.
        string scratch = Path.Combine(Path.GetTempPath(), "avatargo-plot-" + Guid.NewGuid().ToString("N") + ".png");
        try
        {
            multiplot.SavePng(scratch, 1600, 1200);
            byte[] png = File.ReadAllBytes(scratch);
            file.Stream.Write(png, 0, png.Length);
        }
        finally { File.Delete(scratch); }
    }

    private static void AddLine(Plot plot, double[] t, double[] y, string label)
    {
        var line = plot.Add.ScatterLine(t, y);
        line.LegendText = label;
        line.LineWidth = 1.2f;
    }

    private double[] Errors(HumanoidBone bone)
    {
        int i = Array.IndexOf(_bones, bone);
        var e = new double[_frames.Count];
        for (int f = 0; f < e.Length; f++) e[f] = i < 0 ? double.NaN : Vector3.Distance(_solved[f][i], _truth[f][i]) * 1000.0;
        return e;
    }

    private double[] BendErrors(HumanoidBone middle)
    {
        int r = Array.IndexOf(_bones, HumanoidBones.Parent(middle)), m = Array.IndexOf(_bones, middle), e = Array.IndexOf(_bones, SessionEvaluator.LimbEnd(middle));
        var angles = new double[_frames.Count];
        for (int f = 0; f < angles.Length; f++)
            angles[f] = r < 0 || m < 0 || e < 0 ? double.NaN
                : BendPlaneReport.SignedAngleDegrees(_truth[f][r], _truth[f][m], _truth[f][e], _solved[f][r], _solved[f][m], _solved[f][e]);
        return angles;
    }
}
