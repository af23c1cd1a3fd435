using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

public class BvhCommandTests
{
    [TestCase("mocapbank_30fps.bvh", 0.01)]
    [TestCase("mixamo_fingers_30fps.bvh", 1.0)]
    [TestCase("rigify_6channel_24fps_first240.bvh", 1000.0)]
    public void PositionsAgreeWithAnIndependentForwardKinematics(string file, double scale)
    {
        string path = Paths.Mocap(file);
        var r = CliRunner.Run("bvh", "positions", path, "--scale", scale.ToString(CultureInfo.InvariantCulture));
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        string[] rows = r.Stdout.TrimEnd().Split('\n');
        double[][] truth = ReferenceFk.Positions(path, scale);
        Assert.That(rows.Length - 1, Is.EqualTo(truth.Length), "one row per frame");
        // 0.1 mm, in the output's units: file units × scale; metres-per-output-unit as the clip's unit over scale.
        double metresPerFileUnit = file.StartsWith("rigify") ? 1.0 : 0.01;
        double tolerance = 1e-4 / metresPerFileUnit * scale;
        double worst = 0;
        for (int f = 0; f < truth.Length; f++)
        {
            double[] got = rows[f + 1].Split(',').Skip(1).Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
            Assert.That(got.Length, Is.EqualTo(truth[f].Length), $"frame {f} columns");
            for (int i = 0; i < got.Length; i += 3)
            {
                // Unity's frame is the BVH frame with x negated.
                double dx = got[i] + truth[f][i], dy = got[i + 1] - truth[f][i + 1], dz = got[i + 2] - truth[f][i + 2];
                worst = Math.Max(worst, Math.Sqrt(dx * dx + dy * dy + dz * dz));
            }
        }
        Assert.That(worst, Is.LessThanOrEqualTo(tolerance), $"largest joint distance from the reference FK");
    }

    [Test]
    public void FramesOptionSelectsARange()
    {
        var r = CliRunner.Run("bvh", "positions", Paths.Mocap("mocapbank_30fps.bvh"), "--frames", "10:13");
        Assert.That(r.ExitCode, Is.EqualTo(0));
        string[] rows = r.Stdout.TrimEnd().Split('\n');
        Assert.That(rows.Length, Is.EqualTo(4));
        StringAssert.StartsWith("10,", rows[1]);
        StringAssert.StartsWith("12,", rows[3]);
        Assert.That(CliRunner.Run("bvh", "positions", Paths.Mocap("mocapbank_30fps.bvh"), "--frames", "5:999").ExitCode, Is.EqualTo(2));
    }

    [Test]
    public void InfoShowsMappingAndNoMissingBones()
    {
        var r = CliRunner.Run("bvh", "info", Paths.Mocap("mocapbank_30fps.bvh"));
        Assert.That(r.ExitCode, Is.EqualTo(0), r.Stderr);
        StringAssert.Contains("frames: 455", r.Stdout);
        StringAssert.Contains("LeftElbow  [Zrotation Xrotation Yrotation]  -> LeftLowerArm", r.Stdout);
        StringAssert.Contains("missing required: none", r.Stdout);
        StringAssert.Contains("optional bones missing: UpperChest, LeftToes, RightToes, LeftEye, RightEye", r.Stdout);
        StringAssert.Contains("left hand: no finger bones; the hand takes the walk-in offset, without finger IK", r.Stdout);

        var mixamo = CliRunner.Run("bvh", "info", Paths.Mocap("mixamo_fingers_30fps.bvh"));
        StringAssert.Contains("optional bones missing: none", mixamo.Stdout);
        StringAssert.Contains("left hand: fingers found", mixamo.Stdout);
        StringAssert.Contains("right hand: fingers found", mixamo.Stdout);
    }

    /// <summary>
    /// bvh info names a clip's up axis and counts its knee bends; on the clip's mirror image (a left-handed export) it says
    /// its sides look mirrored, and simulate mirrors it back and says so, unless told --keep-sides.
    /// </summary>
    [Test]
    public void InfoAndSimulateNameAMirroredClip()
    {
        var clip = AvatarGo.Core.BvhReader.ReadFile(Paths.Mocap("mocapbank_30fps.bvh"));
        string dir = Path.Combine(Path.GetTempPath(), "avatargo-mirror-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        try
        {
            string mirrored = Path.Combine(dir, "mirrored.bvh");
            AvatarGo.Core.BvhWriter.WriteFile(mirrored, clip.Mirrored());
            var own = CliRunner.Run("bvh", "info", Paths.Mocap("mocapbank_30fps.bvh"));
            StringAssert.Contains("up: +Y", own.Stdout);
            StringAssert.Contains("knees bent 20 deg or more: 724 bend forward, 0 backward", own.Stdout);
            StringAssert.DoesNotContain("mirrored", own.Stdout);
            var info = CliRunner.Run("bvh", "info", mirrored);
            Assert.That(info.ExitCode, Is.EqualTo(0), info.Stderr);
            StringAssert.Contains("0 bend forward, 724 backward (its sides look mirrored", info.Stdout);

            var simulated = CliRunner.Run("simulate", "--bvh", mirrored, "--out", Path.Combine(dir, "a.session"));
            Assert.That(simulated.ExitCode, Is.EqualTo(0), simulated.Stderr);
            StringAssert.Contains("it was mirrored left to right", simulated.Stdout);
            // demo wears the mirrored-back clip and writes the solved avatar on that skeleton (found in review: it wrote them
            // on the file's skeleton and failed).
            var demo = CliRunner.Run("demo", "--bvh", mirrored, "--out-bvh", Path.Combine(dir, "solved.bvh"));
            Assert.That(demo.ExitCode, Is.EqualTo(0), demo.Stderr);
            StringAssert.Contains("it was mirrored left to right", demo.Stdout);
            Assert.That(AvatarGo.Core.BvhReader.ReadFile(Path.Combine(dir, "solved.bvh")).FrameCount, Is.GreaterThan(0));

            var kept = CliRunner.Run("simulate", "--bvh", mirrored, "--out", Path.Combine(dir, "b.session"), "--keep-sides");
            Assert.That(kept.ExitCode, Is.EqualTo(0), kept.Stderr);
            StringAssert.DoesNotContain("mirrored", kept.Stdout);

            // A Z-up copy: named by bvh info, stood up by simulate unless told --keep-up (a flag, as --keep-sides is:
            // found by this test, --keep-up once asked for a value).
            string zUp = Path.Combine(dir, "z-up.bvh");
            AvatarGo.Core.BvhWriter.WriteFile(zUp, TurnedAboutX(clip, -90f));
            StringAssert.Contains("up: -Z (not +Y", CliRunner.Run("bvh", "info", zUp).Stdout);
            StringAssert.Contains("to stand it up", CliRunner.Run("simulate", "--bvh", zUp, "--out", Path.Combine(dir, "c.session")).Stdout);
            var keptUp = CliRunner.Run("simulate", "--bvh", zUp, "--out", Path.Combine(dir, "d.session"), "--keep-up", "--keep-sides");
            Assert.That(keptUp.ExitCode, Is.EqualTo(0), keptUp.Stderr);
            StringAssert.DoesNotContain("stand it up", keptUp.Stdout);
        }
        finally { Directory.Delete(dir, true); }
    }

    /// <summary>
    /// --map: joints whose names the rules miss are given their bones in a file, the rest are still found from the names;
    /// a bad line or a joint the clip lacks is a one-line error naming it.
    /// </summary>
    [Test]
    public void AMapFileGivesTheBonesOfJointsTheNamesMiss()
    {
        string text = File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh"));
        string renamed = text.Replace("JOINT LeftShoulder", "JOINT Bone.010").Replace("JOINT LeftElbow", "JOINT Bone.011").Replace("JOINT LeftWrist", "JOINT Bone.012");
        string dir = Path.Combine(Path.GetTempPath(), "avatargo-map-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        try
        {
            string clip = Path.Combine(dir, "renamed.bvh"), map = Path.Combine(dir, "map.txt"), bad = Path.Combine(dir, "bad.txt"), absent = Path.Combine(dir, "absent.txt");
            File.WriteAllText(clip, renamed);
            File.WriteAllText(map, "# the left arm of renamed.bvh\nBone.010 = LeftUpperArm\nBone.011 = leftlowerarm   # any case\n\nBone.012=LeftHand\n");
            File.WriteAllText(bad, "Bone.010 = LeftUpperArm\nBone.011 = LeftElbow\n");
            File.WriteAllText(absent, "Bone.099 = LeftUpperArm\n");

            // Without the file the hierarchy and the motion find the arm (HumanoidStructure), and the command says so.
            var without = CliRunner.Run("simulate", "--bvh", clip, "--out", Path.Combine(dir, "a.session"));
            Assert.That(without.ExitCode, Is.EqualTo(0), without.Stderr);
            StringAssert.Contains("the names give 16 humanoid bones: all were found from the hierarchy and the motion instead", without.Stdout);
            StringAssert.Contains("Bone.011  [Zrotation Xrotation Yrotation]  -> LeftLowerArm", CliRunner.Run("bvh", "info", clip).Stdout);

            var with = CliRunner.Run("simulate", "--bvh", clip, "--out", Path.Combine(dir, "b.session"), "--map", map);
            Assert.That(with.ExitCode, Is.EqualTo(0), with.Stderr);
            var info = CliRunner.Run("bvh", "info", clip, "--map", map);
            StringAssert.Contains("Bone.011  [Zrotation Xrotation Yrotation]  -> LeftLowerArm", info.Stdout);
            StringAssert.Contains("missing required: none", info.Stdout);

            var badLine = CliRunner.Run("simulate", "--bvh", clip, "--out", Path.Combine(dir, "c.session"), "--map", bad);
            Assert.That(badLine.ExitCode, Is.EqualTo(1));
            StringAssert.Contains("bad.txt:2: 'LeftElbow' is not a humanoid bone", badLine.Stderr);
            var absentJoint = CliRunner.Run("simulate", "--bvh", clip, "--out", Path.Combine(dir, "d.session"), "--map", absent);
            Assert.That(absentJoint.ExitCode, Is.EqualTo(1));
            StringAssert.Contains("Bone.099", absentJoint.Stderr);
            Assert.That(File.Exists(Path.Combine(dir, "c.session")) || File.Exists(Path.Combine(dir, "d.session")), Is.False, "no session written");
        }
        finally { Directory.Delete(dir, true); }
    }

    /// <summary>
    /// A clip neither its names nor its structure read as a humanoid (a chain of numbered joints) is refused with both
    /// reasons, and no session is written.
    /// </summary>
    [Test]
    public void AClipThatIsNoHumanoidIsRefusedWithBothReasons()
    {
        var bvh = new System.Text.StringBuilder("HIERARCHY\nROOT j0\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n");
        for (int j = 1; j < 6; j++) bvh.Append($"JOINT j{j}\n{{\n  OFFSET 0 20 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n");
        bvh.Append("End Site\n{\n  OFFSET 0 20 0\n}\n");
        for (int j = 0; j < 6; j++) bvh.Append("}\n");
        bvh.Append("MOTION\nFrames: 30\nFrame Time: 0.0333333\n");
        // Root position, then every joint's three rotations (the root's too), the chain curling a degree a frame.
        for (int f = 0; f < 30; f++) bvh.Append("0 90 0 " + string.Join(" ", Enumerable.Repeat($"{f} 0 0", 6)) + "\n");
        string dir = Path.Combine(Path.GetTempPath(), "avatargo-chain-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(dir);
        try
        {
            string clip = Path.Combine(dir, "chain.bvh"), session = Path.Combine(dir, "chain.session");
            File.WriteAllText(clip, bvh.ToString());
            var run = CliRunner.Run("simulate", "--bvh", clip, "--out", session);
            Assert.That(run.ExitCode, Is.EqualTo(1), run.Stdout);
            StringAssert.Contains("lacks required humanoid bones", run.Stderr);
            StringAssert.Contains("the hierarchy does not read as a humanoid either: 0 joint(s) where three long branches meet", run.Stderr);
            StringAssert.DoesNotContain(".;", run.Stderr);
            Assert.That(File.Exists(session), Is.False, "no session written");
        }
        finally { Directory.Delete(dir, true); }
    }

    // The clip turned about X at its roots (file units, as read).
    private static AvatarGo.Core.BvhClip TurnedAboutX(AvatarGo.Core.BvhClip clip, float degrees)
    {
        var turn = System.Numerics.Quaternion.CreateFromAxisAngle(System.Numerics.Vector3.UnitX, degrees * MathF.PI / 180f);
        var s = clip.Skeleton;
        var frames = new List<AvatarGo.Core.RigidPose[]>();
        for (int f = 0; f < clip.FrameCount; f++)
        {
            var local = new AvatarGo.Core.RigidPose[s.JointCount];
            clip.GetLocalPoses(f, local);
            for (int j = 0; j < local.Length; j++)
                if (s.GetParent(j) < 0)
                    local[j] = new AvatarGo.Core.RigidPose(System.Numerics.Vector3.Transform(local[j].Position, turn), System.Numerics.Quaternion.Normalize(turn * local[j].Rotation));
            frames.Add(local);
        }
        return AvatarGo.Core.BvhClip.FromPoses(s, frames, clip.FrameTime);
    }

    [Test]
    public void BrokenFileIsAOneLineErrorWithExitCode1()
    {
        string text = File.ReadAllText(Paths.Mocap("mocapbank_30fps.bvh"));
        string path = Path.Combine(Path.GetTempPath(), "avatargo-broken-" + Guid.NewGuid().ToString("N") + ".bvh");
        File.WriteAllText(path, text.Substring(0, text.Length / 2));
        try
        {
            foreach (string cmd in new[] { "info", "positions" })
            {
                var r = CliRunner.Run("bvh", cmd, path);
                Assert.That(r.ExitCode, Is.EqualTo(1));
                Assert.That(r.Stderr.TrimEnd().Split('\n').Length, Is.EqualTo(1), r.Stderr);
                StringAssert.Contains(".bvh:", r.Stderr);
            }
            Assert.That(CliRunner.Run("bvh", "info", path + ".missing").ExitCode, Is.EqualTo(1));
        }
        finally { File.Delete(path); }
    }

    /// <summary>
    /// Reference forward kinematics written independently of the package: double precision, 4×4
    /// column-vector matrices in BVH's own right-handed frame, the simplest possible parse.
    /// </summary>
    private static class ReferenceFk
    {
        public static double[][] Positions(string path, double scale)
        {
            string[] tokens = File.ReadAllText(path).Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
            var joints = new List<(int parent, double[] offset, string[] channels, bool end)>();
            var stack = new Stack<int>();
            int i = 0, pending = -1;
            bool pendingEnd = false;
            while (tokens[i] != "MOTION")
            {
                string t = tokens[i++];
                if (t == "ROOT" || t == "JOINT") { pending = joints.Count; pendingEnd = false; i++; }
                else if (t == "End") { pending = joints.Count; pendingEnd = true; i++; }
                else if (t == "{")
                {
                    joints.Add((stack.Count > 0 ? stack.Peek() : -1, new double[3], new string[0], pendingEnd));
                    stack.Push(pending);
                }
                else if (t == "}") stack.Pop();
                else if (t == "OFFSET")
                {
                    var j = joints[stack.Peek()];
                    for (int k = 0; k < 3; k++) j.offset[k] = double.Parse(tokens[i++], CultureInfo.InvariantCulture);
                }
                else if (t == "CHANNELS")
                {
                    int n = int.Parse(tokens[i++], CultureInfo.InvariantCulture);
                    var j = joints[stack.Peek()];
                    joints[stack.Peek()] = (j.parent, j.offset, tokens.Skip(i).Take(n).ToArray(), j.end);
                    i += n;
                }
            }
            i++; // MOTION
            i++; int frames = int.Parse(tokens[i++], CultureInfo.InvariantCulture); // Frames: N
            i += 2; i++; // Frame Time: t
            var result = new double[frames][];
            int outputs = joints.Count(j => !j.end);
            for (int f = 0; f < frames; f++)
            {
                var world = new double[joints.Count][,];
                result[f] = new double[outputs * 3];
                int o = 0;
                for (int j = 0; j < joints.Count; j++)
                {
                    var (parent, offset, channels, end) = joints[j];
                    double[] t = (double[])offset.Clone();
                    double[,] m = Identity();
                    foreach (string c in channels)
                    {
                        double v = double.Parse(tokens[i++], CultureInfo.InvariantCulture);
                        switch (c)
                        {
                            case "Xposition": t[0] = v; break;
                            case "Yposition": t[1] = v; break;
                            case "Zposition": t[2] = v; break;
                            default: m = Mul(m, Rot(c[0], v)); break;
                        }
                    }
                    m[0, 3] = t[0] * scale; m[1, 3] = t[1] * scale; m[2, 3] = t[2] * scale;
                    world[j] = parent < 0 ? m : Mul(world[parent], m);
                    if (!end)
                    {
                        result[f][o++] = world[j][0, 3]; result[f][o++] = world[j][1, 3]; result[f][o++] = world[j][2, 3];
                    }
                }
            }
            return result;
        }

        private static double[,] Identity() => new double[,] { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };

        private static double[,] Rot(char axis, double degrees)
        {
            double a = degrees * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            return axis switch
            {
                'X' => new double[,] { { 1, 0, 0, 0 }, { 0, c, -s, 0 }, { 0, s, c, 0 }, { 0, 0, 0, 1 } },
                'Y' => new double[,] { { c, 0, s, 0 }, { 0, 1, 0, 0 }, { -s, 0, c, 0 }, { 0, 0, 0, 1 } },
                _ => new double[,] { { c, -s, 0, 0 }, { s, c, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } },
            };
        }

        private static double[,] Mul(double[,] a, double[,] b)
        {
            var r = new double[4, 4];
            for (int x = 0; x < 4; x++)
                for (int y = 0; y < 4; y++)
                    for (int k = 0; k < 4; k++) r[x, y] += a[x, k] * b[k, y];
            return r;
        }
    }
}
