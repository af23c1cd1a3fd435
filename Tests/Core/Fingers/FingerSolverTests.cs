using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    public class FingerSolverTests
    {
        private static HumanoidMap MixamoHand() =>
            HumanoidNaming.Detect(BvhReader.ReadFile(TestData.Mocap("mixamo_fingers_30fps.bvh"), new BvhReadOptions { ToMetres = true }).Skeleton);

        /// <summary>
        /// A hand whose knuckles give no palm plane (the index, middle and little bases on a line with the wrist, or the index
        /// and little bases at one point) is not modelled: <see cref="HandModel.CanModel(HumanoidMap, BodySide, SkeletonPose, out string)"/>
        /// says why and the constructor refuses it (found in review: the palm's axes were normalised from zero vectors and
        /// every finger, the grip and the wrist's place on the controller became NaN).
        /// </summary>
        [Test]
        public void AHandWithoutAPalmPlaneIsNotModelled()
        {
            HumanoidMap map = MixamoHand();
            SkeletonPose pose = RestPose(map);
            Assert.That(HandModel.CanModel(map, BodySide.Left, pose, out string reason), Is.True, reason);
            int wrist = map[HumanoidBone.LeftHand];
            int index = map[HumanoidBones.Finger(BodySide.Left, Finger.Index, Phalanx.Proximal)];
            int middle = map[HumanoidBones.Finger(BodySide.Left, Finger.Middle, Phalanx.Proximal)];
            int little = map[HumanoidBones.Finger(BodySide.Left, Finger.Little, Phalanx.Proximal)];
            Vector3 w = pose.World[wrist].Position, along = pose.World[middle].Position - w;
            pose.World[index] = pose.World[index].WithPosition(w + 1.1f * along);
            pose.World[little] = pose.World[little].WithPosition(w + 0.9f * along);
            Assert.That(HandModel.CanModel(map, BodySide.Left, pose, out reason), Is.False);
            Assert.That(reason, Does.Contain("on a line"));
            Assert.Throws<ArgumentException>(() => new HandModel(map, BodySide.Left, pose));
            pose.World[little] = pose.World[index];
            Assert.That(HandModel.CanModel(map, BodySide.Left, pose, out reason), Is.False);
            Assert.That(reason, Does.Contain("at one point"));
            Assert.That(HandModel.CanModel(map, BodySide.Right, pose, out reason), Is.True, "the other hand is as it was");
        }

        /// <summary>
        /// A fingertip is not taken from a stub under the last phalanx (a zero-length End Site, a nail bone): the tip is then
        /// extrapolated from the phalanx before, as for a finger without an end (found in review: the tip sat at the joint,
        /// so the last phalanx went into the controller).
        /// </summary>
        [Test]
        public void AStubUnderTheLastPhalanxIsNotTheFingertip()
        {
            HumanoidMap map = MixamoHand();
            SkeletonPose pose = RestPose(map);
            int j1 = map[HumanoidBones.Finger(BodySide.Left, Finger.Index, Phalanx.Intermediate)];
            int j2 = map[HumanoidBones.Finger(BodySide.Left, Finger.Index, Phalanx.Distal)];
            int end = -1;
            for (int c = j2 + 1; c < map.Skeleton.JointCount && end < 0; c++) if (map.Skeleton.GetParent(c) == j2) end = c;
            Assume.That(end, Is.GreaterThan(0), "the Mixamo index finger ends in an End Site");
            float phalanx = Vector3.Distance(pose.World[j1].Position, pose.World[j2].Position);
            float withEnd = new HandModel(map, BodySide.Left, pose).TipLocal[(int)Finger.Index].Length();
            pose.World[end] = pose.World[end].WithPosition(pose.World[j2].Position + (pose.World[end].Position - pose.World[j2].Position) * 0.01f);
            float withStub = new HandModel(map, BodySide.Left, pose).TipLocal[(int)Finger.Index].Length();
            TestContext.WriteLine($"tip {withEnd * 1000:F1} mm from the last joint with its End Site, {withStub * 1000:F1} mm with a 1 % stub (phalanx before {phalanx * 1000:F1} mm)");
            Assert.That(withEnd, Is.GreaterThan(0.3f * phalanx), "the End Site marks the tip");
            Assert.That(withStub, Is.EqualTo(0.8f * phalanx).Within(1e-4f), "a stub: extrapolated, 0.8 of the phalanx before");
        }

        // The rig in its rest pose, world poses up to date (a pose to edit as a hand's open pose).
        private static SkeletonPose RestPose(HumanoidMap map)
        {
            var pose = new SkeletonPose(map.Skeleton);
            map.Skeleton.GetRestLocal(pose.Local);
            pose.UpdateWorld();
            return pose;
        }

        private static IEnumerable<ControllerProfile> Profiles()
        {
            string dir = Path.Combine(TestData.PackageRoot ?? ".", "Runtime", "ControllerProfiles");
            if (!Directory.Exists(dir)) Assert.Ignore("controller profiles not found");
            foreach (string file in Directory.GetFiles(dir, "*.json")) yield return ControllerProfile.Parse(File.ReadAllText(file));
        }

        /// <summary>The same rig with every finger bone's local frame turned arbitrarily (world geometry unchanged).</summary>
        private static HumanoidMap WithTwistedLocalAxes(HumanoidMap map, int seed)
        {
            Skeleton s = map.Skeleton;
            var rng = new Random(seed);
            var turn = new Quaternion[s.JointCount];
            for (int j = 0; j < turn.Length; j++)
                turn[j] = HumanoidBones.IsFinger(map.BoneOf(j)) ? DeviceMountings.UniformRotation(rng) : Quaternion.Identity;
            var rest = new RigidPose[s.JointCount];
            var parents = new int[s.JointCount];
            var ends = new bool[s.JointCount];
            for (int j = 0; j < rest.Length; j++)
            {
                parents[j] = s.GetParent(j);
                ends[j] = s.IsEndSite(j);
                RigidPose local = s.GetRestLocal(j);
                Quaternion parentTurn = parents[j] >= 0 ? turn[parents[j]] : Quaternion.Identity;
                // new local = R_parent^-1 * old local * R_j: world rotations become old * R_j, positions unchanged.
                rest[j] = new RigidPose(Vector3.Transform(local.Position, Quaternion.Conjugate(parentTurn)),
                    Quaternion.Normalize(Quaternion.Conjugate(parentTurn) * local.Rotation * turn[j]));
            }
            return new HumanoidMap(new Skeleton(s.Names, parents, rest, ends), map.Pairs());
        }

        [Test]
        public void EveryBundledProfileParsesWithItsGripPointInsideTheHandle()
        {
            int n = 0;
            foreach (ControllerProfile p in Profiles())
            {
                n++;
                Assert.That(p.Shape.Distance(Vector3.Zero), Is.LessThan(-0.01f), p.Name + ": grip origin inside the handle");
                // Goals are points of the surface (within 3 mm: they are the centres of slightly curved buttons).
                Assert.That(Math.Abs(p.Shape.Distance(p.Trigger)), Is.LessThan(0.003f), p.Name + ": trigger on the surface");
                Assert.That(Math.Abs(p.Shape.Distance(p.ThumbRest)), Is.LessThan(0.003f), p.Name + ": thumb rest on the surface");
            }
            Assert.That(n, Is.GreaterThanOrEqualTo(3));
            Assert.Throws<FormatException>(() => ControllerProfile.Parse("{\"format\": \"avatargo-controller-profile\", \"version\": 1, \"shapes\": []}"));
        }

        /// <summary>
        /// <see cref="FingerSolver.SkinDepth"/> (what `avatargo fingers` reports as skin depth) is the deepest skin along
        /// the finger from its knuckle to its tip, checked against 2000 samples of the same bones, on the Mixamo hand opened
        /// as the pipeline opens it, every profile, both hands; it sees at least what the three points the IK keeps out see.
        /// Measured with it at the nominal hold: the three points are on the surface, the skin between them 3.6–10.1 mm
        /// inside (a straight phalanx between two points on the surface crosses a convex handle; deepest where the Quest
        /// Touch and the Index hold a knuckle itself inside: fingers.md, open points).
        /// </summary>
        [Test]
        public void SkinDepthIsTheDeepestSkinAlongTheFinger()
        {
            HumanoidMap map = MixamoHand();
            var pose = new SkeletonPose(map.Skeleton);
            TPoser.Apply(map, pose, RigidPose.Identity);
            foreach (ControllerProfile profile in Profiles())
                foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                {
                    var hand = new HandModel(map, side, pose);
                    RigidPose held = hand.ControllerInHand(profile);
                    var solver = new FingerSolver(hand, profile);
                    solver.Solve(RigidPose.Identity, held, GripMode.Hold);
                    for (int f = 0; f < 5; f++)
                    {
                        var finger = (Finger)f;
                        var knuckle = held.InverseTransformPoint(hand.RestRelative[f, 0].Position); // its first joint
                        Vector3[] bones = { knuckle, solver.PointInController(finger, FingerPoint.IntermediateJoint), solver.PointInController(finger, FingerPoint.DistalJoint), solver.PointInController(finger, FingerPoint.Tip) };
                        float deepest = 0f, atPoints = 0f;
                        for (int b = 0; b < 3; b++)
                        {
                            for (int i = 0; i <= 2000 / 3; i++)
                                deepest = Math.Max(deepest, hand.FingerRadius - profile.Shape.Distance(Vector3.Lerp(bones[b], bones[b + 1], i / (2000f / 3))));
                            atPoints = Math.Max(atPoints, -solver.SurfaceGap(finger, (FingerPoint)b));
                        }
                        float skin = solver.SkinDepth(finger);
                        string what = $"{profile.Name} {side} {finger}";
                        TestContext.WriteLine($"{what}: skin at most {skin * 1000:0.00} mm deep (sampled densely {deepest * 1000:0.00}), at the points {atPoints * 1000:0.00}");
                        Assert.That(skin, Is.EqualTo(deepest).Within(1e-4f), what + ": the deepest skin along the finger (m)");
                        Assert.That(skin, Is.GreaterThanOrEqualTo(atPoints - 1e-6f), what + ": at least the points' penetration");
                    }
                }
        }

        [Test]
        public void ClosingDoesNotDependOnTheRigsLocalAxes()
        {
            HumanoidMap a = MixamoHand();
            HumanoidMap b = WithTwistedLocalAxes(a, 3);
            foreach (ControllerProfile profile in Profiles())
                foreach (bool left in new[] { true, false })
                {
                    var ha = new HandModel(a, left ? BodySide.Left : BodySide.Right);
                    var hb = new HandModel(b, left ? BodySide.Left : BodySide.Right);
                    var sa = new FingerSolver(ha, profile);
                    var sb = new FingerSolver(hb, profile);
                    var hand = new RigidPose(new Vector3(0.2f, 1.1f, 0.3f), Rotations.AngleAxis(40f, new Vector3(0.3f, 1, 0.2f)));
                    sa.Solve(hand, hand * ha.ControllerInHand(profile), GripMode.Hold);
                    sb.Solve(hand, hand * hb.ControllerInHand(profile), GripMode.Hold);
                    float[] ta = sa.Parameters.ToArray(), tb = sb.Parameters.ToArray();
                    for (int i = 0; i < FingerParameters.Count; i++)
                        Assert.That(tb[i], Is.EqualTo(ta[i]).Within(0.01f), $"{profile.Name} {(left ? "left" : "right")} parameter {i}");
                    Assert.That(sa.Parameters[Finger.Index, Phalanx.Intermediate], Is.GreaterThan(0.3f), "the index closes");
                }
        }

        [Test]
        public void OpenModeAndAnOutOfReachControllerGiveTheOpenPoseAtOnce()
        {
            HumanoidMap map = MixamoHand();
            foreach (ControllerProfile profile in Profiles())
            {
                var hand = new HandModel(map, BodySide.Right);
                var solver = new FingerSolver(hand, profile);
                RigidPose h = RigidPose.Identity;
                solver.Solve(h, h * hand.ControllerInHand(profile), GripMode.Hold);
                Assert.That(solver.Parameters[Finger.Index, Phalanx.Intermediate], Is.GreaterThan(0.3f));
                solver.Solve(h, h * hand.ControllerInHand(profile), GripMode.Open);
                Assert.That(solver.Parameters.ToArray(), Is.All.EqualTo(0f));
                solver.Solve(h, h * hand.ControllerInHand(profile), GripMode.Hold);
                var away = new RigidPose(new Vector3(0, 0, 0.5f), Quaternion.Identity) * (h * hand.ControllerInHand(profile));
                for (int frame = 0; frame < 3; frame++)
                {
                    solver.Solve(h, away, GripMode.Hold);
                    Assert.That(solver.OutOfReach, Is.True);
                    Assert.That(solver.Parameters.ToArray(), Is.All.EqualTo(0f), "open, and staying open");
                }
            }
        }

        [Test]
        public void TheSameControllerPoseGivesTheSameGripAt72_90And144Hz()
        {
            HumanoidMap map = MixamoHand();
            foreach (ControllerProfile profile in Profiles())
            {
                var hand = new HandModel(map, BodySide.Left);
                RigidPose inHand = hand.ControllerInHand(profile);
                var final = new float[3][];
                int[] rates = { 72, 90, 144 };
                for (int r = 0; r < rates.Length; r++)
                {
                    var solver = new FingerSolver(hand, profile);
                    int frames = rates[r] * 2; // two seconds of a wobbling controller
                    for (int i = 0; i <= frames; i++)
                    {
                        float t = i / (float)rates[r];
                        var wobble = new RigidPose(new Vector3(0.002f * MathF.Sin(5 * t), 0.002f * MathF.Cos(3 * t), 0), Rotations.AngleAxis(3f * MathF.Sin(4 * t), Vector3.UnitY));
                        solver.Solve(RigidPose.Identity, inHand * wobble, GripMode.Hold);
                    }
                    final[r] = solver.Parameters.ToArray();
                }
                for (int i = 0; i < FingerParameters.Count; i++)
                {
                    Assert.That(Math.Abs(final[0][i] - final[2][i]), Is.LessThanOrEqualTo(0.02f), $"{profile.Name} parameter {i}, 72 vs 144 Hz");
                    Assert.That(Math.Abs(final[1][i] - final[2][i]), Is.LessThanOrEqualTo(0.02f), $"{profile.Name} parameter {i}, 90 vs 144 Hz");
                }
            }
        }

        [Test]
        public void InvalidPosesKeepTheLastGrip()
        {
            var hand = new HandModel(MixamoHand(), BodySide.Right);
            foreach (ControllerProfile profile in Profiles())
            {
                var solver = new FingerSolver(hand, profile);
                solver.Solve(RigidPose.Identity, hand.ControllerInHand(profile), GripMode.Hold);
                float index = solver.Parameters[Finger.Index, Phalanx.Intermediate];
                solver.Solve(new RigidPose(new Vector3(float.NaN, 0, 0), Quaternion.Identity), hand.ControllerInHand(profile), GripMode.Hold);
                Assert.That(solver.Parameters[Finger.Index, Phalanx.Intermediate], Is.EqualTo(index));
                Assert.That(float.IsNaN(solver.Parameters[Finger.Index, Phalanx.Intermediate]), Is.False);
            }
        }

        /// <summary>
        /// A grip released part or all of the way (InputDriven below 1, the Unity component's default mode) keeps every finger
        /// out of the controller, on the Mixamo hand in its T-pose and the reference hands of three sizes, every profile, both
        /// hands (found in review: the open hand's thumb lay 4.2–4.7 mm inside the Mixamo hand's controller, the reference
        /// hands' 11–24 mm at grip 0); a finger outside at its share of the grip keeps that share.
        /// </summary>
        [Test]
        public void AGripReleasedPartOfTheWayStaysOutOfTheController()
        {
            float worst = 0f;
            string where = "";
            foreach (string rig in new[] { "mixamo", "reference", "small", "large" })
                foreach (ControllerProfile profile in Profiles())
                    foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                    {
                        HumanoidMap map = rig == "mixamo" ? MixamoHand() : ReferenceHandRig.Build(rig == "small" ? 0.85f : rig == "large" ? 1.15f : 1f);
                        var pose = new SkeletonPose(map.Skeleton); // the open hand: the T-pose's (the pipeline's), the reference hands' rest
                        if (rig == "mixamo") TPoser.Apply(map, pose, RigidPose.Identity); else pose.ResetToRest();
                        var model = new HandModel(map, side, pose);
                        var solver = new FingerSolver(model, profile);
                        RigidPose held = model.ControllerInHand(profile);
                        solver.Solve(RigidPose.Identity, held, GripMode.Hold);
                        float[] hold = solver.Parameters.ToArray();
                        for (int gi = 0; gi <= 20; gi++)
                        {
                            float g = gi / 20f;
                            solver.Solve(RigidPose.Identity, held, GripMode.InputDriven, g, g);
                            for (Finger f = Finger.Thumb; f <= Finger.Little; f++)
                            {
                                if (!model.Has(f)) continue;
                                for (FingerPoint q = FingerPoint.IntermediateJoint; q <= FingerPoint.Tip; q++)
                                {
                                    float d = solver.SurfaceGap(f, q);
                                    if (-d > worst) { worst = -d; where = $"{rig} {profile.Name} {side} grip {g:F2} {f} {q}: {d * 1000:F2} mm"; }
                                }
                                // Never more closed than the grip asks unless the controller is in the way, never past the hold.
                                float share = solver.Parameters[f, Phalanx.Intermediate], full = hold[(int)f * 3 + 1];
                                Assert.That(share, Is.InRange(Math.Min(g * full, full) - 1e-6f, Math.Max(g * full, full) + 1e-6f), $"{rig} {profile.Name} {side} grip {g} {f}");
                            }
                        }
                    }
            Assert.That(worst, Is.LessThanOrEqualTo(1e-4f), "the deepest finger point (m): " + where);
        }

        [Test]
        public void PointingAndInputDrivenGrips()
        {
            var hand = new HandModel(MixamoHand(), BodySide.Right);
            foreach (ControllerProfile profile in Profiles())
            {
                var solver = new FingerSolver(hand, profile);
                RigidPose c = hand.ControllerInHand(profile);
                solver.Solve(RigidPose.Identity, c, GripMode.Hold);
                float[] hold = solver.Parameters.ToArray();
                solver.Solve(RigidPose.Identity, c, GripMode.Point);
                Assert.That(solver.Parameters[Finger.Index, Phalanx.Proximal] + solver.Parameters[Finger.Index, Phalanx.Intermediate] + solver.Parameters[Finger.Index, Phalanx.Distal], Is.EqualTo(0f), profile.Name + ": index extended");
                Assert.That(solver.Parameters[Finger.Middle, Phalanx.Intermediate], Is.EqualTo(hold[7]).Within(1e-6f), profile.Name + ": middle still holds");
                solver.Solve(RigidPose.Identity, c, GripMode.InputDriven, trigger: 1f, grip: 0.5f);
                Assert.That(solver.Parameters[Finger.Index, Phalanx.Intermediate], Is.EqualTo(hold[4]).Within(1e-6f), profile.Name + ": full trigger = index on the trigger");
                Assert.That(solver.Parameters[Finger.Middle, Phalanx.Intermediate], Is.EqualTo(0.5f * hold[7]).Within(1e-6f), profile.Name + ": half grip = half closed");
                solver.Solve(RigidPose.Identity, c, GripMode.InputDriven, trigger: 0f, grip: 1f);
                Assert.That(solver.Parameters[Finger.Index, Phalanx.Intermediate], Is.EqualTo(0f), profile.Name + ": released trigger = index pointing");
            }
        }
    }
}
