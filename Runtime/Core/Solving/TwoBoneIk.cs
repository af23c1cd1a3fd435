using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Analytic two-bone IK on a <see cref="SkeletonPose"/>: bends the middle joint so the end joint can reach the
    /// goal (law of cosines), aims the root at the goal, twists the limb about the root→goal axis so the middle
    /// joint lies toward the hint, then gives the end joint the goal rotation. Bone lengths are never changed.
    /// An unreachable goal leaves the limb fully stretched toward it. Allocation-free.
    /// </summary>
    public static class TwoBoneIk
    {
        /// <summary>A goal counts as reached when the end joint ends within this distance of it (1 mm).</summary>
        public const float ReachedTolerance = 0.001f;

        /// <summary>
        /// Solves one limb. The world poses of the chain's root's ancestors must be up to date; on return the world
        /// poses of the chain's joints are too (their other descendants are not: call <see cref="SkeletonPose.UpdateWorld()"/>).
        /// </summary>
        public static LimbResult Solve(SkeletonPose pose, LimbChain chain, Pose goal, Vector3 hint)
        {
            Pose[] w = pose.World;
            UpdatePath(pose, chain, 0);
            Vector3 a = w[chain.Root].Position, b = w[chain.Middle].Position, c = w[chain.End].Position;
            if (!goal.IsValid || !Vectors.IsFinite(hint)) return new LimbResult(false, float.NaN);
            float lab = Vector3.Distance(a, b), lbc = Vector3.Distance(b, c);
            float reach = lab + lbc;
            Vector3 toGoal = goal.Position - a;
            float goalDistance = toGoal.Length();
            float min = Math.Abs(lab - lbc) + 1e-4f;
            float d = Math.Max(min, Math.Min(goalDistance, reach - 1e-5f));

            // 1. Bend the middle joint: interior angle from the law of cosines.
            float cosWanted = Math.Max(-1f, Math.Min(1f, (lab * lab + lbc * lbc - d * d) / (2f * lab * lbc)));
            float cosNow = Math.Max(-1f, Math.Min(1f, Vector3.Dot(a - b, c - b) / Math.Max(lab * lbc, 1e-12f)));
            Vector3 axis = Vector3.Cross(c - b, a - b);
            if (axis.LengthSquared() < 1e-12f) axis = Vector3.Cross(c - a, hint - a);
            if (axis.LengthSquared() < 1e-12f) axis = Vector3.Cross(c - a, Math.Abs((c - a).Y) < 0.9f * (c - a).Length() ? Vector3.UnitY : Vector3.UnitX);
            axis = Vectors.NormalizeOr(axis, Vector3.UnitX);
            float delta = MathF.Acos(cosNow) - MathF.Acos(cosWanted);
            RotateJoint(pose, chain, chain.Middle, Quaternion.CreateFromAxisAngle(axis, delta));
            c = w[chain.End].Position;
            b = w[chain.Middle].Position;

            // 2. Aim the root at the goal, and 3. twist about the root→goal axis so the middle joint faces the hint.
            Vector3 aim = goalDistance > 1e-6f ? toGoal : c - a;
            Quaternion swing = Rotations.FromTo(c - a, aim);
            Vector3 u = Vectors.NormalizeOr(aim, Vector3.UnitY);
            Vector3 bAfter = Vector3.Transform(b - a, swing);
            Vector3 pb = Vectors.ProjectOnPlane(bAfter, u), ph = Vectors.ProjectOnPlane(hint - a, u);
            Quaternion twist = Quaternion.Identity;
            if (pb.LengthSquared() > 1e-10f && ph.LengthSquared() > 1e-10f)
                twist = Rotations.AngleAxis(Vectors.SignedAngleDegrees(pb, ph, u), u);
            RotateJoint(pose, chain, chain.Root, Quaternion.Normalize(twist * swing));

            // 4. The end joint takes the goal's rotation.
            int endParent = pose.Skeleton.GetParent(chain.End);
            pose.Local[chain.End] = pose.Local[chain.End].WithRotation(Quaternion.Normalize(Quaternion.Conjugate(w[endParent].Rotation) * goal.Rotation));
            w[chain.End] = w[endParent] * pose.Local[chain.End];
            float left = Vector3.Distance(w[chain.End].Position, goal.Position);
            return new LimbResult(left <= ReachedTolerance, left);
        }

        /// <summary>Applies a world-space rotation <paramref name="delta"/> to joint <paramref name="joint"/> of the chain and refreshes the chain below it.</summary>
        private static void RotateJoint(SkeletonPose pose, LimbChain chain, int joint, Quaternion delta)
        {
            Pose[] w = pose.World;
            int parent = pose.Skeleton.GetParent(joint);
            Quaternion parentRotation = parent < 0 ? pose.Origin.Rotation : w[parent].Rotation;
            Quaternion world = Quaternion.Normalize(delta * w[joint].Rotation);
            pose.Local[joint] = pose.Local[joint].WithRotation(Quaternion.Normalize(Quaternion.Conjugate(parentRotation) * world));
            int start = Array.IndexOf(chain.Path, joint);
            UpdatePath(pose, chain, start);
        }

        private static void UpdatePath(SkeletonPose pose, LimbChain chain, int start) =>
            pose.UpdateWorld(new ReadOnlySpan<int>(chain.Path, start, chain.Path.Length - start));
    }
}
