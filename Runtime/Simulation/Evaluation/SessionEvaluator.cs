using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Replays a synthetic session through the <see cref="SelfAvatarPipeline"/> (calibration, body solve, hands and fingers)
    /// and compares the avatar with the ground truth on every frame after calibration: positions per joint and group,
    /// end-effector rotations, knee angles, and the fingers on the controllers. The avatar is the wearer's own skeleton
    /// from the session header unless another is given.
    /// </summary>
    public static class SessionEvaluator
    {
        /// <summary>
        /// The share of its length (shoulder to elbow plus elbow to wrist) beyond which the wearer's arm counts as fully
        /// stretched (0.98: the elbow within about 23° of straight), for <see cref="EvaluationReport.UnreachedWhileBentFrames"/>.
        /// </summary>
        public const double StretchedArm = 0.98;

        /// <summary>Evaluates one offset mode, without finger IK (see the other overload for settings).</summary>
        public static EvaluationReport Evaluate(SessionReader reader, OffsetMode mode, HumanoidMap avatar = null) =>
            Evaluate(reader, new PipelineSettings { Offsets = mode }, avatar);

        /// <summary>Evaluates the session read by <paramref name="reader"/> (consumed to its end) with these pipeline settings.</summary>
        /// <param name="reader">A session with ground truth.</param>
        /// <param name="settings">Offset mode, controllers and grip of each hand, calibration thresholds.</param>
        /// <param name="avatar">The avatar; null uses the wearer's skeleton from the header.</param>
        /// <param name="onFrame">Optional: called after each solved frame after calibration (to write the pose out, for example).</param>
        /// <param name="disturbance">Optional: losses, noise and teleports injected into every frame after calibration.</param>
        /// <exception cref="ArgumentException">The session has no ground truth and no avatar is given.</exception>
        public static EvaluationReport Evaluate(SessionReader reader, PipelineSettings settings, HumanoidMap avatar = null, Action<SelfAvatarPipeline> onFrame = null,
            DisturbanceOptions disturbance = null) =>
            Run(reader, settings, avatar, onFrame == null ? null : new Action<SelfAvatarPipeline, SessionFrame>((pipeline, frame) => onFrame(pipeline)), disturbance);

        /// <summary>
        /// As <see cref="Evaluate(SessionReader, PipelineSettings, HumanoidMap, Action{SelfAvatarPipeline}, DisturbanceOptions)"/>, with
        /// <paramref name="onFrame"/> also given the session frame (its ground truth) of each solved frame after calibration:
        /// to write the solved and true joints out, for example.
        /// </summary>
        public static EvaluationReport EvaluateWithTruth(SessionReader reader, PipelineSettings settings, HumanoidMap avatar,
            Action<SelfAvatarPipeline, SessionFrame> onFrame, DisturbanceOptions disturbance = null) => Run(reader, settings, avatar, onFrame, disturbance);

        /// <summary>
        /// Evaluates a session with the refinement exercise (<see cref="SimulationOptions.ExerciseSeconds"/>): the
        /// <paramref name="exerciseSeconds"/> after calibration are not scored; with <paramref name="refine"/> they are fed to
        /// the pipeline's refinement (<see cref="SelfAvatarPipeline.BeginRefinement"/>, <see cref="SelfAvatarPipeline.EndRefinement"/>
        /// at their end, <see cref="EvaluationReport.Refinement"/>), without it the calibrated avatar stays. Either way the
        /// same frames are scored, so the two compare.
        /// </summary>
        public static EvaluationReport EvaluateExercise(SessionReader reader, PipelineSettings settings, HumanoidMap avatar, float exerciseSeconds, bool refine) =>
            Run(reader, settings, avatar, null, null, exerciseSeconds, refine);

        private static EvaluationReport Run(SessionReader reader, PipelineSettings settings, HumanoidMap avatar, Action<SelfAvatarPipeline, SessionFrame> onFrame,
            DisturbanceOptions disturbance, float exerciseSeconds = 0f, bool refine = false)
        {
            double exerciseEnd = double.NaN; // when the exercise ends (NaN: none)
            bool exerciseOver = false;
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            SessionHeader header = reader.Header;
            avatar = avatar ?? header.TruthHumanoid ?? throw new ArgumentException("The session has no ground-truth skeleton; give an avatar.", nameof(reader));
            var report = new EvaluationReport { Mode = settings.Offsets };
            var pipeline = new SelfAvatarPipeline(header.Devices, avatar, settings);
            SessionFrame frame = reader.CreateFrame();
            var truthAtCalibration = new RigidPose[HumanoidBones.Count];
            var avatarAtCalibration = new RigidPose[HumanoidBones.Count];
            var hasReference = new bool[HumanoidBones.Count]; // a bone's truth may be absent at calibration: its first frame with it
            bool calibrated = false;
            var lastAvatar = new Vector3[HumanoidBones.Count];
            var lastTruth = new Vector3[HumanoidBones.Count];
            var hasLast = new bool[HumanoidBones.Count]; // the bone was compared on the frame before (its move is measured)
            DisturbanceTracker disturbed = null;
            if (header.TruthHumanoid != null) report.TrueMeasurements = ProportionFitter.MeasureSkeleton(header.TruthHumanoid);
            var armLength = new double[2];
            if (header.TruthHumanoid != null)
                foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                    armLength[(int)side] = report.TrueMeasurements.ArmLength(side).Value;

            while (reader.ReadFrame(frame))
            {
                disturbed?.Disturb(frame);
                pipeline.Update(frame);
                if (pipeline.State != CalibrationState.Calibrated) continue;
                HumanoidMap scaled = pipeline.ScaledAvatar;
                if (!calibrated)
                {
                    // The frame that completed calibration: the references for the rotation errors.
                    calibrated = true;
                    report.Profile = pipeline.ActiveProfile;
                    report.AvatarMeasurements = ProportionFitter.MeasureSkeleton(scaled);
                    for (int b = 0; b < HumanoidBones.Count; b++)
                    {
                        hasReference[b] = frame.HasTruth[b] && scaled.Has((HumanoidBone)b);
                        if (!hasReference[b]) continue;
                        truthAtCalibration[b] = frame.Truth[b];
                        avatarAtCalibration[b] = pipeline.Pose.World[scaled[(HumanoidBone)b]];
                    }
                    if (pipeline.Hand(BodySide.Left).HasFingerIk || pipeline.Hand(BodySide.Right).HasFingerIk) report.Fingers = new FingerReport();
                    if (exerciseSeconds > 0f)
                    {
                        exerciseEnd = frame.Time + exerciseSeconds;
                        if (refine) pipeline.BeginRefinement();
                    }
                    if (disturbance != null && disturbance.IsActive)
                    {
                        report.Disturbance = new DisturbanceReport();
                        disturbed = new DisturbanceTracker(header, disturbance, pipeline, report.Disturbance);
                    }
                    continue;
                }
                if (frame.Time < exerciseEnd)
                {
                    report.ExerciseFrames++;
                    Array.Clear(hasLast, 0, hasLast.Length);
                    continue;
                }
                if (!double.IsNaN(exerciseEnd) && !exerciseOver)
                {
                    // The first frame after the exercise, with or without refinement, so that the same frames are scored:
                    // refined, it was solved on the avatar before, and the next one is the refined avatar's.
                    exerciseOver = true;
                    if (pipeline.IsRefining)
                    {
                        report.Refinement = pipeline.EndRefinement();
                        scaled = pipeline.ScaledAvatar;
                        report.AvatarMeasurements = ProportionFitter.MeasureSkeleton(scaled);
                        report.Profile = pipeline.ActiveProfile;
                    }
                    Array.Clear(hasLast, 0, hasLast.Length);
                    continue;
                }
                SkeletonPose pose = pipeline.Pose;
                if (pipeline.LastSwapTime == frame.Time) report.RoleSwaps++;
                if (!pipeline.Hand(BodySide.Left).Reached || !pipeline.Hand(BodySide.Right).Reached) report.UnreachedHandFrames++;
                if (UnreachedWhileBent(pipeline, frame, armLength)) report.UnreachedWhileBentFrames++;
                onFrame?.Invoke(pipeline, frame);
                report.Frames++;
                for (int b = 0; b < HumanoidBones.Count; b++)
                {
                    var bone = (HumanoidBone)b;
                    if (!frame.HasTruth[b] || !scaled.Has(bone) || HumanoidBones.IsFinger(bone))
                    {
                        hasLast[b] = false;
                        continue;
                    }
                    RigidPose a = pose.World[scaled[bone]];
                    RigidPose t = frame.Truth[b];
                    if (hasLast[b])
                    {
                        if (!report.JointMoveBeyondWearerMm.TryGetValue(bone, out ErrorSeries moves)) report.JointMoveBeyondWearerMm[bone] = moves = new ErrorSeries();
                        moves.Add((Vector3.Distance(a.Position, lastAvatar[b]) - (double)Vector3.Distance(t.Position, lastTruth[b])) * 1000.0);
                    }
                    lastAvatar[b] = a.Position;
                    lastTruth[b] = t.Position;
                    hasLast[b] = true;
                    double mm = Vector3.Distance(a.Position, t.Position) * 1000.0;
                    if (!report.JointPositionMm.TryGetValue(bone, out ErrorSeries series)) report.JointPositionMm[bone] = series = new ErrorSeries();
                    series.Add(mm);
                    report.AllJointsMm.Add(mm);
                    if (HumanoidBones.IsEndEffector(bone))
                    {
                        report.EndEffectorMm.Add(mm);
                        if (!hasReference[b])
                        {
                            // No truth at calibration: the turns are measured from this frame on.
                            hasReference[b] = true;
                            truthAtCalibration[b] = t;
                            avatarAtCalibration[b] = a;
                        }
                        Quaternion avatarTurn = a.Rotation * Quaternion.Conjugate(avatarAtCalibration[b].Rotation);
                        Quaternion truthTurn = t.Rotation * Quaternion.Conjugate(truthAtCalibration[b].Rotation);
                        report.EndEffectorDegrees.Add(Rotations.AngleDegrees(avatarTurn, truthTurn));
                    }
                    if (HumanoidBones.IsMidJoint(bone)) report.MidJointMm.Add(mm);
                }
                foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
                {
                    HumanoidBone hip = HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side);
                    HumanoidBone knee = HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side);
                    HumanoidBone ankle = HumanoidBones.OnSide(HumanoidBone.LeftFoot, side);
                    if (!frame.HasTruth[(int)hip] || !frame.HasTruth[(int)knee] || !frame.HasTruth[(int)ankle]) continue;
                    double avatarAngle = KneeAngle(pose.World[scaled[hip]].Position, pose.World[scaled[knee]].Position, pose.World[scaled[ankle]].Position);
                    double truthAngle = KneeAngle(frame.Truth[(int)hip].Position, frame.Truth[(int)knee].Position, frame.Truth[(int)ankle].Position);
                    report.KneeAngleDegrees.Add(Math.Abs(avatarAngle - truthAngle));
                }
                MeasureBendPlanes(pose, scaled, frame, report);
                if (report.Fingers != null) MeasureFingers(pipeline, report.Fingers);
                disturbed?.Measure(frame);
            }
            if (!calibrated) report.CalibrationMessage = pipeline.LastCalibrationStep.Message;
            return report;
        }

        // A hand that cannot reach its controller while the wearer's arm on that side is not fully stretched.
        private static bool UnreachedWhileBent(SelfAvatarPipeline pipeline, SessionFrame frame, double[] armLength)
        {
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                if (pipeline.Hand(side).Reached || !(armLength[(int)side] > 0)) continue;
                int shoulder = (int)HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side), wrist = (int)HumanoidBones.OnSide(HumanoidBone.LeftHand, side);
                if (!frame.HasTruth[shoulder] || !frame.HasTruth[wrist]) continue;
                if (Vector3.Distance(frame.Truth[shoulder].Position, frame.Truth[wrist].Position) < StretchedArm * armLength[(int)side]) return true;
            }
            return false;
        }

        private static void MeasureFingers(SelfAvatarPipeline pipeline, FingerReport fingers)
        {
            bool any = false;
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HandState hand = pipeline.Hand(side);
                if (!hand.HasFingerIk) continue;
                any = true;
                if (!hand.Holding)
                {
                    fingers.OpenHandFrames++;
                    continue;
                }
                for (Finger f = Finger.Thumb; f <= Finger.Little; f++)
                {
                    float tip = hand.SurfaceGap(f, FingerPoint.Tip);
                    if (float.IsNaN(tip)) continue; // a finger the rig lacks
                    for (FingerPoint p = FingerPoint.IntermediateJoint; p <= FingerPoint.Tip; p++)
                        fingers.MaxPenetrationMm = Math.Max(fingers.MaxPenetrationMm, -hand.SurfaceGap(f, p) * 1000.0);
                    fingers.Gap(f).Add(Math.Abs(tip) * 1000.0); // a tip inside the surface is off it too
                }
            }
            if (any) fingers.Frames++;
        }

        // Per knee and elbow: the signed angle about the wearer's limb axis from the wearer's bend direction to the avatar's.
        private static void MeasureBendPlanes(SkeletonPose pose, HumanoidMap scaled, SessionFrame frame, EvaluationReport report)
        {
            foreach (BendPlaneReport limb in report.BendPlanes)
            {
                HumanoidBone middle = limb.Joint, root = HumanoidBones.Parent(middle), end = LimbEnd(middle);
                if (!frame.HasTruth[(int)root] || !frame.HasTruth[(int)middle] || !frame.HasTruth[(int)end]) continue;
                Vector3 r = frame.Truth[(int)root].Position, m = frame.Truth[(int)middle].Position, e = frame.Truth[(int)end].Position;
                if (!BendPlaneReport.BendsEnough(r, m, e))
                {
                    limb.StraightFrames++;
                    continue;
                }
                Vector3 ar = pose.World[scaled[root]].Position, am = pose.World[scaled[middle]].Position, ae = pose.World[scaled[end]].Position;
                // A non-finite avatar is counted as such (InvalidCount), not as a wearer's straight limb: it was left out of
                // every figure under that name.
                limb.Add(Vectors.IsFinite(ar) && Vectors.IsFinite(am) && Vectors.IsFinite(ae)
                    ? BendPlaneReport.SignedAngleOfBentDegrees(r, m, e, ar, am, ae)
                    : double.NaN);
            }
        }

        /// <summary>The end joint of the limb whose middle joint is <paramref name="middle"/> (a knee's ankle, an elbow's wrist).</summary>
        public static HumanoidBone LimbEnd(HumanoidBone middle) => middle switch
        {
            HumanoidBone.LeftLowerLeg => HumanoidBone.LeftFoot,
            HumanoidBone.RightLowerLeg => HumanoidBone.RightFoot,
            HumanoidBone.LeftLowerArm => HumanoidBone.LeftHand,
            _ => HumanoidBone.RightHand,
        };

        private static double KneeAngle(Vector3 hip, Vector3 knee, Vector3 ankle) => Vectors.AngleDegrees(hip - knee, ankle - knee);
    }
}
