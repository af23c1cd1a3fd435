using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// What the calibrator writes to a Unity avatar's bones for fitted proportions (<see cref="ProportionedBones"/>), on a
    /// stand-in for the engine's hierarchy: the avatar's bind local positions, the root scaled by the calibration's avatar
    /// scale, and the solved local rotations written as a driver writes them. Through the pipeline on recorded motion with
    /// an avatar whose legs are 10 % longer and arms 10 % shorter than the wearer's, against the wearer's true joints.
    /// </summary>
    public class ProportionedBonesTests
    {
        private static readonly HumanoidBone[] Ends = { HumanoidBone.LeftFoot, HumanoidBone.RightFoot, HumanoidBone.LeftHand, HumanoidBone.RightHand };

        // Forward kinematics of the engine stand-in: the root where the pipeline put it, every other joint its transform's
        // local position (the managed ones from the bones, else the bind's) times the root's scale, and its solved rotation.
        internal static void EngineWorld(HumanoidMap avatar, SkeletonPose solved, ProportionedBones bones, bool applied, float rootScale, RigidPose[] world)
        {
            Skeleton s = avatar.Skeleton;
            var position = new Vector3[s.JointCount];
            for (int j = 0; j < position.Length; j++) position[j] = s.GetRestLocal(j).Position;
            if (applied) for (int i = 0; i < bones.Count; i++) position[bones.Joint(i)] = bones.LocalPosition(i);
            world[0] = solved.World[0];
            for (int j = 1; j < position.Length; j++)
                world[j] = world[s.GetParent(j)] * new RigidPose(position[j] * rootScale, solved.Local[j].Rotation);
        }

        [Test]
        public void FittedBonesPutTheEndsWhereTheSolverAndTheWearerHaveThem()
        {
            string session = ProportionFitTests.Simulate(BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true }), 1);
            using var reader = new SessionReader(new StringReader(session), "bones");
            HumanoidMap avatar = Proportions.ScaleLimbs(reader.Header.TruthHumanoid, 1.1f, 0.9f);
            var settings = new PipelineSettings();
            settings.Calibration.Proportions.Mode = ScaleMode.Fitted;
            var pipeline = new SelfAvatarPipeline(reader.Header.Devices, avatar, settings);
            var bind = new Vector3[avatar.Skeleton.JointCount];
            for (int j = 0; j < bind.Length; j++) bind[j] = avatar.Skeleton.GetRestLocal(j).Position;
            var bones = new ProportionedBones(avatar, bind);
            Assert.That(bones.Count, Is.EqualTo(8), "both knees, ankles, elbows and wrists");

            var frame = reader.CreateFrame();
            var world = new RigidPose[avatar.Skeleton.JointCount];
            var toSolver = new List<double>();
            var fittedToTruth = new List<double>[4];
            var bindToTruth = new List<double>[4];
            for (int e = 0; e < 4; e++) { fittedToTruth[e] = new List<double>(); bindToTruth[e] = new List<double>(); }
            bool wasShown = false;
            int frames = 0;
            while (reader.ReadFrame(frame) && frames < 600)
            {
                pipeline.Update(frame);
                if (pipeline.Profile == null) { Assert.That(bones.Update(pipeline.Profile, true), Is.False, "no calibration: bind pose"); continue; }
                bool changed = bones.Update(pipeline.Profile, true);
                if (!wasShown) Assert.That(changed, Is.True, "the fitted avatar's bones change when it is first shown (T-pose press)");
                else if (!changed) Assert.That(bones.Applied, Is.EqualTo(pipeline.Profile.Proportions));
                wasShown = true;
                if (pipeline.State != CalibrationState.Calibrated) continue;
                frames++;
                SkeletonPose solved = pipeline.Pose;
                float scale = pipeline.Profile.AvatarScale;
                EngineWorld(avatar, solved, bones, true, scale, world);
                for (int j = 0; j < world.Length; j++) toSolver.Add(Vector3.Distance(world[j].Position, solved.World[j].Position) * 1000);
                for (int e = 0; e < 4; e++)
                    if (frame.HasTruth[(int)Ends[e]]) fittedToTruth[e].Add(Vector3.Distance(world[avatar[Ends[e]]].Position, frame.Truth[(int)Ends[e]].Position) * 1000);
                EngineWorld(avatar, solved, bones, false, scale, world);
                for (int e = 0; e < 4; e++)
                    if (frame.HasTruth[(int)Ends[e]]) bindToTruth[e].Add(Vector3.Distance(world[avatar[Ends[e]]].Position, frame.Truth[(int)Ends[e]].Position) * 1000);
            }
            Assert.That(frames, Is.GreaterThan(300), "solved frames");
            BodyProportions p = pipeline.Profile.Proportions;
            Assert.That(p.LeftLeg, Is.LessThan(0.95f), $"the legs were fitted shorter ({p})");
            Assert.That(p.LeftArm, Is.GreaterThan(1.05f), $"the arms were fitted longer ({p})");
            toSolver.Sort();
            TestContext.WriteLine($"engine stand-in vs solver: max {toSolver[^1]:0.000} mm over {frames} frames");
            Assert.That(toSolver[^1], Is.LessThan(0.05), "every joint of the engine avatar is where the solver has it (mm)");
            for (int e = 0; e < 4; e++)
            {
                fittedToTruth[e].Sort();
                bindToTruth[e].Sort();
                double fitted = fittedToTruth[e][fittedToTruth[e].Count / 2], unfitted = bindToTruth[e][bindToTruth[e].Count / 2];
                TestContext.WriteLine($"{Ends[e]}: median to the true joint {fitted:0.0} mm with the fitted bones, {unfitted:0.0} mm with the bind ones");
                Assert.That(fitted, Is.LessThan(10.0), $"{Ends[e]}: with the fitted bones, within a few mm of the wearer's joint (median mm)");
                Assert.That(unfitted, Is.GreaterThan(fitted + 20.0), $"{Ends[e]}: the bind bones (unfitted) miss it by centimetres (median mm)");
            }
        }

        private static void Cycle(ProportionedBones bones, CalibrationProfile fitted, int rounds)
        {
            for (int r = 0; r < rounds; r++)
            {
                bones.Update(fitted, true);
                bones.Update(fitted, true);
                bones.Update(fitted, false);
                bones.Update(null, true);
                bones.Restore();
            }
        }

        [Test]
        public void ResetDisableAndUniformGiveTheBindPositionsBack()
        {
            HumanoidMap avatar = new SessionSimulator(RestConventionTests.Read(TestData.Mocap("mixamo_fingers_30fps.bvh")), new SimulationOptions { Seed = 1 }).CreateHeader().TruthHumanoid;
            var bind = new Vector3[avatar.Skeleton.JointCount];
            for (int j = 0; j < bind.Length; j++) bind[j] = avatar.Skeleton.GetRestLocal(j).Position * 100f; // engine units (cm), not the core's
            var bones = new ProportionedBones(avatar, bind);
            var fitted = new CalibrationProfile { Proportions = new BodyProportions(0.9f, 0.92f, 1.1f, 1.08f), AvatarScale = 1.2f };
            var uniform = new CalibrationProfile { AvatarScale = 1.2f };

            Assert.That(bones.Update(uniform, true), Is.False, "a uniform calibration keeps the bind positions");
            Assert.That(bones.Update(fitted, true), Is.True);
            for (int i = 0; i < bones.Count; i++)
            {
                int j = bones.Joint(i);
                HumanoidBone bone = avatar.BoneOf(j);
                float expected = bone == HumanoidBone.LeftLowerLeg || bone == HumanoidBone.LeftFoot ? 0.9f
                    : bone == HumanoidBone.RightLowerLeg || bone == HumanoidBone.RightFoot ? 0.92f
                    : bone == HumanoidBone.LeftLowerArm || bone == HumanoidBone.LeftHand ? 1.1f : 1.08f;
                Assert.That(Vector3.Distance(bones.LocalPosition(i), bind[j] * expected), Is.LessThan(1e-4f), $"{bone}: bind position times its limb's ratio");
            }
            Assert.That(bones.Update(fitted, true), Is.False, "unchanged: nothing to copy");

            bool disabled = bones.Update(fitted, false);
            bool again = bones.Update(fitted, true);
            bool reset = bones.Update(null, true);
            Assert.That(disabled && again && reset, Is.True, "disabling, enabling and resetting each change the positions");
            for (int i = 0; i < bones.Count; i++) Assert.That(bones.LocalPosition(i), Is.EqualTo(bind[bones.Joint(i)]), "reset: exactly the bind positions");
            Assert.That(bones.Update(fitted, true) && bones.Restore(), Is.True);
            for (int i = 0; i < bones.Count; i++) Assert.That(bones.LocalPosition(i), Is.EqualTo(bind[bones.Joint(i)]), "restored: exactly the bind positions");

            // Changes and unchanged frames allocate nothing (measured after a warm-up, as the other allocation tests do).
            var bytes = new long[3];
            Cycle(bones, fitted, 100);
            for (int k = 0; k < bytes.Length; k++)
            {
                long t0 = GC.GetAllocatedBytesForCurrentThread();
                Cycle(bones, fitted, 1000);
                bytes[k] = GC.GetAllocatedBytesForCurrentThread() - t0;
            }
            Assert.That(bytes, Is.EqualTo(new long[bytes.Length]), "bytes allocated by 1000 rounds of changes and unchanged frames");
            Assert.That(bones.Update(new CalibrationProfile { Proportions = new BodyProportions(float.NaN, 1f, 1f, 1f) }, true), Is.False, "invalid proportions: the bind pose stays");
        }
    }
}
