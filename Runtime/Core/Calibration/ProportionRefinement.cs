using System;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Refines the avatar's arm lengths from a short guided exercise after calibration (arm circles and reaches with the
    /// arms stretched, then squats): fed every solved frame of the exercise (<see cref="Add"/>, allocation-free), it
    /// records for each arm where its controller is (the hand targets given to <see cref="Add"/>, as the pipeline passes
    /// them: the controllers' poses, not the wrists' goals) and for each leg the distance from its hip joint on the solved
    /// avatar to the ankle's goal, and at the end (<see cref="Solve"/>) turns the arms' robust longest reach
    /// (<see cref="Percentile"/>) into the arm length that reach needs.
    /// </summary>
    /// <remarks>
    /// <para>The arms, for every hand: the controllers do not depend on the avatar's arm length (the wrists' goals do
    /// where the wrist is placed by the offset measured at the walk-in, <see cref="HandPlacement.CalibratedOffset"/>: that
    /// offset turns with the hand and keeps a stretched arm's goal at the avatar's own length). The reach is measured from
    /// the centre of the sphere the controller moves on in the hips target's frame (the pelvis tracker's; a least-squares
    /// fit, <see cref="LimbRefinement.ShoulderOffset"/>), not from the avatar's solved shoulder, which the solver moves
    /// (leaning the spine toward a target out of reach); where that fit is ill-posed (too little motion, a centre more
    /// than <see cref="MaxShoulderOffset"/> from the avatar's shoulder, no hips target) from the avatar's shoulder. The
    /// reach is then turned into an arm length by scaling the avatar's arm until its stretched T-pose holds the controller
    /// that far from the shoulder, the grip placed as <see cref="ProportionFitter"/> places it (the palm of the finger bones,
    /// or the palm estimated from the forearm, <see cref="HandModel.PalmWithoutFingers"/>, which grows with the arm). A refined
    /// arm is held within <see cref="ProportionSettings.MinRatio"/>…<see cref="ProportionSettings.MaxRatio"/> and changed only
    /// when its residual exceeds <see cref="Tolerance"/>.</para>
    /// <para>The legs are reported, never refined: the exact offsets put the hips' and ankles' targets where the avatar's
    /// joints were at the walk-in, so standing the ankle targets are exactly the avatar's leg length from the hip joints
    /// whatever the wearer's legs are; a leg length wrong by the pelvis strap's offset and that offset trade off, and squats
    /// (knees bent) only shorten the distance.</para>
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
        private readonly Vector3[][] _inTorso = new Vector3[2][];   // the arms' targets in the hips target's frame
        private readonly int[] _torsoCounts = new int[2];
        private readonly Vector3[] _shoulderInTorso = new Vector3[2]; // the avatar's shoulder joint in the hips joint's frame
        private readonly float[] _handleRadius = new float[2];
        private readonly float[] _gripReach = new float[2];           // the avatar's shoulder-to-controller distance, arm stretched
        private int _frames;
        private bool _truncated;

        /// <summary>
        /// Prepares a refinement of <paramref name="scaledAvatar"/> (the calibrated avatar, with proportions
        /// <paramref name="current"/>), recording up to <paramref name="capacity"/> frames (20 s at 90 Hz by default); the
        /// controllers' handles have the radii given (m; those of the hands' controller profiles, 2 cm without one).
        /// </summary>
        /// <exception cref="ArgumentException">The avatar lacks a required bone, or the capacity is not positive.</exception>
        public ProportionRefinement(HumanoidMap scaledAvatar, BodyProportions current, ProportionSettings settings, int capacity = 1800,
            float leftHandleRadius = ProportionFitter.DefaultHandleRadius, float rightHandleRadius = ProportionFitter.DefaultHandleRadius)
        {
            _avatar = scaledAvatar ?? throw new ArgumentNullException(nameof(scaledAvatar));
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            if (capacity <= 0) throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "The capacity must be positive.");
            if (!current.IsValid) throw new ArgumentException($"Proportions must be positive and finite: {current}.", nameof(current));
            scaledAvatar.RequireComplete(nameof(scaledAvatar));
            _current = current;
            Capacity = capacity;
            _handleRadius[0] = leftHandleRadius;
            _handleRadius[1] = rightHandleRadius;
            var tpose = new SkeletonPose(scaledAvatar.Skeleton);
            TPoser.Apply(scaledAvatar, tpose, RigidPose.Identity);
            RigidPose[] rest = tpose.World;
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
                if (l < 2)
                {
                    _shoulderInTorso[l] = rest[scaledAvatar[HumanoidBone.Hips]].InverseTransformPoint(rest[r].Position);
                    _inTorso[l] = new Vector3[capacity];
                }
            }
            for (int a = 0; a < 2; a++) _gripReach[a] = GripReach((BodySide)a, 1f);
        }

        // The avatar's shoulder-to-controller distance in its T-pose (arm stretched) with the arm on that side scaled by k.
        private float GripReach(BodySide side, float k)
        {
            HumanoidMap map = k == 1f ? _avatar : new BodyProportions(1f, 1f, side == BodySide.Left ? k : 1f, side == BodySide.Right ? k : 1f).Apply(_avatar, 1f);
            var pose = new SkeletonPose(map.Skeleton);
            TPoser.Apply(map, pose, RigidPose.Identity);
            Vector3 shoulder = pose.World[map[HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side)]].Position;
            return Vector3.Distance(shoulder, ProportionFitter.GripPose(map, pose, side, _handleRadius[(int)side]).Position);
        }

        // The arm scale k whose grip reach is `reach` (secant steps from k = 1; the reach is nearly linear in k).
        private float ScaleForReach(BodySide side, float reach)
        {
            float k0 = 1f, d0 = _gripReach[(int)side] - reach;
            float k1 = reach / _gripReach[(int)side], d1 = GripReach(side, k1) - reach;
            for (int i = 0; i < 4 && Math.Abs(d1) > 1e-4f && Math.Abs(d1 - d0) > 1e-7f; i++)
            {
                float k2 = k1 - d1 * (k1 - k0) / (d1 - d0);
                k0 = k1; d0 = d1;
                k1 = Math.Max(0.2f, Math.Min(5f, k2));
                d1 = GripReach(side, k1) - reach;
            }
            return k1;
        }
        /// <summary>The robust "longest" distance: this fraction of the exercise's frames has a shorter one (0.95).</summary>
        public const float Percentile = 0.95f;

        /// <summary>How many frames can be recorded.</summary>
        public int Capacity { get; }

        /// <summary>Smallest residual (m) that changes a limb (1 cm: the controllers' tolerance of the fit).</summary>
        public float Tolerance { get; set; } = 0.01f;

        /// <summary>Fewest frames with a limb's target tracked for the limb to be refined (60: under a second at 90 Hz).</summary>
        public int MinimumSamples { get; set; } = DefaultMinimumSamples;

        /// <summary>The default of <see cref="MinimumSamples"/> (60 frames), the one the pipeline's refinement uses.</summary>
        public const int DefaultMinimumSamples = 60;

        /// <summary>True between <see cref="Begin"/> and <see cref="Solve"/>.</summary>
        public bool IsRecording { get; private set; }

        /// <summary>Starts (or restarts) recording: everything recorded before is discarded.</summary>
        public void Begin()
        {
            for (int l = 0; l < 4; l++) _counts[l] = 0;
            _torsoCounts[0] = _torsoCounts[1] = 0;
            _frames = 0;
            _truncated = false;
            IsRecording = true;
        }

        /// <summary>
        /// Records one solved frame: <paramref name="targets"/> the frame's targets, with the hands' goals the controllers'
        /// poses (see the class remarks), and <paramref name="pose"/> the avatar solved to them (of the avatar given at
        /// construction). Ignored when not recording; a limb whose target is inactive or not finite is skipped. Allocates nothing.
        /// </summary>
        public void Add(in BodyTargets targets, SkeletonPose pose)
        {
            if (!IsRecording || pose == null) return;
            if (_frames >= Capacity) { _truncated = true; return; }
            _frames++;
            RigidPose[] w = pose.World;
            Record(0, in targets.LeftHand, w, in targets);
            Record(1, in targets.RightHand, w, in targets);
            Record(2, in targets.LeftFoot, w, in targets);
            Record(3, in targets.RightFoot, w, in targets);
        }

        private void Record(int limb, in LimbTarget target, RigidPose[] world, in BodyTargets targets)
        {
            if (!target.IsActive) return;
            float d = Vector3.Distance(world[_roots[limb]].Position, target.Goal.Position);
            if (!Vectors.IsFinite(d)) return;
            if (limb < 2 && targets.HipsActive && targets.Hips.IsValid)
                _inTorso[limb][_torsoCounts[limb]++] = targets.Hips.InverseTransformPoint(target.Goal.Position);
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
            var centreOffset = new float[4];
            for (int l = 0; l < 4; l++) reach[l] = RobustMax(_distances[l], _counts[l]);
            for (int a = 0; a < 2; a++)
            {
                // The wearer's own shoulder: the centre of the sphere the stretched arm's targets lie on in the hips target's
                // frame (the pelvis tracker's), so that the avatar's shoulder, where the solver puts it (leaning the avatar's
                // spine toward a target out of reach, for one), does not count as arm.
                centreOffset[a] = float.NaN;
                int n = _torsoCounts[a];
                if (n < MinimumSamples || !FitSphereCentre(_inTorso[a], n, out Vector3 centre)) continue;
                float offset = Vector3.Distance(centre, _shoulderInTorso[a]);
                if (offset > MaxShoulderOffset) continue; // an ill-posed fit (the arm not moved enough, or bent): the avatar's shoulder
                var around = new float[n];
                for (int i = 0; i < around.Length; i++) around[i] = Vector3.Distance(_inTorso[a][i], centre);
                reach[a] = RobustMax(around, around.Length);
                centreOffset[a] = offset;
            }
            // The controllers' reach as the arm length that gives it: the avatar's arm, scaled, until its stretched T-pose
            // holds the controller that far from the shoulder (the grip placed as ProportionFitter places it).
            for (int a = 0; a < 2; a++)
                if (!float.IsNaN(reach[a])) reach[a] = _lengths[a] * ScaleForReach((BodySide)a, reach[a]);
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
                report.Limbs[a] = new LimbRefinement(_counts[a], _lengths[a], reach[a], after, refined[a], centreOffset[a]);
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

        /// <summary>
        /// Farthest (m) the fitted centre of an arm's motion may be from the avatar's shoulder joint for the reach to be
        /// measured from it (10 cm); farther, the fit is taken as ill-posed and the reach is measured from the avatar's
        /// shoulder (<see cref="LimbRefinement.ShoulderOffset"/> is then NaN).
        /// </summary>
        public const float MaxShoulderOffset = 0.1f;

        // The least-squares sphere through n points (algebraic: |p|^2 = 2 c.p + k), its centre; false when the points do not
        // span the three dimensions well enough for one (an arm moved in a plane only).
        private static bool FitSphereCentre(Vector3[] points, int n, out Vector3 centre)
        {
            centre = default;
            Vector3 mean = Vector3.Zero;
            for (int i = 0; i < n; i++) mean += points[i];
            mean /= n;
            var m = new double[4, 5];
            for (int i = 0; i < n; i++)
            {
                Vector3 q = points[i] - mean; // centred for conditioning
                double[] row = { q.X, q.Y, q.Z, 1.0, q.LengthSquared() };
                for (int r = 0; r < 4; r++)
                    for (int c = 0; c < 5; c++) m[r, c] += row[r] * row[c];
            }
            // Too small a cloud (under 3 cm of standard deviation per axis on average); a flat one fails the pivots below.
            double trace = m[0, 0] + m[1, 1] + m[2, 2];
            if (trace / n < 3 * 0.03 * 0.03) return false;
            for (int k = 0; k < 4; k++)
            {
                int pivot = k;
                for (int r = k + 1; r < 4; r++) if (Math.Abs(m[r, k]) > Math.Abs(m[pivot, k])) pivot = r;
                if (Math.Abs(m[pivot, k]) < 1e-12 * Math.Max(1.0, trace)) return false;
                for (int c = 0; c < 5; c++) { double t = m[k, c]; m[k, c] = m[pivot, c]; m[pivot, c] = t; }
                for (int r = 0; r < 4; r++)
                {
                    if (r == k) continue;
                    double f = m[r, k] / m[k, k];
                    for (int c = k; c < 5; c++) m[r, c] -= f * m[k, c];
                }
            }
            // Unknowns (2cx, 2cy, 2cz, k) of |q|^2 = 2c.q + k.
            centre = mean + new Vector3((float)(0.5 * m[0, 4] / m[0, 0]), (float)(0.5 * m[1, 4] / m[1, 1]), (float)(0.5 * m[2, 4] / m[2, 2]));
            return Vectors.IsFinite(centre);
        }

        private static string Mm(float metres) => float.IsNaN(metres) ? "n/a" : FormattableString.Invariant($"{metres * 1000:+0.0;-0.0;0.0}");

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
