using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Analytic two-bone IK on a <see cref="SkeletonPose"/>: bends the middle joint so the end joint can reach the
    /// goal (law of cosines), aims the root at the goal, twists the limb about the root→goal axis so the middle
    /// joint lies toward the hint, then gives the end joint the goal rotation. Only joint rotations change (bone
    /// lengths never do), and Local and World are kept in step along the chain. Allocation-free.
    /// </summary>
    /// <remarks>
    /// Unreachable goals: a goal farther than the two bones reach leaves the limb stretched straight at it
    /// (to within <see cref="StretchMargin"/>, so the bend plane survives to the next frame), and one closer than
    /// the limb can fold leaves it folded as far as it goes (interior angle of the middle joint
    /// <see cref="MinFoldDistance"/> short of the bones' length difference) toward it; both are reported as not
    /// reached with the distance left. A hint on the root→goal line (or not finite, or so far off that its offset from
    /// that line overflows) gives no plane: the limb keeps its current bend plane. A goal whose rotation is not a unit
    /// quaternion still positions the limb and leaves the end joint's local rotation alone. A goal whose position is not
    /// finite leaves the limb untouched and is reported as not reached, infinitely far. Nothing here ever writes NaN.
    /// </remarks>
    public static class TwoBoneIk
    {
        /// <summary>A goal counts as reached when the end joint ends within this distance of it (1 mm).</summary>
        public const float ReachedTolerance = 0.001f;

        /// <summary>How far short of full extension (in metres) a stretched limb stops: 0.01 mm.</summary>
        public const float StretchMargin = 1e-5f;

        /// <summary>How far beyond the tightest fold (in metres) a folded limb stops: 0.1 mm.</summary>
        public const float MinFoldDistance = 1e-4f;

        private const float MinBoneLength = 1e-6f;

        /// <summary>
        /// Solves one limb. The world poses of the chain root's ancestors must be up to date; on return the world
        /// poses of the chain's joints are too (their other descendants are not: call <see cref="SkeletonPose.UpdateWorld()"/>).
        /// </summary>
        /// <param name="pose">The pose to change; its current content is the starting point.</param>
        /// <param name="chain">The limb.</param>
        /// <param name="goal">World pose for the end joint.</param>
        /// <param name="hint">World position the middle joint should bend toward.</param>
        /// <returns>Whether the end joint reached the goal (within <see cref="ReachedTolerance"/>) and how far it is from it.</returns>
        public static LimbResult Solve(SkeletonPose pose, LimbChain chain, RigidPose goal, Vector3 hint)
        {
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            if (chain == null) throw new ArgumentNullException(nameof(chain));
            RigidPose[] w = pose.World;
            UpdatePath(pose, chain, 0);
            if (!Vectors.IsFinite(goal.Position)) return new LimbResult(false, float.PositiveInfinity);
            int middleIndex = IndexInPath(chain, chain.Middle);
            Vector3 a = w[chain.Root].Position, b = w[chain.Middle].Position, c = w[chain.End].Position;
            float lab = Vector3.Distance(a, b), lbc = Vector3.Distance(b, c);
            Vector3 toGoal = goal.Position - a;
            float goalDistance = toGoal.Length();
            bool hasHint = Vectors.IsFinite(hint);

            // 1. Bend the middle joint to the interior angle that puts the end at the goal's distance (law of cosines).
            if (lab > MinBoneLength && lbc > MinBoneLength)
            {
                float reach = lab + lbc;
                float fold = Math.Abs(lab - lbc) + MinFoldDistance;
                float d = Math.Max(fold, Math.Min(goalDistance, reach - StretchMargin));
                float cosWanted = Math.Max(-1f, Math.Min(1f, (lab * lab + lbc * lbc - d * d) / (2f * lab * lbc)));
                Vector3 ba = a - b, bc = c - b;
                Vector3 normal = Vector3.Cross(bc, ba);
                float angleNow = MathF.Atan2(normal.Length(), Vector3.Dot(ba, bc));
                float delta = angleNow - MathF.Acos(cosWanted);
                // Turning bc about bc×ba by +δ closes the angle by δ. A straight (or fully folded) limb has no plane
                // of its own: any axis perpendicular to bc then changes the angle by |δ| the right way; take the
                // hint's plane, turning the end away from the hint so that the middle joint ends on the hint's side
                // and the twist below has little to do (bc×hint turned it toward the hint: a half turn of twist).
                if (normal.LengthSquared() < 1e-14f * lab * lab * lbc * lbc)
                {
                    normal = hasHint ? Vector3.Cross(hint - b, bc) : Vector3.Zero;
                    if (normal.LengthSquared() < 1e-14f * lbc * lbc) normal = Vector3.Cross(bc, Math.Abs(bc.Y) < 0.9f * lbc ? Vector3.UnitY : Vector3.UnitX);
                }
                if (Vectors.IsFinite(delta) && Math.Abs(delta) > 0f)
                    RotateJoint(pose, chain, middleIndex, Quaternion.CreateFromAxisAngle(Vectors.NormalizeOr(normal, Vector3.UnitX), delta));
                b = w[chain.Middle].Position;
                c = w[chain.End].Position;
            }

            // 2. Aim the root at the goal, and 3. twist about the root→goal axis so the middle joint faces the hint.
            Vector3 aim = goalDistance > 1e-6f ? toGoal : c - a;
            Quaternion swing = Rotations.FromTo(c - a, aim);
            Vector3 u = Vectors.NormalizeOr(aim, Vector3.UnitY);
            Quaternion turn = swing;
            if (hasHint)
            {
                Vector3 pb = Vectors.ProjectOnPlane(Vector3.Transform(b - a, swing), u);
                Vector3 ph = Vectors.ProjectOnPlane(hint - a, u);
                if (pb.LengthSquared() > 1e-12f && ph.LengthSquared() > 1e-10f)
                {
                    float twistAngle = MathF.Atan2(Vector3.Dot(u, Vector3.Cross(pb, ph)), Vector3.Dot(pb, ph));
                    // A finite hint so far off that its offset overflowed gives no angle, so no plane (it gave a NaN root).
                    if (Vectors.IsFinite(twistAngle)) turn = Quaternion.CreateFromAxisAngle(u, twistAngle) * swing;
                }
            }
            RotateJoint(pose, chain, 0, Quaternion.Normalize(turn));

            // 4. The end joint takes the goal's rotation.
            int endParent = pose.Skeleton.GetParent(chain.End);
            if (Rotations.IsUnit(goal.Rotation))
            {
                pose.SetWorldRotation(chain.End, goal.Rotation);
                w[chain.End] = w[endParent] * pose.Local[chain.End];
            }
            float left = Vector3.Distance(w[chain.End].Position, goal.Position);
            if (!Vectors.IsFinite(left)) left = float.PositiveInfinity;
            return new LimbResult(left <= ReachedTolerance, left);
        }

        private static int IndexInPath(LimbChain chain, int joint)
        {
            int[] path = chain.Path;
            for (int i = 0; i < path.Length; i++)
                if (path[i] == joint) return i;
            return 0;
        }

        /// <summary>Applies a world-space rotation <paramref name="delta"/> to the chain's joint at <paramref name="pathIndex"/> and refreshes the chain below it.</summary>
        private static void RotateJoint(SkeletonPose pose, LimbChain chain, int pathIndex, Quaternion delta)
        {
            pose.RotateWorld(chain.Path[pathIndex], delta);
            UpdatePath(pose, chain, pathIndex);
        }

        private static void UpdatePath(SkeletonPose pose, LimbChain chain, int start) =>
            pose.UpdateWorld(new ReadOnlySpan<int>(chain.Path, start, chain.Path.Length - start));
    }
}
