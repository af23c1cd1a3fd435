using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// The assertions shared by the play-mode tests (<c>Tests/Runtime</c>) and their engine-free twins (<c>Tests/Core</c>):
    /// fed, every calibrated frame, the avatar's bone positions (read from the scene's transforms in play mode, from the
    /// pipeline's pose the drivers copy in the twin) and the session's ground truth, it says what is out of the core tests'
    /// tolerances. Both sides call <c>Failures</c> and assert it is empty, so they check the same numbers.
    /// </summary>
    public sealed class ReplayCheck
    {
        /// <summary>End effectors (hips, head, wrists, ankles): median error bound, as the core's PipelineTests (mm).</summary>
        public const double EndEffectorMedianMm = 5.0;

        /// <summary>End effectors: 95th percentile bound, as the core's PipelineTests (mm).</summary>
        public const double EndEffectorP95Mm = 15.0;

        /// <summary>Knees and elbows: median error bound, as the core's RestConventionTests (mm).</summary>
        public const double MidJointMedianMm = 35.0;

        /// <summary>Knees and elbows: 95th percentile bound, as the core's RestConventionTests (mm).</summary>
        public const double MidJointP95Mm = 100.0;

        /// <summary>Knee angle error: median bound, as the core's LongerLegs test (degrees).</summary>
        public const double KneeAngleMedianDegrees = 5.0;

        /// <summary>The deepest a finger point may be inside the controller's surface (mm), the fingers' bar.</summary>
        public const double FingerPenetrationMm = 1.0;

        /// <summary>The largest frame-to-frame jump of an end effector beyond the truth's own motion (mm), the tracking-loss bar.</summary>
        public const double JumpMm = 20.0;

        private readonly Vector3[] _lastAvatar = new Vector3[6], _lastTruth = new Vector3[6];
        private readonly bool[] _hasLast = new bool[6];

        /// <summary>End-effector position errors (mm).</summary>
        public ErrorSeries EndEffectorMm { get; } = new ErrorSeries();

        /// <summary>Knee and elbow position errors (mm).</summary>
        public ErrorSeries MidJointMm { get; } = new ErrorSeries();

        /// <summary>Knee angle errors (degrees).</summary>
        public ErrorSeries KneeAngleDegrees { get; } = new ErrorSeries();

        /// <summary>The deepest finger point inside a controller over every frame (mm; 0 or less: none inside).</summary>
        public double MaxFingerPenetrationMm { get; private set; } = double.NegativeInfinity;

        /// <summary>The largest frame-to-frame move of an end effector beyond the truth's move on that frame (mm).</summary>
        public double MaxExcessJumpMm { get; private set; }

        /// <summary>Frames measured.</summary>
        public int Frames { get; private set; }

        /// <summary>Frames on which a hand with finger IK held its controller.</summary>
        public int HoldingFrames { get; private set; }

        /// <summary>Frames measured whose samples (as given to <see cref="Add"/>) report some device untracked.</summary>
        public int FramesWithAnUntrackedDevice { get; private set; }

        /// <summary>
        /// Measures one calibrated frame: <paramref name="avatar"/> gives a bone's world position (tracking space = world in the
        /// tests), or null when the avatar lacks it; <paramref name="frame"/> carries the truth; the pipeline's hands give
        /// the fingers' distances to the controller surface.
        /// </summary>
        public void Add(SessionFrame frame, Func<HumanoidBone, Vector3?> avatar, SelfAvatarPipeline pipeline)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            Frames++;
            for (int d = 0; d < frame.Samples.Length; d++)
                if (!frame.Samples[d].IsTracked) { FramesWithAnUntrackedDevice++; break; }
            for (int e = 0; e < HumanoidBones.EndEffectors.Length; e++)
            {
                HumanoidBone bone = HumanoidBones.EndEffectors[e];
                Measure(frame, avatar, bone, EndEffectorMm);
                Vector3? p = avatar(bone);
                if (p == null || !frame.HasTruth[(int)bone]) continue;
                Vector3 t = frame.Truth[(int)bone].Position;
                if (_hasLast[e])
                    MaxExcessJumpMm = Math.Max(MaxExcessJumpMm, ((p.Value - _lastAvatar[e]) - (t - _lastTruth[e])).Length() * 1000.0);
                _lastAvatar[e] = p.Value;
                _lastTruth[e] = t;
                _hasLast[e] = true;
            }
            foreach (HumanoidBone bone in HumanoidBones.MidJoints) Measure(frame, avatar, bone, MidJointMm);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HumanoidBone hip = HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side);
                HumanoidBone knee = HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side);
                HumanoidBone ankle = HumanoidBones.OnSide(HumanoidBone.LeftFoot, side);
                Vector3? h = avatar(hip), k = avatar(knee), a = avatar(ankle);
                if (!frame.HasTruth[(int)hip] || !frame.HasTruth[(int)knee] || !frame.HasTruth[(int)ankle] || h == null || k == null || a == null) continue;
                KneeAngleDegrees.Add(Math.Abs(Angle(h.Value, k.Value, a.Value) - Angle(frame.Truth[(int)hip].Position, frame.Truth[(int)knee].Position, frame.Truth[(int)ankle].Position)));
            }
            if (pipeline == null) return;
            bool holding = false;
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HandState hand = pipeline.Hand(side);
                if (!hand.HasFingerIk || !hand.Holding) continue;
                holding = true;
                for (Finger f = Finger.Thumb; f <= Finger.Little; f++)
                    for (FingerPoint p = FingerPoint.IntermediateJoint; p <= FingerPoint.Tip; p++)
                    {
                        float gap = hand.SurfaceGap(f, p);
                        if (!float.IsNaN(gap)) MaxFingerPenetrationMm = Math.Max(MaxFingerPenetrationMm, -gap * 1000.0);
                    }
            }
            if (holding) HoldingFrames++;
        }

        /// <summary>What is out of tolerance, one line each; empty when the avatar followed the recording.</summary>
        public List<string> Failures(int minimumFrames) => Failures(minimumFrames, accuracy: true);

        /// <summary>
        /// What is out of tolerance; with <paramref name="accuracy"/> false only the frame count, finite positions, the fingers
        /// and the jumps are checked (a lost tracker's frames are not expected to be exact).
        /// </summary>
        public List<string> Failures(int minimumFrames, bool accuracy)
        {
            var failures = new List<string>();
            if (Frames < minimumFrames) failures.Add($"only {Frames} calibrated frames were measured (at least {minimumFrames} expected)");
            if (EndEffectorMm.InvalidCount + MidJointMm.InvalidCount > 0) failures.Add("a joint position was NaN or infinite");
            Bound(failures, "largest end-effector jump beyond the wearer's motion (mm)", MaxExcessJumpMm, JumpMm);
            if (!accuracy) return failures;
            Bound(failures, "end-effector median (mm)", EndEffectorMm.Median, EndEffectorMedianMm);
            Bound(failures, "end-effector p95 (mm)", EndEffectorMm.P95, EndEffectorP95Mm);
            // Knees and elbows: the bounds RestConventionTests holds the pipeline to.
            Bound(failures, "knee and elbow median (mm)", MidJointMm.Median, MidJointMedianMm);
            Bound(failures, "knee and elbow p95 (mm)", MidJointMm.P95, MidJointP95Mm);
            Bound(failures, "knee angle median (deg)", KneeAngleDegrees.Median, KneeAngleMedianDegrees);
            if (HoldingFrames > 0 && MaxFingerPenetrationMm > FingerPenetrationMm)
                failures.Add($"a finger was {MaxFingerPenetrationMm:0.00} mm inside the controller (at most {FingerPenetrationMm} mm)");
            return failures;
        }

        /// <summary>The measured numbers, for the test's output.</summary>
        public override string ToString() =>
            $"{Frames} frames: end effectors median {EndEffectorMm.Median:0.0} mm, p95 {EndEffectorMm.P95:0.0} mm; knees and elbows median {MidJointMm.Median:0.0} mm, p95 {MidJointMm.P95:0.0} mm; " +
            $"knee angle median {KneeAngleDegrees.Median:0.0} deg; largest excess jump {MaxExcessJumpMm:0.0} mm; fingers holding on {HoldingFrames} frames, deepest {MaxFingerPenetrationMm:0.00} mm";

        private static void Measure(SessionFrame frame, Func<HumanoidBone, Vector3?> avatar, HumanoidBone bone, ErrorSeries series)
        {
            Vector3? p = avatar(bone);
            if (!frame.HasTruth[(int)bone] || p == null) return;
            series.Add(Vector3.Distance(p.Value, frame.Truth[(int)bone].Position) * 1000.0);
        }

        private static void Bound(List<string> failures, string what, double value, double bound)
        {
            if (!(value <= bound)) failures.Add($"{what} {value:0.00} is over {bound}");
        }

        private static double Angle(Vector3 hip, Vector3 knee, Vector3 ankle)
        {
            Vector3 a = Vector3.Normalize(hip - knee), b = Vector3.Normalize(ankle - knee);
            return Math.Acos(Math.Max(-1.0, Math.Min(1.0, Vector3.Dot(a, b)))) * 180.0 / Math.PI;
        }
    }
}
