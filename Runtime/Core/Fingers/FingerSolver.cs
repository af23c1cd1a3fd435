using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Closes the fingers of one hand on a controller by minimising, per finger, the paper's cost: the sum over the
    /// finger's moving points (intermediate and distal joints, fingertip) of their distance to the controller's
    /// surface, negative distances (penetration) multiplied by <see cref="Penalty"/> before taking the absolute value
    /// — plus the thumb tip toward the thumb rest and the index tip toward the trigger, and a small term keeping a
    /// finger's three joints curling together. Distances are measured from the finger's surface (joint centre minus
    /// <see cref="HandModel.FingerRadius"/>), so contact means skin on plastic, not bone.
    /// </summary>
    /// <remarks>
    /// Each frame runs projected gradient descent to convergence (Polyak step size with backtracking, analytic
    /// gradients from the SDF gradients and the joints' rotation axes, parameters clamped to [0, 1]), started
    /// every frame from the grip solved once for the nominal hold (not from the last frame); it stops when no parameter moves more than 2e-3 (0.2° at a joint) or after <see cref="MaxIterations"/>.
    /// The result therefore depends on the controller's pose, not on the frame rate. No allocation per frame.
    /// </remarks>
    public sealed class FingerSolver
    {
        /// <summary>Multiplier of penetration depths in the cost (the paper's penalisation factor).</summary>
        public const float Penalty = 30f;

        /// <summary>Iteration cap per finger per frame.</summary>
        public const int MaxIterations = 60;

        /// <summary>Weight of the thumb-rest and trigger goals relative to surface distances.</summary>
        public const float GoalWeight = 0.5f;

        /// <summary>Weight (metres) of the term that keeps a finger's joints curling together.</summary>
        public const float Smoothness = 0.03f;

        /// <summary>When the palm is farther than this from the controller's surface (m), the hand opens: nothing to hold.</summary>
        public const float ReachDistance = 0.03f;

        private readonly HandModel _hand;
        private readonly ControllerProfile _profile;
        private readonly float[] _solved = new float[15];
        private readonly float[] _start = new float[15];
        private readonly float[] _t = new float[15];
        private readonly Vector3[] _points = new Vector3[3];
        private readonly Vector3[] _pointGradients = new Vector3[3];
        private Pose _handInController;
        private readonly Pose[] _fingerBase = new Pose[5];

        /// <summary>Creates a solver for one hand and one controller.</summary>
        public FingerSolver(HandModel hand, ControllerProfile profile)
        {
            _hand = hand ?? throw new ArgumentNullException(nameof(hand));
            _profile = profile ?? throw new ArgumentNullException(nameof(profile));
            // The start of every frame's descent: the grip solved once, from half-closed, with the controller
            // exactly where this hand holds it. Near every frame's answer, and the same whatever the frame rate.
            for (int i = 0; i < 15; i++) _start[i] = 0.5f;
            Solve(Pose.Identity, hand.ControllerInHand(profile), GripMode.Hold);
            Array.Copy(_solved, _start, 15);
            Array.Clear(_solved, 0, 15);
            Array.Clear(_t, 0, 15);
        }

        /// <summary>The hand.</summary>
        public HandModel Hand => _hand;

        /// <summary>The 15 joint parameters after the last <see cref="Solve"/> (finger-major: thumb 0–2, index 3–5, …).</summary>
        public ReadOnlySpan<float> T => _t;

        /// <summary>Iterations used by the last solve, summed over the fingers.</summary>
        public int LastIterations { get; private set; }

        /// <summary>True when the last solve found the controller out of the palm's reach and opened the hand.</summary>
        public bool OutOfReach { get; private set; }

        /// <summary>
        /// Solves the fingers for this frame. <paramref name="trigger"/> and <paramref name="grip"/> are the analog
        /// values 0..1 for <see cref="GripMode.InputDriven"/> (NaN: not provided; grip defaults to held, trigger to released).
        /// </summary>
        public void Solve(Pose handWorld, Pose controllerWorld, GripMode mode, float trigger = float.NaN, float grip = float.NaN)
        {
            LastIterations = 0;
            if (!handWorld.IsValid || !controllerWorld.IsValid) return; // keep the last good grip
            _handInController = handWorld.RelativeTo(controllerWorld);
            for (int f = 0; f < 5; f++) _fingerBase[f] = _handInController * _hand.RestRelative[f, 0];
            Vector3 palm = _handInController.TransformPoint(_hand.PalmCentreInHand);
            OutOfReach = _profile.Shape.Distance(palm) > ReachDistance;
            if (mode == GripMode.Open || OutOfReach)
            {
                Array.Clear(_solved, 0, 15);
                Array.Clear(_t, 0, 15);
                return;
            }
            for (int f = 0; f < 5; f++)
            {
                if (!_hand.HasFinger[f]) continue;
                bool pointing = f == 1 && (mode == GripMode.Point || (mode == GripMode.InputDriven && !(trigger > 0f)));
                if (pointing)
                {
                    _solved[3] = _solved[4] = _solved[5] = 0f;
                    continue;
                }
                LastIterations += SolveFinger(f);
            }
            float g = float.IsNaN(grip) ? 1f : Math.Max(0f, Math.Min(1f, grip));
            float v = float.IsNaN(trigger) ? 0f : Math.Max(0f, Math.Min(1f, trigger));
            for (int f = 0; f < 5; f++)
            {
                float blend = mode != GripMode.InputDriven ? 1f : f == 1 ? v : g;
                for (int k = 0; k < 3; k++) _t[f * 3 + k] = _solved[f * 3 + k] * blend;
            }
        }

        /// <summary>
        /// The signed distance (m) from the controller's surface to the skin at a finger point after the last solve:
        /// point 0 intermediate joint, 1 distal joint, 2 fingertip. Negative: penetration.
        /// </summary>
        public float SurfaceGap(int finger, int point)
        {
            Pose w0, w1, w2;
            Chain(finger, _t[finger * 3], _t[finger * 3 + 1], _t[finger * 3 + 2], out w0, out w1, out w2);
            Vector3 p = point == 0 ? w1.Position : point == 1 ? w2.Position : w2.TransformPoint(_hand.TipLocal[finger]);
            return _profile.Shape.Distance(p) - _hand.FingerRadius;
        }

        private int SolveFinger(int f)
        {
            int o = f * 3;
            // Every frame starts from the same place (_start), not from the last frame: where the cost is flat (a
            // long finger already wrapped past a thin handle) a warm start settles wherever it came from, which made
            // the grip depend on the frame rate by up to 0.035 in t. This way the grip is a function of this frame's
            // controller pose alone.
            float t0 = _start[o], t1 = _start[o + 1], t2 = _start[o + 2];
            float cost = Cost(f, t0, t1, t2, out Vector3 grad);
            int iterations = 0;
            float lastStep = float.MaxValue;
            for (; iterations < MaxIterations; iterations++)
            {
                float g2 = grad.LengthSquared();
                if (g2 < 1e-14f) break;
                // Polyak's step (exact when the minimum cost is 0), capped, and at most twice the last accepted one
                // so that a finger resting against the surface does not backtrack from a huge step every iteration.
                float step = Math.Min(Math.Min(cost / g2, 0.5f / (float)Math.Sqrt(g2)), 2f * lastStep);
                bool improved = false;
                float n0 = t0, n1 = t1, n2 = t2, newCost = cost;
                Vector3 newGrad = grad;
                for (int backtrack = 0; backtrack < 8; backtrack++)
                {
                    n0 = Clamp01(t0 - step * grad.X);
                    n1 = Clamp01(t1 - step * grad.Y);
                    n2 = Clamp01(t2 - step * grad.Z);
                    newCost = Cost(f, n0, n1, n2, out newGrad);
                    if (newCost < cost) { improved = true; break; }
                    step *= 0.5f;
                }
                if (!improved) break;
                lastStep = step;
                float moved = Math.Max(Math.Abs(n0 - t0), Math.Max(Math.Abs(n1 - t1), Math.Abs(n2 - t2)));
                t0 = n0; t1 = n1; t2 = n2; cost = newCost; grad = newGrad;
                if (moved < 2e-3f) { iterations++; break; }
            }
            _solved[o] = t0; _solved[o + 1] = t1; _solved[o + 2] = t2;
            return iterations;
        }

        // The cost of finger f at (t0, t1, t2) and its gradient with respect to them.
        private float Cost(int f, float t0, float t1, float t2, out Vector3 gradient)
        {
            Chain(f, t0, t1, t2, out Pose w0, out Pose w1, out Pose w2);
            _points[0] = w1.Position;
            _points[1] = w2.Position;
            _points[2] = w2.TransformPoint(_hand.TipLocal[f]);
            // Rotation axes in the controller frame, scaled by each joint's full closing angle: dp/dt_k = axis_k × (p − joint_k).
            Vector3 a0 = Vector3.Transform(_hand.AxisLocal[f, 0], w0.Rotation) * _hand.MaxRadians[f, 0];
            Vector3 a1 = Vector3.Transform(_hand.AxisLocal[f, 1], w1.Rotation) * _hand.MaxRadians[f, 1];
            Vector3 a2 = Vector3.Transform(_hand.AxisLocal[f, 2], w2.Rotation) * _hand.MaxRadians[f, 2];
            float cost = 0f;
            for (int i = 0; i < 3; i++)
            {
                float s = _profile.Shape.Evaluate(_points[i], out Vector3 g) - _hand.FingerRadius;
                float weight = s >= 0f ? 1f : -Penalty;
                cost += s * weight;
                _pointGradients[i] = g * weight;
            }
            Vector3 goalGradient = Vector3.Zero;
            if (f == 0 || f == 1)
            {
                Vector3 goal = f == 0 ? _profile.ThumbRest : _profile.Trigger;
                Vector3 d = _points[2] - goal;
                float len = d.Length();
                cost += GoalWeight * len;
                if (len > 1e-9f) goalGradient = d / len * GoalWeight;
            }
            Vector3 tipGradient = _pointGradients[2] + goalGradient;
            float g0 = Vector3.Dot(_pointGradients[0], Vector3.Cross(a0, _points[0] - w0.Position))
                     + Vector3.Dot(_pointGradients[1], Vector3.Cross(a0, _points[1] - w0.Position))
                     + Vector3.Dot(tipGradient, Vector3.Cross(a0, _points[2] - w0.Position));
            float g1 = Vector3.Dot(_pointGradients[1], Vector3.Cross(a1, _points[1] - w1.Position))
                     + Vector3.Dot(tipGradient, Vector3.Cross(a1, _points[2] - w1.Position));
            float g2 = Vector3.Dot(tipGradient, Vector3.Cross(a2, _points[2] - w2.Position));
            float d01 = t0 - t1, d12 = t1 - t2;
            cost += Smoothness * (d01 * d01 + d12 * d12);
            gradient = new Vector3(g0 + 2f * Smoothness * d01, g1 + 2f * Smoothness * (d12 - d01), g2 - 2f * Smoothness * d12);
            return cost;
        }

        // Forward kinematics of finger f in the controller frame. The quaternions stay unit to float precision
        // over three products, so this hot path skips the renormalisation Pose's operator does.
        private void Chain(int f, float t0, float t1, float t2, out Pose w0, out Pose w1, out Pose w2)
        {
            Pose b = _fingerBase[f];
            Quaternion r0 = b.Rotation * Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 0], t0 * _hand.MaxRadians[f, 0]);
            w0 = new Pose(b.Position, r0);
            Pose rest1 = _hand.RestRelative[f, 1], rest2 = _hand.RestRelative[f, 2];
            Quaternion r1 = r0 * rest1.Rotation * Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 1], t1 * _hand.MaxRadians[f, 1]);
            w1 = new Pose(b.Position + Vector3.Transform(rest1.Position, r0), r1);
            Quaternion r2 = r1 * rest2.Rotation * Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 2], t2 * _hand.MaxRadians[f, 2]);
            w2 = new Pose(w1.Position + Vector3.Transform(rest2.Position, r1), r2);
        }

        private static float Clamp01(float v) => v < 0f ? 0f : v > 1f ? 1f : v;
    }
}
