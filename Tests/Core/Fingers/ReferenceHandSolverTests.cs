using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The finger solver on hands built in code (no mocap needed): every bundled profile, both hands, three hand
    /// sizes, and rigs whose bones point along different local axes with arbitrary twists.
    /// </summary>
    public class ReferenceHandSolverTests
    {
        private static List<ControllerProfile> Profiles()
        {
            string dir = Path.Combine(TestData.PackageRoot ?? ".", "Runtime", "ControllerProfiles");
            if (!Directory.Exists(dir)) Assert.Ignore("controller profiles not found");
            var list = new List<ControllerProfile>();
            foreach (string file in Directory.GetFiles(dir, "*.json")) list.Add(ControllerProfile.Parse(File.ReadAllText(file)));
            return list;
        }

        private static readonly Vector3[] Axes =
        {
            Vector3.UnitY, Vector3.UnitX, -Vector3.UnitX, Vector3.UnitZ, -Vector3.UnitY, Vector3.Normalize(new Vector3(1, 2, -3)),
        };

        [Test]
        public void ClosingCurlsEveryFingerTowardThePalmWhateverTheBoneAxes()
        {
            foreach (Vector3 axis in Axes)
                foreach (bool left in new[] { true, false })
                {
                    HumanoidMap map = ReferenceHandRig.Build(1f, axis, 7, Rotations.AngleAxis(70f, new Vector3(0.2f, 0.1f, 1f)));
                    var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                    Skeleton s = map.Skeleton;
                    var pose = new SkeletonPose(s);
                    pose.ResetToRest();
                    var t = new FingerParameters();
                    for (Finger f = Finger.Thumb; f <= Finger.Little; f++)
                        for (Phalanx k = Phalanx.Proximal; k <= Phalanx.Distal; k++) t[f, k] = 0.5f; // every joint half closed, the thumb not spread
                    model.Apply(t, pose);
                    var world = new RigidPose[s.JointCount];
                    s.ComputeWorld(pose.Local, world);
                    var rest = new RigidPose[s.JointCount];
                    s.GetRestLocal(rest);
                    var restWorld = new RigidPose[s.JointCount];
                    s.ComputeWorld(rest, restWorld);
                    RigidPose hand = restWorld[model.HandJoint];
                    Vector3 palm = hand.TransformDirection(model.PalmNormalInHand);
                    // Truth from the construction: the palm faces the rig's canonical −y, turned by the arm rotation.
                    Vector3 expectedPalm = Vector3.Transform(-Vector3.UnitY, Rotations.AngleAxis(70f, new Vector3(0.2f, 0.1f, 1f)));
                    Assert.That(Vector3.Dot(palm, expectedPalm), Is.GreaterThan(0.99f), $"palm normal, axis {axis}, {(left ? "left" : "right")}");
                    for (int f = 1; f < 5; f++)
                    {
                        int tip = map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, (Finger)f, Phalanx.Distal)] + 1; // the end site follows the distal joint
                        Vector3 moved = world[tip].Position - restWorld[tip].Position;
                        // Half-closed, every tip has moved toward the palm side by at least 1 cm (a 7-9 cm finger
                        // turned by 35-50° per joint moves its tip 3-6 cm).
                        Assert.That(Vector3.Dot(moved, palm), Is.GreaterThan(0.01f), $"finger {f}, axis {axis}, {(left ? "left" : "right")}");
                    }
                    // The thumb flexes across the palm: its tip comes at least 1 cm nearer the little finger's base
                    // (a 9.8 cm thumb turned by 20°, 25° and 35°) and moves to the palm side.
                    int thumbTip = map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, Finger.Thumb, Phalanx.Distal)] + 1;
                    Vector3 littleBase = restWorld[map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, Finger.Little, Phalanx.Proximal)]].Position;
                    float nearer = Vector3.Distance(restWorld[thumbTip].Position, littleBase) - Vector3.Distance(world[thumbTip].Position, littleBase);
                    Assert.That(nearer, Is.GreaterThan(0.01f), $"thumb toward the little finger, axis {axis}, {(left ? "left" : "right")}");
                    Assert.That(Vector3.Dot(world[thumbTip].Position - restWorld[thumbTip].Position, palm), Is.GreaterThan(0f), $"thumb to the palm side, axis {axis}, {(left ? "left" : "right")}");

                    // Spreading alone lifts the thumb radially: away from the little finger, along little-to-index.
                    var spreadOnly = new FingerParameters { ThumbSpread = 0.5f };
                    pose.ResetToRest();
                    model.Apply(spreadOnly, pose);
                    s.ComputeWorld(pose.Local, world);
                    Vector3 across = hand.TransformDirection(model.AcrossInHand);
                    Vector3 lifted = world[thumbTip].Position - restWorld[thumbTip].Position;
                    Assert.That(Vector3.Dot(lifted, across), Is.GreaterThan(0.01f), $"thumb spread, axis {axis}, {(left ? "left" : "right")}");
                    for (int f = 1; f < 5; f++)
                    {
                        int tip = map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, (Finger)f, Phalanx.Distal)] + 1;
                        Assert.That(Vector3.Distance(world[tip].Position, restWorld[tip].Position), Is.LessThan(1e-5f), "spreading the thumb moves no finger");
                    }
                }
        }

        [Test]
        public void TheGripDoesNotDependOnTheRigsAxisConvention()
        {
            foreach (ControllerProfile profile in Profiles())
                foreach (bool left in new[] { true, false })
                {
                    float[] reference = null;
                    foreach (Vector3 axis in Axes)
                    {
                        HumanoidMap map = ReferenceHandRig.Build(1f, axis, 11, Rotations.AngleAxis(-90f, Vector3.UnitZ));
                        var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                        var solver = new FingerSolver(model, profile);
                        var hand = new RigidPose(new Vector3(0.3f, 1.0f, 0.2f), Rotations.AngleAxis(25f, new Vector3(1, 1, 0)));
                        solver.Solve(hand, hand * model.ControllerInHand(profile), GripMode.Hold);
                        float[] t = solver.Parameters.ToArray();
                        if (reference == null) { reference = t; continue; }
                        // The rigs have the same geometry to float precision; 0.01 in t is under 1° at a joint.
                        for (int i = 0; i < FingerParameters.Count; i++)
                            Assert.That(t[i], Is.EqualTo(reference[i]).Within(0.01f), $"{profile.Name} {(left ? "left" : "right")} axis {axis} parameter {i}");
                    }
                    Assert.That(reference[4], Is.GreaterThan(0.2f), profile.Name + ": the index closes");
                }
        }

        private static float Median(List<float> values)
        {
            values.Sort();
            return values[values.Count / 2];
        }

        [TestCase(0.85f)]
        [TestCase(1.0f)]
        [TestCase(1.15f)]
        public void EveryProfileIsHeldWithoutPenetrationAndWithFingertipsOnTheSurface(float scale)
        {
            HumanoidMap map = ReferenceHandRig.Build(scale, Vector3.UnitX, 5, Quaternion.Identity);
            foreach (ControllerProfile profile in Profiles())
                foreach (bool left in new[] { true, false })
                {
                    var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                    var solver = new FingerSolver(model, profile);
                    RigidPose inHand = model.ControllerInHand(profile);
                    float maxPenetration = 0f;
                    var gaps = new List<float>[5];
                    for (int f = 0; f < 5; f++) gaps[f] = new List<float>();
                    var thumbToRest = new List<float>();
                    for (int frame = 0; frame < 90; frame++)
                    {
                        float time = frame / 90f;
                        // The controller wobbles in the hand by up to 2 mm and 3°, as a loosely held controller does.
                        var wobble = new RigidPose(new Vector3(0.002f * MathF.Sin(5 * time), 0.002f * MathF.Cos(3 * time), 0.001f * MathF.Sin(7 * time)),
                            Rotations.AngleAxis(3f * MathF.Sin(4 * time), new Vector3(0.3f, 1f, 0.2f)));
                        solver.Solve(RigidPose.Identity, inHand * wobble, GripMode.Hold);
                        for (int f = 0; f < 5; f++)
                        {
                            for (int point = 0; point < 3; point++) maxPenetration = Math.Max(maxPenetration, -solver.SurfaceGap((Finger)f, (FingerPoint)point));
                            gaps[f].Add(Math.Abs(solver.SurfaceGap((Finger)f, FingerPoint.Tip)));
                        }
                        thumbToRest.Add(solver.GoalDistance(Finger.Thumb));
                    }
                    string what = $"{profile.Name} {(left ? "left" : "right")} scale {scale}";
                    // The issue's bounds: no point of a finger more than 1 mm into the surface; every fingertip, the
                    // thumb's included, within 3 mm of it (median).
                    Assert.That(maxPenetration, Is.LessThanOrEqualTo(0.001f), what + ": penetration");
                    for (int f = 0; f < 5; f++)
                        Assert.That(Median(gaps[f]), Is.LessThanOrEqualTo(0.003f), $"{what}: median gap of fingertip {f}");
                    // The thumb lies on the top of the head, not on its side: within 25 mm of the thumb rest (the heads'
                    // top faces are 40-52 mm deep, so 25 mm from their centre is still on them).
                    Assert.That(Median(thumbToRest), Is.LessThanOrEqualTo(0.025f), what + ": thumb tip to thumb rest");
                }
        }

        [Test]
        public void TheCostsAnalyticGradientMatchesFiniteDifferencesForEveryFingerAndTheThumbsSpread()
        {
            HumanoidMap map = ReferenceHandRig.Build(1f, Vector3.Normalize(new Vector3(1, 2, -3)), 9, Rotations.AngleAxis(30f, Vector3.UnitX));
            var rng = new Random(4);
            foreach (ControllerProfile profile in Profiles())
                foreach (bool left in new[] { true, false })
                {
                    var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                    var solver = new FingerSolver(model, profile);
                    var hand = new RigidPose(new Vector3(0.1f, 1.2f, -0.3f), Rotations.AngleAxis(40f, new Vector3(0, 1, 1)));
                    solver.Solve(hand, hand * model.ControllerInHand(profile), GripMode.Hold); // sets the hand in the controller frame
                    int compared = 0;
                    for (int sample = 0; sample < 40; sample++)
                    {
                        int f = sample % 5;
                        var t = new Vector4((float)rng.NextDouble(), (float)rng.NextDouble(), (float)rng.NextDouble(), f == 0 ? (float)rng.NextDouble() : 0f);
                        solver.Cost(f, t, out Vector4 analytic);
                        for (int k = 0; k < (f == 0 ? 4 : 3); k++)
                        {
                            const float h = 1e-3f;
                            Vector4 e = k == 0 ? Vector4.UnitX : k == 1 ? Vector4.UnitY : k == 2 ? Vector4.UnitZ : Vector4.UnitW;
                            float plus = solver.Cost(f, t + h * e, out _), minus = solver.Cost(f, t - h * e, out _);
                            // Skip the samples where a point crosses the surface or a shape's seam within ±h: the
                            // cost has a kink there and the central difference is not its derivative.
                            float centre = solver.Cost(f, t, out _);
                            if (Math.Abs(plus + minus - 2f * centre) > 1e-5f) continue;
                            float numeric = (plus - minus) / (2f * h);
                            float component = k == 0 ? analytic.X : k == 1 ? analytic.Y : k == 2 ? analytic.Z : analytic.W;
                            Assert.That(component, Is.EqualTo(numeric).Within(2e-3f + 0.02f * Math.Abs(numeric)), $"{profile.Name} {(left ? "left" : "right")} finger {f} parameter {k} at {t}");
                            compared++;
                        }
                    }
                    Assert.That(compared, Is.GreaterThan(60), "most samples are away from kinks");
                }
        }

        [Test]
        public void TheAppliedPoseIsTheSolvedOneAndTheHandsAreMirrorImages()
        {
            HumanoidMap map = ReferenceHandRig.Build(1f, Vector3.Normalize(new Vector3(1, 2, -3)), 13, Rotations.AngleAxis(20f, Vector3.UnitY));
            Skeleton s = map.Skeleton;
            foreach (ControllerProfile profile in Profiles())
            {
                var t = new float[2][];
                foreach (bool left in new[] { true, false })
                {
                    var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                    var solver = new FingerSolver(model, profile);
                    var hand = new RigidPose(new Vector3(0.2f, 1.1f, 0.4f), Rotations.AngleAxis(-35f, new Vector3(1, 0, 1)));
                    RigidPose controller = hand * model.ControllerInHand(profile);
                    solver.Solve(hand, controller, GripMode.Hold);
                    t[left ? 0 : 1] = solver.Parameters.ToArray();
                    // What the avatar shows (Apply, then forward kinematics) is what the solver measured.
                    var pose = new SkeletonPose(s);
                    pose.ResetToRest();
                    pose.Local[model.HandJoint] = hand.RelativeTo(s.GetParent(model.HandJoint) < 0 ? RigidPose.Identity : RestWorld(s)[s.GetParent(model.HandJoint)]);
                    model.Apply(solver.Parameters, pose);
                    var world = new RigidPose[s.JointCount];
                    s.ComputeWorld(pose.Local, world);
                    for (int f = 0; f < 5; f++)
                        for (int k = 1; k < 3; k++)
                        {
                            Vector3 shown = controller.InverseTransformPoint(world[map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, (Finger)f, (Phalanx)k)]].Position);
                            Assert.That(Vector3.Distance(shown, solver.PointInController((Finger)f, (FingerPoint)(k - 1))), Is.LessThan(1e-5f), $"{profile.Name} {(left ? "left" : "right")} finger {f} joint {k}");
                        }
                    int tip = map[HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, Finger.Thumb, Phalanx.Distal)] + 1;
                    Assert.That(Vector3.Distance(controller.InverseTransformPoint(world[tip].Position), solver.PointInController(Finger.Thumb, FingerPoint.Tip)), Is.LessThan(1e-5f), profile.Name + ": thumb tip");
                }
                // The profiles are symmetric about their x = 0 plane and the hands are mirror images: same grip.
                for (int i = 0; i < FingerParameters.Count; i++)
                    Assert.That(t[0][i], Is.EqualTo(t[1][i]).Within(0.005f), $"{profile.Name}: parameter {i}, left against right");
            }
        }

        private static RigidPose[] RestWorld(Skeleton s)
        {
            var rest = new RigidPose[s.JointCount];
            s.GetRestLocal(rest);
            var world = new RigidPose[s.JointCount];
            s.ComputeWorld(rest, world);
            return world;
        }

        [Test]
        public void AHandWithoutAThumbHoldsWithItsFingersAndReportsNoThumb()
        {
            HumanoidMap full = ReferenceHandRig.Build();
            var bones = new List<KeyValuePair<HumanoidBone, string>>();
            foreach (HumanoidBone b in Enum.GetValues(typeof(HumanoidBone)))
            {
                bool thumb = false;
                foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                    for (Phalanx k = Phalanx.Proximal; k <= Phalanx.Distal; k++) thumb |= b == HumanoidBones.Finger(side, Finger.Thumb, k);
                if (!thumb && full.Has(b)) bones.Add(new KeyValuePair<HumanoidBone, string>(b, full.NameOf(b)));
            }
            var map = new HumanoidMap(full.Skeleton, bones);
            foreach (ControllerProfile profile in Profiles())
            {
                var model = new HandModel(map, BodySide.Right);
                Assert.That(model.Has(Finger.Thumb), Is.False);
                var solver = new FingerSolver(model, profile);
                solver.Solve(RigidPose.Identity, model.ControllerInHand(profile), GripMode.Hold);
                Assert.That(float.IsNaN(solver.PointInController(Finger.Thumb, FingerPoint.Tip).X), Is.True, profile.Name + ": no thumb, no thumb point");
                Assert.That(float.IsNaN(solver.GoalDistance(Finger.Thumb)), Is.True, profile.Name + ": no thumb, no thumb distance");
                Assert.That(solver.Parameters[Finger.Thumb, Phalanx.Proximal] + solver.Parameters[Finger.Thumb, Phalanx.Intermediate] + solver.Parameters[Finger.Thumb, Phalanx.Distal] + solver.Parameters.ThumbSpread, Is.EqualTo(0f), profile.Name + ": the missing thumb stays at rest");
                for (int f = 1; f < 5; f++)
                    Assert.That(Math.Abs(solver.SurfaceGap((Finger)f, FingerPoint.Tip)), Is.LessThanOrEqualTo(0.003f), $"{profile.Name}: fingertip {f} on the surface");
            }
        }

        [Test]
        public void SameGripAt72_90And144HzAndOpenWithoutOscillationOutOfReach()
        {
            HumanoidMap map = ReferenceHandRig.Build(1f, -Vector3.UnitX, 3, Quaternion.Identity);
            foreach (ControllerProfile profile in Profiles())
            {
                var model = new HandModel(map, BodySide.Right);
                RigidPose inHand = model.ControllerInHand(profile);
                int[] rates = { 72, 90, 144 };
                var final = new float[rates.Length][];
                for (int r = 0; r < rates.Length; r++)
                {
                    var solver = new FingerSolver(model, profile);
                    for (int i = 0; i <= rates[r]; i++)
                    {
                        float time = i / (float)rates[r]; // one second; every rate ends on the same pose at t = 1 s
                        var wobble = new RigidPose(new Vector3(0.002f * MathF.Sin(5 * time), 0, 0.002f * MathF.Cos(4 * time)), Rotations.AngleAxis(4f * MathF.Sin(3 * time), Vector3.UnitX));
                        solver.Solve(RigidPose.Identity, inHand * wobble, GripMode.Hold);
                    }
                    final[r] = solver.Parameters.ToArray();
                    // Pull the controller out of the hand over 10 frames: the hand must end open and stay open.
                    float previousSum = float.MaxValue;
                    for (int i = 1; i <= 20; i++)
                    {
                        var away = new RigidPose(new Vector3(0, 0, 0.01f * Math.Min(i, 10)), Quaternion.Identity);
                        solver.Solve(RigidPose.Identity, away * inHand, GripMode.Hold);
                        if (i >= 10)
                        {
                            float sum = 0f;
                            foreach (float v in solver.Parameters.ToArray()) sum += v;
                            Assert.That(sum, Is.EqualTo(0f), $"{profile.Name}: open once out of reach (frame {i})");
                            Assert.That(sum, Is.LessThanOrEqualTo(previousSum));
                            previousSum = sum;
                        }
                    }
                }
                for (int i = 0; i < FingerParameters.Count; i++)
                {
                    Assert.That(Math.Abs(final[0][i] - final[2][i]), Is.LessThanOrEqualTo(0.02f), $"{profile.Name} parameter {i}, 72 vs 144 Hz");
                    Assert.That(Math.Abs(final[1][i] - final[2][i]), Is.LessThanOrEqualTo(0.02f), $"{profile.Name} parameter {i}, 90 vs 144 Hz");
                }
            }
        }

        // A new solver's grip for one frame: what a solve that never keeps an earlier grip gives.
        private static float[] FreshGrip(HandModel model, ControllerProfile profile, RigidPose hand, RigidPose controller, GripMode mode, float trigger = float.NaN, float grip = float.NaN)
        {
            var solver = new FingerSolver(model, profile);
            solver.Solve(hand, controller, mode, trigger, grip);
            Assert.That(solver.LastSolveReused, Is.False, "a new solver descends");
            return solver.Parameters.ToArray();
        }

        [Test]
        public void AHandStillInItsControllerKeepsItsGripAndOneThatMovesIsSolvedAgain()
        {
            HumanoidMap map = ReferenceHandRig.Build(1f, Vector3.Normalize(new Vector3(1, 2, -3)), 9, Rotations.AngleAxis(30f, Vector3.UnitX));
            foreach (ControllerProfile profile in Profiles())
                foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                {
                    string what = $"{profile.Name} {side}";
                    var model = new HandModel(map, side);
                    var solver = new FingerSolver(model, profile);
                    // The hand a little off the nominal hold (3 mm, 4°), the controller somewhere in the room.
                    var controller = new RigidPose(new Vector3(0.3f, 1.1f, -0.4f), Rotations.AngleAxis(75f, new Vector3(0.3f, 1f, -0.2f)));
                    RigidPose inController = model.WristInController(profile) * new RigidPose(new Vector3(0.003f, 0, 0), Rotations.AngleAxis(4f, Vector3.UnitZ));
                    RigidPose hand = controller * inController;

                    solver.Solve(hand, controller, GripMode.Hold);
                    float[] solved = solver.Parameters.ToArray();
                    Assert.That(solver.LastSolveReused, Is.False, what);
                    Assert.That(solver.LastIterations, Is.GreaterThan(0), what);
                    Assert.That(solved, Is.EqualTo(FreshGrip(model, profile, hand, controller, GripMode.Hold)), what + ": the first solve descends as a new solver does");

                    // Hand and controller carried together across the room: the same grip, without a descent.
                    var carried = new RigidPose(new Vector3(-1.5f, 0.2f, 2f), Rotations.AngleAxis(140f, new Vector3(1f, -0.5f, 0.2f)));
                    solver.Solve(carried * hand, carried * controller, GripMode.Hold);
                    Assert.That(solver.LastSolveReused, Is.True, what + ": carried");
                    Assert.That(solver.LastIterations, Is.EqualTo(0), what);
                    Assert.That(solver.Parameters.ToArray(), Is.EqualTo(solved), what + ": carried");

                    // Half the tolerances away: kept, and here as a new descent there would give it (within its own tolerance; the
                    // descent is not continuous everywhere, so elsewhere a pose this close can give another grip).
                    RigidPose nudged = controller * new RigidPose(new Vector3(0, 0.5f * FingerSolver.ResolveDistance, 0), Quaternion.Identity) * inController;
                    solver.Solve(nudged, controller, GripMode.Hold);
                    Assert.That(solver.LastSolveReused, Is.True, what + ": nudged");
                    float[] fresh = FreshGrip(model, profile, nudged, controller, GripMode.Hold);
                    float[] kept = solver.Parameters.ToArray();
                    for (int i = 0; i < solved.Length; i++)
                        Assert.That(kept[i], Is.EqualTo(fresh[i]).Within(2e-3f), $"{what}: parameter {i} against a new descent half a tolerance away");
                    RigidPose turned = controller * inController * new RigidPose(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.5f * FingerSolver.ResolveAngle));
                    solver.Solve(turned, controller, GripMode.Hold);
                    Assert.That(solver.LastSolveReused, Is.True, what + ": turned by half the angle");

                    // Drifting 0.3 tolerances a frame: kept while within the tolerance of the pose last solved (not of the last
                    // frame), so the drift is solved again before it adds up; every descent is a new solver's.
                    RigidPose lastSolved = inController;
                    int descents = 0;
                    for (int i = 1; i <= 12; i++)
                    {
                        RigidPose drifted = new RigidPose(new Vector3(0.3f * FingerSolver.ResolveDistance * i, 0, 0), Quaternion.Identity) * inController;
                        solver.Solve(controller * drifted, controller, GripMode.Hold);
                        float apart = Vector3.Distance(drifted.Position, lastSolved.Position);
                        if (solver.LastSolveReused)
                            Assert.That(apart, Is.LessThanOrEqualTo(FingerSolver.ResolveDistance * 1.01f), $"{what}: kept {apart * 1e6f:F2} µm from its descent (frame {i})");
                        else
                        {
                            descents++;
                            lastSolved = drifted;
                            Assert.That(solver.Parameters.ToArray(), Is.EqualTo(FreshGrip(model, profile, controller * drifted, controller, GripMode.Hold)), $"{what}: descent at frame {i}");
                        }
                    }
                    Assert.That(descents, Is.InRange(3, 6), what + ": 3.6 tolerances of drift in steps of 0.3 are descended again about every tolerance");

                    // Turned by twice the angle tolerance: solved again.
                    RigidPose turnedMore = controller * inController * new RigidPose(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitY, 2f * FingerSolver.ResolveAngle));
                    solver.Solve(turnedMore, controller, GripMode.Hold);
                    Assert.That(solver.LastSolveReused, Is.False, what + ": turned by twice the angle");

                    // Another mode at the same pose: pointing is descended again; an input-driven grip with the trigger
                    // pressed closes the same fingers, blended by the inputs.
                    solver.Solve(hand, controller, GripMode.Hold);
                    solver.Solve(hand, controller, GripMode.Point);
                    Assert.That(solver.LastSolveReused, Is.False, what + ": pointing");
                    Assert.That(solver.Parameters.ToArray(), Is.EqualTo(FreshGrip(model, profile, hand, controller, GripMode.Point)), what + ": pointing");
                    solver.Solve(hand, controller, GripMode.Hold);
                    solver.Solve(hand, controller, GripMode.InputDriven, 0.5f, 0.7f);
                    Assert.That(solver.LastSolveReused, Is.True, what + ": the trigger pressed closes the index as the hold does");
                    Assert.That(solver.Parameters.ToArray(), Is.EqualTo(FreshGrip(model, profile, hand, controller, GripMode.InputDriven, 0.5f, 0.7f)), what + ": input-driven");

                    // Opened (or out of reach) and closed again: descended again.
                    solver.Solve(hand, controller, GripMode.Open);
                    solver.Solve(hand, controller, GripMode.Hold);
                    Assert.That(solver.LastSolveReused, Is.False, what + ": after the open hand");
                    Assert.That(solver.Parameters.ToArray(), Is.EqualTo(solved), what + ": after the open hand");
                }
        }

        [Test]
        public void TheGripPointSitsOnThePalmCentreAndTheWristFollowsTheController()
        {
            HumanoidMap map = ReferenceHandRig.Build(1.1f, Vector3.UnitZ, 9, Rotations.AngleAxis(30f, Vector3.UnitY));
            foreach (ControllerProfile profile in Profiles())
                foreach (bool left in new[] { true, false })
                {
                    var model = new HandModel(map, left ? BodySide.Left : BodySide.Right);
                    RigidPose controllerInHand = model.ControllerInHand(profile);
                    // The palm centre (on the skin) touches the handle: 2 mm of clearance, within 0.5 mm.
                    Vector3 palmInController = controllerInHand.InverseTransformPoint(model.PalmCentreInHand);
                    Assert.That(profile.Shape.Distance(palmInController), Is.EqualTo(0.002f).Within(0.0005f), profile.Name);
                    // The handle runs across the palm (controller +Y along little → index).
                    Vector3 handleAxis = controllerInHand.TransformDirection(Vector3.UnitY);
                    Assert.That(Vector3.Dot(handleAxis, model.AcrossInHand), Is.GreaterThan(0.999f), profile.Name);
                    // Wrist from a tracked controller pose: c * WristInController puts the palm centre back on the grip.
                    var c = new RigidPose(new Vector3(0.1f, 1.2f, 0.4f), Rotations.AngleAxis(120f, new Vector3(1, -2, 0.5f)));
                    RigidPose wrist = c * model.WristInController(profile);
                    Vector3 palmWorld = wrist.TransformPoint(model.PalmCentreInHand);
                    Assert.That(Vector3.Distance(c.InverseTransformPoint(palmWorld), palmInController), Is.LessThan(1e-5f), profile.Name);
                }
        }
    }
}
