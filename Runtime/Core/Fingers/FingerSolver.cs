using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Closes the fingers of one hand on a controller by minimising, per finger, the paper's cost: the sum over the
    /// finger's moving points (intermediate and distal joints, fingertip) of their distance to the controller's
    /// surface, negative distances (penetration) multiplied by <see cref="Penalty"/> before taking the absolute value
    /// — plus the thumb tip toward the thumb rest and the index tip toward the trigger (each goal lifted one finger
    /// radius off the surface, where the fingertip's centre is when its pad touches it), and a small term keeping a
    /// finger's joints curling together (a finger's three, the thumb's outer two). The thumb arches over the
    /// controller to its rest, so only its tip is drawn to the surface; its joints are only kept out of it. Distances
    /// are measured from the finger's surface (joint centre minus <see cref="HandModel.FingerRadius"/>), so contact
    /// means skin on plastic, not bone.
    /// </summary>
    /// <remarks>
    /// Each frame runs projected gradient descent to convergence (Polyak step size with backtracking, analytic
    /// gradients from the SDF gradients and the joints' rotation axes, parameters clamped to [0, 1]) until no
    /// parameter moves more than 2e-3 (0.2° at a joint), a step that small no longer lowers the cost, or after
    /// <see cref="MaxIterations"/>. Every frame starts
    /// from the grip solved once, at construction, for the nominal hold (from the best point of a coarse grid),
    /// not from the last frame, so the result depends on the controller's pose, not on the frame rate.
    /// A frame whose hand lies where the last solve had it in the controller's frame (within
    /// <see cref="ResolveDistance"/> and <see cref="ResolveAngle"/>, in the same mode) keeps that solve's grip without
    /// descending again: the descent is a function of that pose alone, and a hand that follows its controller, as it does
    /// whenever the arm reaches it, keeps one pose in the controller's frame to float precision.
    /// No allocation per frame.
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

        /// <summary>
        /// How far (m) the hand may lie, in the controller's frame, from where the last descent had it before the fingers
        /// are descended again: 1 µm, a few times the float noise of a hand that follows its controller (its pose in the
        /// controller's frame moves 0.3 µm median, 0.5 µm p90, frame to frame on the Mixamo session). The descent is not
        /// continuous everywhere (its backtracking decides by comparisons), so a kept grip is the descent of a pose within
        /// this of the current one, not always the grip a new descent would give: on 900 random poses a micrometre apart,
        /// 7 differed by more than the descent's own tolerance, at most by 0.04 in t (0.065 at 10 µm).
        /// </summary>
        public const float ResolveDistance = 1e-6f;

        /// <summary>How far (radians) the hand may be turned, in the controller's frame, from the last descent's before the fingers are descended again (1e-6).</summary>
        public const float ResolveAngle = 1e-6f;

        private readonly HandModel _hand;
        private readonly ControllerProfile _profile;
        private readonly float[] _solved = new float[FingerParameters.Count];
        private readonly float[] _start = new float[FingerParameters.Count];
        private readonly FingerParameters _parameters = new FingerParameters();
        private readonly float[] _t;   // _parameters' storage
        private readonly Vector3[] _points = new Vector3[3];
        private readonly Vector3[] _pointGradients = new Vector3[3];
        private RigidPose _handInController;
        private readonly RigidPose[] _fingerBase = new RigidPose[5];
        private Vector3 _thumbSpreadAxis;   // this frame's, in the controller frame, scaled by the full spread angle
        private readonly Vector3 _thumbGoal, _indexGoal;
        // Where the hand was, in the controller's frame, when _solved was last descended to, and whether the index pointed.
        private RigidPose _solvedFor;
        private bool _solvedPointing, _hasSolved;

        /// <summary>Creates a solver for one hand and one controller.</summary>
        public FingerSolver(HandModel hand, ControllerProfile profile)
        {
            _hand = hand ?? throw new ArgumentNullException(nameof(hand));
            _profile = profile ?? throw new ArgumentNullException(nameof(profile));
            _t = _parameters.Values;
            _thumbGoal = Lifted(profile.ThumbRest);
            _indexGoal = Lifted(profile.Trigger);
            // The start of every frame's descent: the grip solved once with the controller exactly where this hand
            // holds it, from the best point of a coarse grid over each finger's parameters (the cost has local
            // minima: a thumb whose tip touches the side of the controller's head stays there). Near every frame's
            // answer, and the same whatever the frame rate.
            RigidPose held = hand.ControllerInHand(profile);
            PlaceHand(held.Inverse());
            for (int f = 0; f < 5; f++)
                if (_hand.HasFinger[f]) GridStart(f);
            Solve(RigidPose.Identity, held, GripMode.Hold);
            Array.Copy(_solved, _start, FingerParameters.Count);
            Array.Clear(_solved, 0, FingerParameters.Count);
            Array.Clear(_t, 0, FingerParameters.Count);
            _hasSolved = false;
        }

        /// <summary>The hand.</summary>
        public HandModel Hand => _hand;

        /// <summary>The hand's joint parameters after the last <see cref="Solve"/> (what <see cref="HandModel.Apply"/> poses the fingers from).</summary>
        public FingerParameters Parameters => _parameters;

        /// <summary>The controller profile the fingers close on.</summary>
        public ControllerProfile Profile => _profile;

        /// <summary>Iterations used by the last solve, summed over the fingers (0 when it kept the grip before it: <see cref="LastSolveReused"/>).</summary>
        public int LastIterations { get; private set; }

        /// <summary>
        /// True when the last <see cref="Solve"/> kept the grip of the solve before it, the hand lying where it was in the
        /// controller's frame (within <see cref="ResolveDistance"/> and <see cref="ResolveAngle"/>, in the same mode).
        /// </summary>
        public bool LastSolveReused { get; private set; }

        /// <summary>True when the last solve found the controller out of the palm's reach and opened the hand.</summary>
        public bool OutOfReach { get; private set; }

        /// <summary>
        /// Solves the fingers for this frame. <paramref name="trigger"/> and <paramref name="grip"/> are the analog
        /// values 0..1 for <see cref="GripMode.InputDriven"/> (NaN: not provided; grip defaults to held, trigger to released).
        /// </summary>
        public void Solve(RigidPose handWorld, RigidPose controllerWorld, GripMode mode, float trigger = float.NaN, float grip = float.NaN)
        {
            LastIterations = 0;
            LastSolveReused = false;
            if (!handWorld.IsValid || !controllerWorld.IsValid) return; // keep the last good grip
            RigidPose handInController = handWorld.RelativeTo(controllerWorld);
            PlaceHand(handInController);
            Vector3 palm = _handInController.TransformPoint(_hand.PalmCentreInHand);
            OutOfReach = _profile.Shape.Distance(palm) > ReachDistance;
            if (mode == GripMode.Open || OutOfReach)
            {
                Array.Clear(_solved, 0, FingerParameters.Count);
                Array.Clear(_t, 0, FingerParameters.Count);
                _hasSolved = false;
                return;
            }
            bool indexPoints = mode == GripMode.Point || (mode == GripMode.InputDriven && !(trigger > 0f));
            LastSolveReused = _hasSolved && indexPoints == _solvedPointing && Near(handInController, _solvedFor);
            if (!LastSolveReused)
            {
                for (int f = 0; f < 5; f++)
                {
                    if (!_hand.HasFinger[f]) continue;
                    if (f == 1 && indexPoints)
                    {
                        _solved[3] = _solved[4] = _solved[5] = 0f;
                        continue;
                    }
                    LastIterations += SolveFinger(f);
                }
                // Compared with the pose of this descent, not of the last frame, so a hand drifting slowly is solved again.
                _solvedFor = handInController;
                _solvedPointing = indexPoints;
                _hasSolved = true;
            }
            float g = float.IsNaN(grip) ? 1f : Math.Max(0f, Math.Min(1f, grip));
            float v = float.IsNaN(trigger) ? 0f : Math.Max(0f, Math.Min(1f, trigger));
            for (int f = 0; f < 5; f++)
            {
                float blend = mode != GripMode.InputDriven ? 1f : f == 1 ? v : g;
                // A finger released only part of the way opens no further than the controller lets it: the open hand (the
                // T-pose's) may lie inside the controller held in it (found in review: the thumb's last joint 4.4 mm deep in
                // the VIVE wand at grip 0, the Unity component's default mode), the solved grip does not.
                if (blend < 1f && _hand.HasFinger[f] && Penetrates(f, blend)) blend = LeastBlendOutside(f, blend);
                SetBlend(f, blend);
            }
        }

        private void SetBlend(int f, float blend)
        {
            for (int k = 0; k < 3; k++) _t[f * 3 + k] = _solved[f * 3 + k] * blend;
            if (f == 0) _t[FingerParameters.ThumbSpreadIndex] = _solved[FingerParameters.ThumbSpreadIndex] * blend;
        }

        // Whether finger f, blended `blend` of the way from open to the solved grip, has a point inside the controller (more
        // than the solved grip may: PenetrationTolerance).
        private bool Penetrates(int f, float blend)
        {
            int o = f * 3;
            var t = new Vector4(_solved[o] * blend, _solved[o + 1] * blend, _solved[o + 2] * blend, f == 0 ? _solved[FingerParameters.ThumbSpreadIndex] * blend : 0f);
            Chain(f, t, out _, out RigidPose w1, out RigidPose w2);
            return _profile.Shape.Distance(w1.Position) - _hand.FingerRadius < -PenetrationTolerance
                || _profile.Shape.Distance(w2.Position) - _hand.FingerRadius < -PenetrationTolerance
                || _profile.Shape.Distance(w2.TransformPoint(_hand.TipLocal[f])) - _hand.FingerRadius < -PenetrationTolerance;
        }

        // The least blend above `from` at which finger f is outside the controller, to 1/256 of the way (bisection: the
        // solved grip, blend 1, is outside).
        private float LeastBlendOutside(int f, float from)
        {
            float inside = from, outside = 1f;
            for (int i = 0; i < 8; i++)
            {
                float mid = 0.5f * (inside + outside);
                if (Penetrates(f, mid)) inside = mid; else outside = mid;
            }
            return outside;
        }

        // How deep a blended finger point may lie inside the controller: what the descent leaves (0.01 mm) and then some.
        private const float PenetrationTolerance = 1e-4f;

        /// <summary>
        /// The signed distance (m) from the controller's surface to the skin at a finger point after the last solve.
        /// Negative: penetration. NaN for a finger the rig does not have (check <see cref="HandModel.Has"/>).
        /// </summary>
        public float SurfaceGap(Finger finger, FingerPoint point) => _profile.Shape.Distance(PointInController(finger, point)) - _hand.FingerRadius;

        /// <summary>
        /// How deep (m) the skin of <paramref name="finger"/> lies inside the controller at its deepest after the last solve,
        /// sampled along its bones from the knuckle (its first joint) to the tip, 0 when it is outside everywhere: the
        /// solver keeps only the three <see cref="FingerPoint"/>s out, and a straight phalanx between two of them can cross
        /// a convex handle (a diagnostic, for `avatargo fingers`; not per-frame work). NaN for a finger the rig does not have.
        /// </summary>
        public float SkinDepth(Finger finger)
        {
            if ((uint)finger > 4) throw new ArgumentOutOfRangeException(nameof(finger), finger, "Not a finger.");
            int f = (int)finger;
            if (!_hand.HasFinger[f]) return float.NaN;
            const int samples = 16;
            Vector3 from = _fingerBase[f].Position;
            float depth = 0f;
            for (int p = 0; p < 3; p++)
            {
                Vector3 to = PointInController(finger, (FingerPoint)p);
                for (int i = p == 0 ? 0 : 1; i <= samples; i++)
                    depth = Math.Max(depth, _hand.FingerRadius - _profile.Shape.Distance(Vector3.Lerp(from, to, i / (float)samples)));
                from = to;
            }
            return depth;
        }

        /// <summary>
        /// How far (m) the fingertip of the thumb or the index is, after the last solve, from resting on the thumb rest or
        /// the trigger: the distance from the fingertip's centre to its goal, the profile's point lifted one finger radius
        /// off the surface (where the fingertip's centre is when its pad touches the point). NaN when the rig has no such finger.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Not the thumb or the index.</exception>
        public float GoalDistance(Finger finger)
        {
            if (finger != Finger.Thumb && finger != Finger.Index) throw new ArgumentOutOfRangeException(nameof(finger), finger, "Only the thumb and the index have goals.");
            return Vector3.Distance(PointInController(finger, FingerPoint.Tip), finger == Finger.Thumb ? _thumbGoal : _indexGoal);
        }

        /// <summary>
        /// A finger point after the last solve, in the controller's frame (the frame of the profile's trigger and
        /// thumb rest). NaN for a finger the rig does not have.
        /// </summary>
        public Vector3 PointInController(Finger finger, FingerPoint point)
        {
            if ((uint)finger > 4) throw new ArgumentOutOfRangeException(nameof(finger), finger, "Not a finger.");
            if ((uint)point > 2) throw new ArgumentOutOfRangeException(nameof(point), point, "Not a finger point.");
            int f = (int)finger;
            if (!_hand.HasFinger[f]) return new Vector3(float.NaN);
            int o = f * 3;
            Chain(f, new Vector4(_t[o], _t[o + 1], _t[o + 2], f == 0 ? _t[FingerParameters.ThumbSpreadIndex] : 0f), out _, out RigidPose w1, out RigidPose w2);
            return point == FingerPoint.IntermediateJoint ? w1.Position : point == FingerPoint.DistalJoint ? w2.Position : w2.TransformPoint(_hand.TipLocal[f]);
        }

        // Sets finger f's start to the lowest-cost point of a grid over its parameters (7 values each: 343 points
        // for a finger, 2401 for the thumb). Once per solver, at construction.
        private void GridStart(int f)
        {
            const int steps = 7;
            bool thumb = f == 0;
            int spreads = thumb ? steps : 1;
            float best = float.MaxValue;
            Vector4 bestT = Vector4.Zero;
            for (int i = 0; i < steps; i++)
                for (int j = 0; j < steps; j++)
                    for (int k = 0; k < steps; k++)
                        for (int m = 0; m < spreads; m++)
                        {
                            var t = new Vector4(i, j, k, m) / (steps - 1);
                            float cost = Cost(f, t, out _);
                            if (cost < best) { best = cost; bestT = t; }
                        }
            _start[f * 3] = bestT.X; _start[f * 3 + 1] = bestT.Y; _start[f * 3 + 2] = bestT.Z;
            if (thumb) _start[FingerParameters.ThumbSpreadIndex] = bestT.W;
        }

        // What stays fixed through a frame's descent: the hand in the controller frame, each finger's base, and the
        // thumb's spread axis.
        private void PlaceHand(RigidPose handInController)
        {
            _handInController = handInController;
            for (int f = 0; f < 5; f++) _fingerBase[f] = handInController * _hand.RestRelative[f, 0];
            _thumbSpreadAxis = Vector3.Transform(_hand.ThumbSpreadAxisLocal, _fingerBase[0].Rotation) * _hand.ThumbSpreadRadians;
        }

        private int SolveFinger(int f)
        {
            int o = f * 3;
            bool thumb = f == 0;
            // Every frame starts from the same place (_start), not from the last frame: where the cost is flat (a
            // long finger already wrapped past a thin handle) a warm start settles wherever it came from, which made
            // the grip depend on the frame rate by up to 0.035 in t. This way the grip is a function of this frame's
            // controller pose alone. Parameters: x, y, z the three joints; w the thumb's spread (0 for a finger).
            var t = new Vector4(_start[o], _start[o + 1], _start[o + 2], thumb ? _start[FingerParameters.ThumbSpreadIndex] : 0f);
            float cost = Cost(f, t, out Vector4 grad);
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
                Vector4 next = t, nextGrad = grad;
                float nextCost = cost;
                float moved = 0f;
                for (int backtrack = 0; backtrack < 8; backtrack++)
                {
                    next = Vector4.Clamp(t - step * grad, Vector4.Zero, thumb ? Vector4.One : new Vector4(1f, 1f, 1f, 0f));
                    moved = LargestChange(next, t);
                    nextCost = Cost(f, next, out nextGrad);
                    if (nextCost < cost) { improved = true; break; }
                    // A step too small to count as a move did not lower the cost either: converged. (The halvings
                    // after it could only move t less than that; this is where a finger resting on the surface, at
                    // the kink of the cost's absolute value, used to spend all eight of them.)
                    if (moved < ConvergedChange) break;
                    step *= 0.5f;
                }
                if (!improved) break;
                lastStep = step;
                t = next; cost = nextCost; grad = nextGrad;
                if (moved < ConvergedChange) { iterations++; break; }
            }
            _solved[o] = t.X; _solved[o + 1] = t.Y; _solved[o + 2] = t.Z;
            if (thumb) _solved[FingerParameters.ThumbSpreadIndex] = t.W;
            return iterations;
        }

        // Whether the hand lies within ResolveDistance and ResolveAngle of where it lay for the last descent.
        private static bool Near(RigidPose a, RigidPose b)
        {
            if (Vector3.DistanceSquared(a.Position, b.Position) > ResolveDistance * ResolveDistance) return false;
            // The vector part of the rotation between them is sin(angle / 2): resolved to float precision near 0,
            // where the dot product's cos(angle / 2) is 1 in float below about 5e-4 rad.
            Quaternion d = Quaternion.Conjugate(a.Rotation) * b.Rotation;
            float half = 0.5f * ResolveAngle;
            return d.X * d.X + d.Y * d.Y + d.Z * d.Z <= half * half;
        }

        // The descent has converged when no parameter moves more than this (0.2° at a joint).
        private const float ConvergedChange = 2e-3f;

        private static float LargestChange(Vector4 a, Vector4 b)
        {
            Vector4 change = Vector4.Abs(a - b);
            return Math.Max(Math.Max(change.X, change.Y), Math.Max(change.Z, change.W));
        }

        // The cost of finger f at parameters t (x, y, z its joints, w the thumb's spread) and its gradient.
        internal float Cost(int f, Vector4 t, out Vector4 gradient)
        {
            Chain(f, t, out RigidPose w0, out RigidPose w1, out RigidPose w2);
            _points[0] = w1.Position;
            _points[1] = w2.Position;
            _points[2] = w2.TransformPoint(_hand.TipLocal[f]);
            // Rotation axes in the controller frame, scaled by each joint's full closing angle: dp/dt_k = axis_k × (p − joint_k).
            Vector3 a0 = Vector3.Transform(_hand.AxisLocal[f, 0], w0.Rotation) * _hand.MaxRadians[f, 0];
            Vector3 a1 = Vector3.Transform(_hand.AxisLocal[f, 1], w1.Rotation) * _hand.MaxRadians[f, 1];
            Vector3 a2 = Vector3.Transform(_hand.AxisLocal[f, 2], w2.Rotation) * _hand.MaxRadians[f, 2];
            bool thumb = f == 0;
            float cost = 0f;
            for (int i = 0; i < 3; i++)
            {
                float s = _profile.Shape.Evaluate(_points[i], out Vector3 g) - _hand.FingerRadius;
                // The paper's cost for a finger: every point drawn to the surface, penetration penalised. The thumb
                // arches over the controller to its rest: its joints are only kept out, its tip is drawn to the surface.
                float weight = s < 0f ? -Penalty : thumb && i < 2 ? 0f : 1f;
                cost += s * weight;
                _pointGradients[i] = g * weight;
            }
            Vector3 goalGradient = Vector3.Zero;
            if (f == 0 || f == 1)
            {
                Vector3 goal = f == 0 ? _thumbGoal : _indexGoal;
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
            float gs = 0f;
            if (thumb)
            {
                // The spread axis is fixed in the thumb base's rest frame (the spread turns before the flexion).
                Vector3 a3 = _thumbSpreadAxis;
                gs = Vector3.Dot(_pointGradients[0], Vector3.Cross(a3, _points[0] - w0.Position))
                   + Vector3.Dot(_pointGradients[1], Vector3.Cross(a3, _points[1] - w0.Position))
                   + Vector3.Dot(tipGradient, Vector3.Cross(a3, _points[2] - w0.Position));
            }
            // Fingers curl their three joints together; the thumb's first joint moves in another direction than its
            // outer two, so only those two are tied.
            float d01 = thumb ? 0f : t.X - t.Y, d12 = t.Y - t.Z;
            cost += Smoothness * (d01 * d01 + d12 * d12);
            gradient = new Vector4(g0 + 2f * Smoothness * d01, g1 + 2f * Smoothness * (d12 - d01), g2 - 2f * Smoothness * d12, gs);
            return cost;
        }

        // Forward kinematics of finger f in the controller frame. The quaternions stay unit to float precision
        // over three products, so this hot path skips the renormalisation RigidPose's operator does.
        private void Chain(int f, Vector4 t, out RigidPose w0, out RigidPose w1, out RigidPose w2)
        {
            RigidPose b = _fingerBase[f];
            Quaternion bend0 = Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 0], t.X * _hand.MaxRadians[f, 0]);
            if (f == 0) bend0 = Quaternion.CreateFromAxisAngle(_hand.ThumbSpreadAxisLocal, t.W * _hand.ThumbSpreadRadians) * bend0;
            Quaternion r0 = b.Rotation * bend0;
            w0 = new RigidPose(b.Position, r0);
            RigidPose rest1 = _hand.RestRelative[f, 1], rest2 = _hand.RestRelative[f, 2];
            Quaternion r1 = r0 * rest1.Rotation * Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 1], t.Y * _hand.MaxRadians[f, 1]);
            w1 = new RigidPose(b.Position + Vector3.Transform(rest1.Position, r0), r1);
            Quaternion r2 = r1 * rest2.Rotation * Quaternion.CreateFromAxisAngle(_hand.AxisLocal[f, 2], t.Z * _hand.MaxRadians[f, 2]);
            w2 = new RigidPose(w1.Position + Vector3.Transform(rest2.Position, r1), r2);
        }

        // Where a fingertip's centre is when its pad touches the surface point p: p moved along the surface normal to
        // one finger radius off the surface.
        private Vector3 Lifted(Vector3 p)
        {
            float d = _profile.Shape.Evaluate(p, out Vector3 normal);
            return p + normal * (_hand.FingerRadius - d);
        }

    }
}
