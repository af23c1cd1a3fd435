using System;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Refines the avatar's arm lengths from a short guided exercise after calibration (arm circles and reaches with the
    /// arms stretched, then squats): fed every solved frame of the exercise (<see cref="Add"/>, allocation-free), it
    /// records each limb's distance from its root joint on the solved avatar (shoulder, hip joint) to its target (the
    /// wrist's goal, the ankle's goal), and at the end (<see cref="Solve"/>) takes the robust longest one
    /// (<see cref="Percentile"/>) as the length the limb needs for its target to be reachable.
    /// </summary>
    /// <remarks>
    /// <para>What the motion identifies, and what it does not (Documentation~/calibration.md): an arm's reach, where the hand
    /// is placed from the palm on the controller (<see cref="HandPlacement.PalmOnController"/>), so its target does not
    /// depend on the arm's length: with the arm stretched the target is as far from the avatar's shoulder as the arm must
    /// be long. A refined arm is held within <see cref="ProportionSettings.MinRatio"/>…<see cref="ProportionSettings.MaxRatio"/>
    /// and changed only when its residual exceeds <see cref="Tolerance"/>. The legs are reported, never refined: the exact
    /// offsets put the hips' and ankles' targets where the avatar's joints were at the walk-in, so standing the ankle
    /// targets are exactly the avatar's leg length from the hip joints whatever the wearer's legs are; a leg length wrong
    /// by the pelvis strap's offset and that offset trade off, and squats (knees bent) only shorten the distance.</para>
    /// <para>Where the hand is placed by the offset measured at the walk-in (<see cref="HandPlacement.CalibratedOffset"/>),
    /// that offset turns with the hand and keeps a stretched arm's target at the avatar's arm length: the exercise then
    /// shows nothing to refine, and nothing is.</para>
    /// </remarks>
    public sealed class ProportionRefinement
    {
        private readonly HumanoidMap _avatar;
        private readonly ProportionSettings _settings;
        private readonly BodyProportions _current;
        private readonly float[][] _distances = new float[4][];
        private readonly int[] _counts = new int[4];
        private readonly float[] _lengths = new float[4];
        private readonly int[] _roots = new int[4];
        private int _frames;
        private bool _truncated;

        /// <summary>
        /// Prepares a refinement of <paramref name="scaledAvatar"/> (the calibrated avatar, with proportions
        /// <paramref name="current"/>), recording up to <paramref name="capacity"/> frames (20 s at 90 Hz by default).
        /// </summary>
        /// <exception cref="ArgumentException">The avatar lacks a required bone, or the capacity is not positive.</exception>
        public ProportionRefinement(HumanoidMap scaledAvatar, BodyProportions current, ProportionSettings settings, int capacity = 1800)
        {
            _avatar = scaledAvatar ?? throw new ArgumentNullException(nameof(scaledAvatar));
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            if (capacity <= 0) throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "The capacity must be positive.");
            if (!current.IsValid) throw new ArgumentException($"Proportions must be positive and finite: {current}.", nameof(current));
            scaledAvatar.RequireComplete(nameof(scaledAvatar));
            _current = current;
            Capacity = capacity;
            Skeleton s = scaledAvatar.Skeleton;
            var local = new RigidPose[s.JointCount];
            var rest = new RigidPose[s.JointCount];
            s.GetRestLocal(local);
            s.ComputeWorld(local, rest); // distances between joints do not depend on the pose
            for (int l = 0; l < 4; l++)
            {
                _distances[l] = new float[capacity];
                BodySide side = (BodySide)(l % 2);
                HumanoidBone root = l < 2 ? HumanoidBone.LeftUpperArm : HumanoidBone.LeftUpperLeg;
                HumanoidBone middle = l < 2 ? HumanoidBone.LeftLowerArm : HumanoidBone.LeftLowerLeg;
                HumanoidBone end = l < 2 ? HumanoidBone.LeftHand : HumanoidBone.LeftFoot;
                int r = scaledAvatar[HumanoidBones.OnSide(root, side)], m = scaledAvatar[HumanoidBones.OnSide(middle, side)], e = scaledAvatar[HumanoidBones.OnSide(end, side)];
                _roots[l] = r;
                _lengths[l] = Vector3.Distance(rest[r].Position, rest[m].Position) + Vector3.Distance(rest[m].Position, rest[e].Position);
            }
        }

        /// <summary>The robust "longest" distance: this fraction of the exercise's frames has a shorter one (0.95).</summary>
        public const float Percentile = 0.95f;

        /// <summary>How many frames can be recorded.</summary>
        public int Capacity { get; }

        /// <summary>Smallest residual (m) that changes a limb (1 cm: the controllers' tolerance of the fit).</summary>
        public float Tolerance { get; set; } = 0.01f;

        /// <summary>Fewest frames with a limb's target tracked for the limb to be refined (60: under a second at 90 Hz).</summary>
        public int MinimumSamples { get; set; } = 60;

        /// <summary>True between <see cref="Begin"/> and <see cref="Solve"/>.</summary>
        public bool IsRecording { get; private set; }

        /// <summary>Starts (or restarts) recording: everything recorded before is discarded.</summary>
        public void Begin()
        {
            for (int l = 0; l < 4; l++) _counts[l] = 0;
            _frames = 0;
            _truncated = false;
            IsRecording = true;
        }

        /// <summary>
        /// Records one solved frame: <paramref name="targets"/> the frame's targets and <paramref name="pose"/> the avatar
        /// solved to them (of the avatar given at construction). Ignored when not recording; a limb whose target is inactive
        /// or not finite is skipped. Allocates nothing.
        /// </summary>
        public void Add(in BodyTargets targets, SkeletonPose pose)
        {
            if (!IsRecording || pose == null) return;
            if (_frames >= Capacity) { _truncated = true; return; }
            _frames++;
            RigidPose[] w = pose.World;
            Record(0, in targets.LeftHand, w);
            Record(1, in targets.RightHand, w);
            Record(2, in targets.LeftFoot, w);
            Record(3, in targets.RightFoot, w);
        }

        private void Record(int limb, in LimbTarget target, RigidPose[] world)
        {
            if (!target.IsActive) return;
            float d = Vector3.Distance(world[_roots[limb]].Position, target.Goal.Position);
            if (!Vectors.IsFinite(d)) return;
            _distances[limb][_counts[limb]++] = d;
        }

        /// <summary>
        /// Ends recording and refines: each arm whose robust longest reach differs from its length by more than
        /// <see cref="Tolerance"/> gets the length that reach needs (per side with <see cref="ProportionSettings.PerSide"/>,
        /// else both arms together), held within the settings' limits; the legs are reported only. Allocates (sorts a copy).
        /// </summary>
        public RefinementReport Solve()
        {
            IsRecording = false;
            var report = new RefinementReport { Frames = _frames, Truncated = _truncated, Before = _current };
            var reach = new float[4];
            for (int l = 0; l < 4; l++) reach[l] = RobustMax(_distances[l], _counts[l]);
            float[] ratio = { _current.LeftArm, _current.RightArm };
            bool[] refined = new bool[2];
            var why = new StringBuilder();
            bool enough = _counts[0] >= MinimumSamples && _counts[1] >= MinimumSamples;
            if (_settings.PerSide)
            {
                for (int a = 0; a < 2; a++)
                {
                    bool ok = _counts[a] >= MinimumSamples && Math.Abs(reach[a] - _lengths[a]) > Tolerance;
                    if (ok) { ratio[a] = Limit(_current.Arm((BodySide)a) * reach[a] / _lengths[a]); refined[a] = true; }
                }
            }
            else if (enough && Math.Abs(0.5f * (reach[0] + reach[1] - _lengths[0] - _lengths[1])) > Tolerance)
            {
                // One ratio for both arms: the mean of what each side's reach asks for.
                float r = Limit(0.5f * (_current.LeftArm * reach[0] / _lengths[0] + _current.RightArm * reach[1] / _lengths[1]));
                ratio[0] = ratio[1] = r;
                refined[0] = refined[1] = true;
            }
            for (int a = 0; a < 2; a++)
            {
                float after = refined[a] ? _lengths[a] * ratio[a] / _current.Arm((BodySide)a) : _lengths[a];
                report.Limbs[a] = new LimbRefinement(_counts[a], _lengths[a], reach[a], after, refined[a]);
            }
            for (int l = 2; l < 4; l++) report.Limbs[l] = new LimbRefinement(_counts[l], _lengths[l], reach[l], _lengths[l], false);
            report.After = new BodyProportions(_current.LeftLeg, _current.RightLeg, ratio[0], ratio[1]);
            why.Append(FormattableString.Invariant(
                $"arms {(refined[0] || refined[1] ? "refined" : "kept")}: reach {Mm(reach[0] - _lengths[0])} / {Mm(reach[1] - _lengths[1])} mm beyond the arms' length (tolerance {Tolerance * 1000:0} mm, {_counts[0]} / {_counts[1]} frames, at least {MinimumSamples})"));
            why.Append(FormattableString.Invariant(
                $"; legs reported, not refined (the exact offsets hold the ankle targets at the avatar's leg length standing; leg length and pelvis strap offset are not separable): {Mm(reach[2] - _lengths[2])} / {Mm(reach[3] - _lengths[3])} mm"));
            if (_truncated) why.Append(FormattableString.Invariant($"; only the first {Capacity} frames were used"));
            report.Explanation = why.ToString();
            return report;
        }

        private static string Mm(float metres) => float.IsNaN(metres) ? "n/a" : FormattableString.Invariant($"{metres * 1000:+0.0;-0.0}");

        private float Limit(float ratio) => Math.Min(_settings.MaxRatio, Math.Max(_settings.MinRatio, ratio));

        // The Percentile-th of the first n values (NaN for none), on a sorted copy.
        private static float RobustMax(float[] values, int n)
        {
            if (n == 0) return float.NaN;
            var copy = new float[n];
            Array.Copy(values, copy, n);
            Array.Sort(copy);
            return copy[Math.Min(n - 1, (int)Math.Floor(Percentile * (n - 1) + 0.5f))];
        }
    }
}
