using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Replays a synthetic session through calibration, the body solver and the IK, and compares the avatar with
    /// the ground truth on every frame after calibration (positions per joint and group, end-effector rotations,
    /// knee angles). The avatar is the wearer's own skeleton from the session header unless another is given.
    /// </summary>
    public static class SessionEvaluator
    {
        private static readonly HumanoidBone[] EndEffectors =
            { HumanoidBone.Hips, HumanoidBone.Head, HumanoidBone.LeftHand, HumanoidBone.RightHand, HumanoidBone.LeftFoot, HumanoidBone.RightFoot };

        private static readonly HumanoidBone[] MidJoints =
            { HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm, HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg };

        /// <summary>Evaluates one offset mode over the session read by <paramref name="reader"/> (consumed to its end).</summary>
        /// <param name="reader">A session with ground truth.</param>
        /// <param name="mode">Exact offsets or the fixed baseline.</param>
        /// <param name="avatar">The avatar; null uses the wearer's skeleton from the header.</param>
        /// <param name="onFrame">Optional: called with each solved avatar pose after calibration (for writing it out).</param>
        /// <exception cref="ArgumentException">The session has no ground truth.</exception>
        public static EvaluationReport Evaluate(SessionReader reader, OffsetMode mode, HumanoidMap avatar = null, Action<SkeletonPose> onFrame = null)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            SessionHeader header = reader.Header;
            avatar = avatar ?? header.TruthHumanoid ?? throw new ArgumentException("The session has no ground-truth skeleton; give an avatar.", nameof(reader));
            var report = new EvaluationReport { Mode = mode };
            var calibrator = new Calibrator(header.Devices, avatar);
            SessionFrame frame = reader.CreateFrame();
            BodyTargetMapper solver = null;
            FullBodyIk ik = null;
            SkeletonPose pose = null;
            var targets = new BodyTargets();
            var truthAtCalibration = new RigidPose[HumanoidBones.Count];
            var avatarAtCalibration = new RigidPose[HumanoidBones.Count];
            HumanoidMap scaled = null;

            while (reader.ReadFrame(frame))
            {
                if (solver == null)
                {
                    calibrator.Update(frame.Time, frame.Samples, frame.Events);
                    if (calibrator.State != CalibrationState.Calibrated) continue;
                    CalibrationProfile profile = mode == OffsetMode.Exact ? calibrator.Profile : calibrator.Profile.WithFixedOffsets();
                    report.Profile = profile;
                    scaled = calibrator.ScaledAvatar;
                    solver = new BodyTargetMapper(profile, header.Devices, scaled, calibrator.AvatarPose);
                    ik = new FullBodyIk(scaled, calibrator.AvatarPose);
                    pose = new SkeletonPose(scaled.Skeleton);
                    pose.CopyFrom(calibrator.AvatarPose);
                    for (int b = 0; b < HumanoidBones.Count; b++)
                    {
                        truthAtCalibration[b] = frame.Truth[b];
                        if (scaled.Has((HumanoidBone)b)) avatarAtCalibration[b] = calibrator.AvatarPose.World[scaled[(HumanoidBone)b]];
                    }
                    continue;
                }

                solver.Compute(frame.Samples, ref targets);
                IkReport ikReport = ik.Solve(in targets, pose);
                if (!ikReport.LeftHand.Reached || !ikReport.RightHand.Reached) report.UnreachedHandFrames++;
                onFrame?.Invoke(pose);
                report.Frames++;
                for (int b = 0; b < HumanoidBones.Count; b++)
                {
                    var bone = (HumanoidBone)b;
                    if (!frame.HasTruth[b] || !scaled.Has(bone) || HumanoidBones.IsFinger(bone)) continue;
                    RigidPose a = pose.World[scaled[bone]];
                    RigidPose t = frame.Truth[b];
                    double mm = Vector3.Distance(a.Position, t.Position) * 1000.0;
                    if (!report.JointPositionMm.TryGetValue(bone, out ErrorSeries series)) report.JointPositionMm[bone] = series = new ErrorSeries();
                    series.Add(mm);
                    report.AllJointsMm.Add(mm);
                    if (Array.IndexOf(EndEffectors, bone) >= 0)
                    {
                        report.EndEffectorMm.Add(mm);
                        Quaternion avatarTurn = a.Rotation * Quaternion.Conjugate(avatarAtCalibration[b].Rotation);
                        Quaternion truthTurn = t.Rotation * Quaternion.Conjugate(truthAtCalibration[b].Rotation);
                        report.EndEffectorDegrees.Add(Rotations.AngleDegrees(avatarTurn, truthTurn));
                    }
                    if (Array.IndexOf(MidJoints, bone) >= 0) report.MidJointMm.Add(mm);
                }
                foreach (bool left in new[] { true, false })
                {
                    HumanoidBone hip = left ? HumanoidBone.LeftUpperLeg : HumanoidBone.RightUpperLeg;
                    HumanoidBone knee = left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg;
                    HumanoidBone ankle = left ? HumanoidBone.LeftFoot : HumanoidBone.RightFoot;
                    if (!frame.HasTruth[(int)hip] || !frame.HasTruth[(int)knee] || !frame.HasTruth[(int)ankle]) continue;
                    double avatarAngle = KneeAngle(pose.World[scaled[hip]].Position, pose.World[scaled[knee]].Position, pose.World[scaled[ankle]].Position);
                    double truthAngle = KneeAngle(frame.Truth[(int)hip].Position, frame.Truth[(int)knee].Position, frame.Truth[(int)ankle].Position);
                    report.KneeAngleDegrees.Add(Math.Abs(avatarAngle - truthAngle));
                }
            }
            if (solver == null) report.CalibrationMessage = calibrator.LastStep.Message;
            return report;
        }

        private static double KneeAngle(Vector3 hip, Vector3 knee, Vector3 ankle) => Vectors.AngleDegrees(hip - knee, ankle - knee);
    }
}
