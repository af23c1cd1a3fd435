using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The knee and elbow hints of <see cref="BodyTargetMapper"/> as <see cref="FullBodyIk"/> solves them frame after frame:
    /// a wrist or ankle target swept a millimetre a frame past a direction where one of a hint's terms vanishes must not
    /// turn the limb round in one frame. A calibrated mocap wearer stands in the T-pose while one hand's or foot's device
    /// moves; the true elbow or knee sits at a chosen swivel about the limb's axis, and the hand lies along the forearm
    /// (the foot turns with the shin).
    /// </summary>
    public class LimbHintContinuityTests
    {
        private sealed class Body
        {
            public readonly Wearer Wearer = new Wearer("mocapbank_30fps.bvh", 31);
            public readonly CalibrationProfile Profile;
            public readonly HumanoidMap Avatar;
            public readonly SkeletonPose CalibrationPose;
            public readonly BodyTargetMapper Mapper;
            public readonly FullBodyIk Ik;
            public readonly SkeletonPose Pose;
            public readonly DeviceSample[] Standing = new DeviceSample[6], Samples = new DeviceSample[6];
            public BodyTargets Targets;

            public Body(KneeHintModel knees)
            {
                var calibrator = new Calibrator(Wearer.Devices, Wearer.Map);
                Wearer.StandInTPose(new RigidPose(new Vector3(-1, 0, 0.5f), Rotations.AngleAxis(130f, Vector3.UnitY)));
                double t = 0;
                Wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
                Wearer.StandInTPose(calibrator.Profile.Placement);
                Wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
                Assume.That(calibrator.State, Is.EqualTo(CalibrationState.Calibrated), calibrator.LastStep.Message);
                Profile = calibrator.Profile;
                Avatar = calibrator.ScaledAvatar;
                CalibrationPose = calibrator.AvatarPose;
                Mapper = new BodyTargetMapper(Profile, Wearer.Devices, Avatar, CalibrationPose, knees, ElbowHintModel.HandAxis);
                // The hints alone: the straight limbs' filters would carry each sweep's opening jump (from wherever the last
                // sweep left the limb) into the frames after it (AStraightLegDoesNotShiverWithTheDevicesNoise and
                // StraightArmTests test them).
                Ik = new FullBodyIk(Avatar, CalibrationPose) { StraightLegCutoffHz = 0f, StraightArmCutoffHz = 0f };
                Pose = new SkeletonPose(Avatar.Skeleton);
                Pose.CopyFrom(CalibrationPose);
                Wearer.Sample(Standing, 0f, 0f); // still standing in the T-pose of the walk-in
            }

            public Vector3 At(HumanoidBone bone) => CalibrationPose.World[Avatar[bone]].Position;

            /// <summary>One frame: the others' devices where they stood, this role's device where its joint's goal puts it.</summary>
            public void Solve(DeviceRole role, RigidPose goal)
            {
                Array.Copy(Standing, Samples, Samples.Length);
                for (int i = 0; i < Samples.Length; i++)
                    if (Wearer.Devices[i].Id == Profile.DeviceId(role))
                        Samples[i] = new DeviceSample(goal * Profile.JointInDevice(role).Inverse(), true);
                Mapper.Compute(Samples, ref Targets);
                Ik.Solve(in Targets, Pose, 1f / 90f);
            }
        }

        private static Vector3 Turned(Vector3 v, Vector3 axis, float degrees) => Vector3.Transform(v, Rotations.AngleAxis(degrees, axis));

        /// <summary>
        /// Sweeps the limb's axis (root to end) across <paramref name="singular"/> (16°, the end a millimetre a frame; up and
        /// down through it, or to and fro with <paramref name="sideways"/>), passing <paramref name="missDegrees"/> beside it, the middle joint bent by <paramref name="flexionDegrees"/> at
        /// <paramref name="swivelDegrees"/> about the axis; the end joint's direction (the hand's toward the knuckles, the
        /// foot's sole) follows the lower bone, the hand's turned <paramref name="wristDegrees"/> off it. Returns the largest
        /// frame-to-frame turn of the root bone (degrees) and move of the middle joint (mm).
        /// </summary>
        private static (float rootDegrees, float middleMm) Sweep(Body body, bool arm, BodySide side, Vector3 singular,
            bool sideways, float missDegrees, float flexionDegrees, float swivelDegrees, float wristDegrees = 0f)
        {
            HumanoidBone root = HumanoidBones.OnSide(arm ? HumanoidBone.LeftUpperArm : HumanoidBone.LeftUpperLeg, side);
            HumanoidBone middle = HumanoidBones.OnSide(arm ? HumanoidBone.LeftLowerArm : HumanoidBone.LeftLowerLeg, side);
            HumanoidBone end = HumanoidBones.OnSide(arm ? HumanoidBone.LeftHand : HumanoidBone.LeftFoot, side);
            DeviceRole role = arm ? BodyRoles.Hand(side) : BodyRoles.Foot(side);
            Vector3 origin = body.At(root);
            float upper = Vector3.Distance(origin, body.At(middle)), lower = Vector3.Distance(body.At(middle), body.At(end));
            float interior = (180f - flexionDegrees) * MathF.PI / 180f;
            float reach = MathF.Sqrt(upper * upper + lower * lower - 2f * upper * lower * MathF.Cos(interior));
            float atRoot = MathF.Acos((upper * upper + reach * reach - lower * lower) / (2f * upper * reach));
            Quaternion endRotation0 = body.CalibrationPose.World[body.Avatar[end]].Rotation;
            // The T-pose's hand toward its knuckles (the forearm without them), foot along the shin.
            int knuckles = arm ? TPoser.HandLandmark(body.Avatar, side) : -1;
            Vector3 endDirection0 = Vector3.Normalize(knuckles >= 0 ? body.CalibrationPose.World[knuckles].Position - body.At(end) : body.At(end) - body.At(middle));
            Vector3 across = Vector3.Normalize(Vector3.Cross(singular, Math.Abs(singular.Y) < 0.9f ? Vector3.UnitY : Vector3.UnitX));
            Vector3 beside = Vector3.Cross(singular, across);
            if (sideways) (across, beside) = (beside, -across);
            int rootJoint = body.Avatar[root], middleJoint = body.Avatar[middle];
            float step = 0.001f / reach * 180f / MathF.PI;
            float rootDegrees = 0f, middleMm = 0f;
            Quaternion lastRoot = default;
            Vector3 lastMiddle = default;
            for (int frame = 0; frame * step <= 16f; frame++)
            {
                Vector3 axis = Vector3.Normalize(Turned(Turned(singular, across, frame * step - 8f), beside, missDegrees));
                Vector3 swivel = Vector3.Normalize(Vectors.ProjectOnPlane(Turned(beside, singular, swivelDegrees), axis));
                Vector3 goal = origin + axis * reach;
                Vector3 knee = origin + upper * (MathF.Cos(atRoot) * axis + MathF.Sin(atRoot) * swivel);
                Vector3 bone = Vector3.Normalize(goal - knee);
                if (arm) bone = Turned(bone, Vector3.Normalize(Vector3.Cross(bone, across)), wristDegrees);
                body.Solve(role, new RigidPose(goal, Rotations.FromTo(endDirection0, bone) * endRotation0));
                RigidPose[] w = body.Pose.World;
                Assert.That(Vector3.Distance(w[body.Avatar[end]].Position, goal), Is.LessThan(TwoBoneIk.ReachedTolerance), "the end reaches its goal");
                if (frame > 0) // the first frame comes from wherever the last sweep left the limb
                {
                    rootDegrees = Math.Max(rootDegrees, Rotations.AngleDegrees(lastRoot, w[rootJoint].Rotation));
                    middleMm = Math.Max(middleMm, 1000f * Vector3.Distance(lastMiddle, w[middleJoint].Position));
                }
                lastRoot = w[rootJoint].Rotation;
                lastMiddle = w[middleJoint].Position;
            }
            return (rootDegrees, middleMm);
        }

        /// <summary>
        /// The elbow's fallback (down, out and back from the torso) was normalised after its part square to the arm's axis
        /// was taken, so it turned round in the frame the arm passed through that direction (55° down, out and back), and a
        /// hand that weighed no more (a 30° bent elbow with the hand along the forearm, or a nearly straight one with the
        /// wrist a few degrees off it) turned the elbow with it: up to 127° and 111 mm in a frame where the wrist moved 1 mm,
        /// and still 50° at 2° beside it. A straight arm with the hand exactly along it stays singular there (neither term
        /// says anything: Documentation~/solver.md).
        /// </summary>
        [Test]
        public void AnElbowDoesNotTurnRoundWhereTheArmPointsDownOutAndBack()
        {
            var body = new Body(KneeHintModel.OuterOfPelvisAndFoot);
            Vector3 right = Vector3.Normalize(body.At(HumanoidBone.RightUpperLeg) - body.At(HumanoidBone.LeftUpperLeg));
            Vector3 up = Vector3.Normalize(body.At(HumanoidBone.Head) - body.At(HumanoidBone.Hips));
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Vector3 outward = side == BodySide.Left ? -right : right;
                Vector3 facing = Vector3.Transform(Vectors.Forward, body.Profile.Placement.Rotation); // the T-pose's forward
                Vector3 downOutBack = Vector3.Normalize(outward - up - Vector3.Normalize(Vectors.ProjectOnPlane(facing, up)));
                foreach (bool sideways in new[] { false, true })
                    foreach (float miss in new[] { 0f, 0.5f, 2f })
                        foreach (float swivel in new[] { 0f, 90f, 180f, 270f })
                        {
                            string what = $"{side} arm, {miss}° beside down-out-back (to and fro: {sideways}), the elbow at swivel {swivel}°";
                            (float turn, float move) = Sweep(body, true, side, downOutBack, sideways, miss, 30f, swivel);
                            Assert.That(turn, Is.LessThan(1f), what + ", bent 30°: the upper arm's largest turn in a frame (deg)");
                            Assert.That(move, Is.LessThan(1f), what + ", bent 30°: the elbow's largest move in a frame (mm)");
                            (turn, _) = Sweep(body, true, side, downOutBack, sideways, miss, 2f, swivel, wristDegrees: 6f);
                            Assert.That(turn, Is.LessThan(2f), what + ", bent 2°, the wrist 6° off the forearm: the upper arm's largest turn in a frame (deg)");
                        }
            }
        }

        /// <summary>
        /// The toes' knee model had the same normalised fallback (the pelvis's flexion plane), which turned round where the
        /// leg passes through the hip line (a leg out sideways, the foot turned with it): a 30° bent knee by up to 29° and
        /// 56 mm in a frame where the ankle moved 1 mm. The pelvis's and the foot's planes, added or the outer one weighted most
        /// (the default), have no zero there (the foot's lateral axis turns with the leg), which this also keeps.
        /// </summary>
        [TestCase(KneeHintModel.Toes)]
        [TestCase(KneeHintModel.PelvisAndFoot)]
        [TestCase(KneeHintModel.OuterOfPelvisAndFoot)]
        public void AKneeDoesNotTurnRoundWhereTheLegLiesAlongTheHipLine(KneeHintModel knees)
        {
            var body = new Body(knees);
            Vector3 right = Vector3.Normalize(body.At(HumanoidBone.RightUpperLeg) - body.At(HumanoidBone.LeftUpperLeg));
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                foreach (bool sideways in new[] { false, true })
                    foreach (float miss in new[] { 0f, 0.5f, 2f })
                        foreach (float flexion in new[] { 2f, 30f })
                        {
                            (float turn, float move) = Sweep(body, false, side, side == BodySide.Left ? -right : right, sideways, miss, flexion, 0f);
                            string what = $"{knees}, {side} leg out sideways, knee bent {flexion}°, {miss}° beside the hip line (to and fro: {sideways})";
                            Assert.That(turn, Is.LessThan(2f), what + ": the thigh's largest turn in a frame (deg)");
                            Assert.That(move, Is.LessThan(2f), what + ": the knee's largest move in a frame (mm)");
                        }
        }
    }
}
