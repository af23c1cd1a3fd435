using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// <see cref="TwoBoneIk"/> on a leg-like chain whose joints all have arbitrary rest rotations and slightly
    /// off-axis bone offsets, with a twist bone between the knee and the ankle and a child below the ankle, so no
    /// test can pass by an accident of axis alignment. Goals, hints and starting poses are random (fixed seeds).
    /// </summary>
    public class TwoBoneIkTests
    {
        private const int Base = 0, Root = 1, Middle = 2, Twist = 3, End = 4, Toe = 5;

        private static Skeleton MakeLeg(Random rng, float middleOffsetScale = 1f)
        {
            var names = new[] { "Base", "Root", "Middle", "Twist", "End", "Toe" };
            var parents = new[] { -1, 0, 1, 2, 3, 4 };
            var rest = new[]
            {
                new RigidPose(new Vector3(0.1f, 1.2f, -0.3f), RandomRotation(rng)),
                new RigidPose(new Vector3(0.15f, -0.05f, 0.02f), RandomRotation(rng)),
                new RigidPose(new Vector3(0.01f, -0.42f, 0.02f) * middleOffsetScale, RandomRotation(rng)),
                new RigidPose(new Vector3(0.0f, -0.12f, 0.01f), RandomRotation(rng)),
                new RigidPose(new Vector3(0.005f, -0.14f, 0.0f), RandomRotation(rng)),
                new RigidPose(new Vector3(0.0f, -0.05f, 0.1f), RandomRotation(rng)),
            };
            return new Skeleton(names, parents, rest);
        }

        internal static Quaternion RandomRotation(Random rng)
        {
            var q = new Quaternion((float)Gaussian(rng), (float)Gaussian(rng), (float)Gaussian(rng), (float)Gaussian(rng));
            return Quaternion.Normalize(q);
        }

        private static double Gaussian(Random rng) =>
            Math.Sqrt(-2.0 * Math.Log(1.0 - rng.NextDouble())) * Math.Cos(2.0 * Math.PI * rng.NextDouble());

        private static Vector3 RandomDirection(Random rng) =>
            Vector3.Normalize(new Vector3((float)Gaussian(rng), (float)Gaussian(rng), (float)Gaussian(rng)));

        private static void Randomize(SkeletonPose pose, Random rng, bool keepBase = false)
        {
            pose.ResetToRest();
            // The twist bone keeps its rest rotation: turning it would change the knee-ankle distance (its child is
            // offset from its axis), which the solver rightly takes as given.
            for (int j = Base; j <= Toe; j++)
                if (j != Twist && !(keepBase && j == Base)) pose.Local[j] = pose.Local[j].WithRotation(RandomRotation(rng));
            pose.UpdateWorld();
        }

        /// <summary>Angle in degrees between two vectors, by atan2 (exact near 0°, unlike acos of a dot product).</summary>
        private static double Angle(Vector3 a, Vector3 b) =>
            Math.Atan2(Vector3.Cross(a, b).Length(), Vector3.Dot(a, b)) * (180.0 / Math.PI);

        private static void AssertFinite(SkeletonPose pose)
        {
            for (int j = 0; j < pose.Skeleton.JointCount; j++)
            {
                Assert.That(pose.World[j].IsValid, Is.True, $"world pose of joint {j} is {pose.World[j]}");
                Assert.That(pose.Local[j].IsValid, Is.True, $"local pose of joint {j} is {pose.Local[j]}");
            }
        }

        private static void AssertLengthsKept(SkeletonPose pose, Skeleton s)
        {
            // IK may only turn joints: every local offset is the rest offset, bit for bit; the world distances
            // then agree with the rest ones to float rounding (1e-5 m is ~100 ulps at 1 m).
            var rest = new SkeletonPose(s);
            for (int j = 0; j < s.JointCount; j++)
                Assert.That(pose.Local[j].Position, Is.EqualTo(s.GetRestLocal(j).Position), $"local offset of joint {j}");
            for (int j = 1; j < s.JointCount; j++)
            {
                int p = s.GetParent(j);
                float now = Vector3.Distance(pose.World[j].Position, pose.World[p].Position);
                float then = Vector3.Distance(rest.World[j].Position, rest.World[p].Position);
                Assert.That(now, Is.EqualTo(then).Within(1e-5f), $"bone {p}-{j}");
            }
            Assert.That(Vector3.Distance(pose.World[Middle].Position, pose.World[End].Position),
                Is.EqualTo(Vector3.Distance(rest.World[Middle].Position, rest.World[End].Position)).Within(1e-5f), "middle-end distance");
        }

        /// <summary>Checks that World is what forward kinematics of Local gives (the solver kept them in step).</summary>
        private static void AssertWorldMatchesLocal(SkeletonPose pose)
        {
            var world = new RigidPose[pose.Skeleton.JointCount];
            pose.Skeleton.ComputeWorld(pose.Local, world, pose.Origin);
            for (int j = 0; j < world.Length; j++)
                Approx.Near(world[j], pose.World[j], 1e-5f, 1e-3f, $"joint {j} world vs FK of local");
        }

        [Test]
        public void ReachesReachableGoalsWithTheMiddleJointTowardTheHint()
        {
            var rng = new Random(11);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            float upper = s.GetRestLocal(Middle).Position.Length();
            float lower = Vector3.Distance(pose.World[Middle].Position, pose.World[End].Position);
            for (int i = 0; i < 500; i++)
            {
                Randomize(pose, rng);
                Vector3 a = pose.World[Root].Position;
                // Goal distances from just outside the tightest fold to just short of full stretch.
                float distance = Math.Abs(upper - lower) + 0.005f + (float)rng.NextDouble() * (upper + lower - Math.Abs(upper - lower) - 0.006f);
                Vector3 goal = a + RandomDirection(rng) * distance;
                Vector3 hint;
                do hint = a + RandomDirection(rng) * (0.1f + (float)rng.NextDouble());
                while (Vectors.ProjectOnPlane(hint - a, Vector3.Normalize(goal - a)).Length() < 0.02f);
                Quaternion goalRotation = RandomRotation(rng);

                LimbResult r = TwoBoneIk.Solve(pose, chain, new RigidPose(goal, goalRotation), hint);
                pose.UpdateWorld();

                // 0.01 mm: the analytic solution is exact; what is left is float rounding at metre scale (~1e-6 m).
                Assert.That(Vector3.Distance(pose.World[End].Position, goal), Is.LessThan(1e-5f), $"case {i}: end joint to goal");
                Assert.That(r.Reached, Is.True, $"case {i}");
                Assert.That(r.DistanceLeft, Is.LessThan(1e-5f), $"case {i}");
                Approx.Near(goalRotation, pose.World[End].Rotation, 0.01f, $"case {i}: end rotation");
                // The middle joint lies in the root-goal-hint plane, on the hint's side of the root-goal line.
                Vector3 axis = Vector3.Normalize(goal - a);
                Vector3 m = Vectors.ProjectOnPlane(pose.World[Middle].Position - a, axis);
                Vector3 h = Vectors.ProjectOnPlane(hint - a, axis);
                Assert.That(Angle(m, h), Is.LessThan(0.05), $"case {i}: middle joint vs hint, about the root-goal line (deg)");
                AssertLengthsKept(pose, s);
                AssertWorldMatchesLocal(pose);
            }
        }

        [Test]
        public void SolvesFromAStraightLimbToo()
        {
            // A limb in a straight line gives no bend plane of its own (the T-pose arm): the hint must give it.
            var names = new[] { "Root", "Middle", "End" };
            var rest = new[] { RigidPose.FromPosition(new Vector3(0, 1, 0)), RigidPose.FromPosition(new Vector3(0, -0.4f, 0)), RigidPose.FromPosition(new Vector3(0, -0.4f, 0)) };
            var s = new Skeleton(names, new[] { -1, 0, 1 }, rest);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, 0, 1, 2);
            Vector3 goal = new Vector3(0.2f, 0.5f, 0.3f);
            Vector3 hint = new Vector3(0, 0.6f, 1f);
            LimbResult r = TwoBoneIk.Solve(pose, chain, new RigidPose(goal, Quaternion.Identity), hint);
            Assert.That(r.Reached, Is.True);
            Approx.Near(goal, pose.World[2].Position, 1e-5f, "end");
            Vector3 axis = Vector3.Normalize(goal - rest[0].Position);
            Assert.That(Angle(Vectors.ProjectOnPlane(pose.World[1].Position - rest[0].Position, axis), Vectors.ProjectOnPlane(hint - rest[0].Position, axis)), Is.LessThan(0.05));
        }

        [Test]
        public void UnreachableGoalStretchesTheLimbTowardIt()
        {
            var rng = new Random(12);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            float reach = s.GetRestLocal(Middle).Position.Length() + Vector3.Distance(pose.World[Middle].Position, pose.World[End].Position);
            for (int i = 0; i < 200; i++)
            {
                Randomize(pose, rng);
                Vector3 a = pose.World[Root].Position;
                float distance = reach * (1.001f + 2f * (float)rng.NextDouble());
                Vector3 goal = a + RandomDirection(rng) * distance;
                Vector3 hint = a + RandomDirection(rng) * 0.5f;

                LimbResult r = TwoBoneIk.Solve(pose, chain, new RigidPose(goal, Quaternion.Identity), hint);
                pose.UpdateWorld();

                Vector3 end = pose.World[End].Position;
                Assert.That(r.Reached, Is.False, $"case {i}");
                // Fully stretched (within 0.1 mm of the summed bone lengths) and pointing at the goal (0.01°).
                Assert.That(Vector3.Distance(a, end), Is.EqualTo(reach).Within(1e-4f), $"case {i}: stretched");
                Assert.That(Angle(end - a, goal - a), Is.LessThan(0.01), $"case {i}: aimed at the goal (deg)");
                Assert.That(r.DistanceLeft, Is.EqualTo(distance - reach).Within(1e-4f), $"case {i}: distance left");
                Assert.That(r.DistanceLeft, Is.EqualTo(Vector3.Distance(end, goal)).Within(1e-6f), $"case {i}: distance left is the end's");
                AssertLengthsKept(pose, s);
            }
        }

        [Test]
        public void TooCloseGoalFoldsTheLimbAsFarAsItGoesTowardTheGoal()
        {
            var rng = new Random(13);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            float upper = s.GetRestLocal(Middle).Position.Length();
            float lower = Vector3.Distance(pose.World[Middle].Position, pose.World[End].Position);
            float fold = Math.Abs(upper - lower);
            for (int i = 0; i < 100; i++)
            {
                Randomize(pose, rng);
                Vector3 a = pose.World[Root].Position;
                Vector3 direction = RandomDirection(rng);
                Vector3 goal = a + direction * fold * 0.5f * (float)rng.NextDouble();
                LimbResult r = TwoBoneIk.Solve(pose, chain, new RigidPose(goal, Quaternion.Identity), a + RandomDirection(rng));
                pose.UpdateWorld();
                AssertFinite(pose);
                AssertLengthsKept(pose, s);
                Vector3 end = pose.World[End].Position;
                Assert.That(r.Reached, Is.False, $"case {i}");
                // The end is at the tightest fold's distance (plus the solver's 0.1 mm margin), on the goal's side.
                Assert.That(Vector3.Distance(a, end), Is.EqualTo(fold).Within(2e-4f), $"case {i}: folded");
                Assert.That(Angle(end - a, goal - a), Is.LessThan(0.05), $"case {i}: toward the goal (deg)");
                Assert.That(r.DistanceLeft, Is.EqualTo(Vector3.Distance(end, goal)).Within(1e-6f), $"case {i}");
            }
        }

        [Test]
        public void DegenerateInputNeverGivesNaN()
        {
            var rng = new Random(14);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            Vector3 a = pose.World[Root].Position;
            Vector3 g = a + new Vector3(0.2f, -0.4f, 0.1f);
            float nan = float.NaN;
            var goals = new[]
            {
                new RigidPose(g, Quaternion.Identity),
                new RigidPose(a, Quaternion.Identity),                                  // goal at the root
                new RigidPose(new Vector3(nan, 0, 0), Quaternion.Identity),              // NaN goal
                new RigidPose(new Vector3(float.PositiveInfinity, 0, 0), Quaternion.Identity),
                new RigidPose(g, new Quaternion(0, 0, 0, 0)),                            // zero quaternion
                new RigidPose(g, new Quaternion(nan, 0, 0, 1)),
                new RigidPose(a + new Vector3(1e6f, 0, 0), Quaternion.Identity),         // very far
            };
            var hints = new[]
            {
                a + new Vector3(0, 0, 1), a, g, a + 0.5f * (g - a), a + 3f * (g - a), // on the root-goal line
                new Vector3(nan, nan, nan), new Vector3(float.NegativeInfinity, 0, 0),
            };
            foreach (RigidPose goal in goals)
                foreach (Vector3 hint in hints)
                    for (int start = 0; start < 3; start++)
                    {
                        // The base stays put so that the root does too and the hints stay on the root-goal line.
                        if (start == 0) pose.ResetToRest(); else Randomize(pose, rng, keepBase: true);
                        LimbResult r = TwoBoneIk.Solve(pose, chain, goal, hint);
                        string what = $"goal {goal}, hint {hint}, start {start}";
                        Assert.That(float.IsNaN(r.DistanceLeft), Is.False, what);
                        pose.UpdateWorld();
                        AssertFinite(pose);
                        AssertLengthsKept(pose, s);
                        if (Vectors.IsFinite(goal.Position) && Vector3.Distance(goal.Position, a) > 0.4f && Vector3.Distance(goal.Position, a) < 0.6f)
                        {
                            // A usable goal position is reached whatever the hint or the goal's rotation.
                            Assert.That(r.Reached, Is.True, what);
                            Approx.Near(goal.Position, pose.World[End].Position, 1e-5f, what);
                        }
                        if (!Vectors.IsFinite(goal.Position)) Assert.That(r.Reached, Is.False, what);
                    }
        }

        /// <summary>
        /// A finite hint very far off (found in review: at ±3e38 m its offset from the root-goal axis overflowed to infinity,
        /// whose square still passed the "off the axis" test) wrote a NaN rotation to the root. It now gives no NaN, and the
        /// goal is reached.
        /// </summary>
        [Test]
        public void AFarHintGivesNoNaN()
        {
            var rng = new Random(17);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            float big = float.MaxValue;
            var hints = new[] { new Vector3(-3e38f, 3e38f, -1f), new Vector3(big, big, big), new Vector3(0f, -big, big), new Vector3(1e20f, -1e25f, 3e30f) };
            for (int i = 0; i < 40; i++)
            {
                Randomize(pose, rng);
                Vector3 a = pose.World[Root].Position;
                var goal = new RigidPose(a + RandomDirection(rng) * 0.45f, RandomRotation(rng));
                Vector3 hint = hints[i % hints.Length];
                LimbResult r = TwoBoneIk.Solve(pose, chain, goal, hint);
                pose.UpdateWorld();
                AssertFinite(pose);
                AssertLengthsKept(pose, s);
                Assert.That(r.Reached, Is.True, $"case {i}, hint {hint}");
            }
        }

        [Test]
        public void ZeroLengthBoneGivesNoNaN()
        {
            var rng = new Random(15);
            Skeleton s = MakeLeg(rng, middleOffsetScale: 0f);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            Vector3 a = pose.World[Root].Position;
            LimbResult r = TwoBoneIk.Solve(pose, chain, new RigidPose(a + new Vector3(0, -0.2f, 0.1f), Quaternion.Identity), a + Vector3.UnitZ);
            pose.UpdateWorld();
            AssertFinite(pose);
            Assert.That(float.IsNaN(r.DistanceLeft), Is.False);
        }

        private static void SolveMany(SkeletonPose pose, LimbChain chain, RigidPose goal, Vector3 hint, int count)
        {
            for (int i = 0; i < count; i++) TwoBoneIk.Solve(pose, chain, goal, hint);
        }

        [Test]
        public void AllocatesNothing()
        {
            var rng = new Random(16);
            Skeleton s = MakeLeg(rng);
            var pose = new SkeletonPose(s);
            var chain = new LimbChain(s, Root, Middle, End);
            var goal = new RigidPose(pose.World[Root].Position + new Vector3(0.1f, -0.5f, 0.1f), Quaternion.Identity);
            Vector3 hint = pose.World[Root].Position + Vector3.UnitZ;
            SolveMany(pose, chain, goal, hint, 1000);
            // Windows inside a loop, the loop of solves in a method of its own that has run before: a long loop in
            // a not yet optimised method switches to optimised code in the middle (on-stack replacement), which
            // allocates a few bytes of the runtime's own.
            var bytes = new long[4];
            for (int k = 0; k < bytes.Length; k++)
            {
                long t0 = GC.GetAllocatedBytesForCurrentThread();
                SolveMany(pose, chain, goal, hint, 5000);
                bytes[k] = GC.GetAllocatedBytesForCurrentThread() - t0;
            }
            Assert.That(bytes, Is.EqualTo(new long[bytes.Length]));
        }
    }
}
