using System;
using System.Collections.Generic;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>How closely the avatar followed the wearer over a session (<see cref="SessionEvaluator"/>).</summary>
    public sealed class EvaluationReport
    {
        /// <summary>The offset mode evaluated.</summary>
        public OffsetMode Mode { get; internal set; }

        /// <summary>Frames compared (every frame after calibration).</summary>
        public int Frames { get; internal set; }

        /// <summary>The calibration used, or null when calibration did not complete.</summary>
        public CalibrationProfile Profile { get; internal set; }

        /// <summary>Why calibration failed, when it did.</summary>
        public string CalibrationMessage { get; internal set; }

        /// <summary>Position error per humanoid joint but the finger bones (the fingers are in <see cref="Fingers"/>), in millimetres.</summary>
        public Dictionary<HumanoidBone, ErrorSeries> JointPositionMm { get; } = new Dictionary<HumanoidBone, ErrorSeries>();

        /// <summary>Position error of the end effectors (hips, head, hands, feet), in millimetres.</summary>
        public ErrorSeries EndEffectorMm { get; } = new ErrorSeries();

        /// <summary>Position error of the middle joints (elbows, knees), in millimetres.</summary>
        public ErrorSeries MidJointMm { get; } = new ErrorSeries();

        /// <summary>
        /// Position error over all compared joints (MPJPE samples), in millimetres: every humanoid joint the avatar and the
        /// truth share but the finger bones, which the fingertips' gaps to the controller measure instead (<see cref="Fingers"/>).
        /// </summary>
        public ErrorSeries AllJointsMm { get; } = new ErrorSeries();

        /// <summary>Rotation error of the end effectors (change since calibration, avatar vs wearer), in degrees.</summary>
        public ErrorSeries EndEffectorDegrees { get; } = new ErrorSeries();

        /// <summary>
        /// Per joint (not the fingers), how much further the avatar's joint moved from one compared frame to the next than the
        /// wearer's did (mm; negative where it moved less): its jitter and pops beyond the motion. Frames not compared (the
        /// refinement exercise) break the sequence.
        /// </summary>
        public Dictionary<HumanoidBone, ErrorSeries> JointMoveBeyondWearerMm { get; } = new Dictionary<HumanoidBone, ErrorSeries>();

        /// <summary>The move beyond the wearer's (<see cref="JointMoveBeyondWearerMm"/>) counted as a jump: 10 mm in one frame.</summary>
        public const double JumpMm = 10.0;

        /// <summary>
        /// The mean over the joints of their <see cref="JointMoveBeyondWearerMm"/> 95th percentile (mm): one figure for how
        /// steady the avatar is beyond the wearer's own motion; NaN before two compared frames.
        /// </summary>
        public double JitterMm
        {
            get
            {
                double sum = 0;
                int n = 0;
                foreach (ErrorSeries s in JointMoveBeyondWearerMm.Values)
                    if (s.Count > 0) { sum += s.P95; n++; }
                return n == 0 ? double.NaN : sum / n;
            }
        }

        /// <summary>Difference of the knee's interior angle, avatar vs wearer, in degrees.</summary>
        public ErrorSeries KneeAngleDegrees { get; } = new ErrorSeries();

        /// <summary>
        /// Per knee and elbow (LeftLowerLeg, RightLowerLeg, LeftLowerArm, RightLowerArm, in that order), the angle between
        /// the wearer's and the avatar's bend directions about the limb's axis: what sees a knee or elbow bent the wrong way.
        /// </summary>
        public BendPlaneReport[] BendPlanes { get; } =
        {
            new BendPlaneReport(HumanoidBone.LeftLowerLeg), new BendPlaneReport(HumanoidBone.RightLowerLeg),
            new BendPlaneReport(HumanoidBone.LeftLowerArm), new BendPlaneReport(HumanoidBone.RightLowerArm),
        };

        /// <summary>The bend-plane report of one knee or elbow (LeftLowerLeg, RightLowerLeg, LeftLowerArm, RightLowerArm), or null.</summary>
        public BendPlaneReport BendPlane(HumanoidBone joint) => Array.Find(BendPlanes, b => b.Joint == joint);

        /// <summary>Frames in which a hand could not reach its controller.</summary>
        public int UnreachedHandFrames { get; internal set; }

        /// <summary>
        /// Frames in which a hand could not reach its controller while the wearer's own arm on that side was not fully
        /// stretched (its shoulder-to-wrist distance under <see cref="SessionEvaluator.StretchedArm"/> of its length): an
        /// avatar arm shorter than the wearer's shows here.
        /// </summary>
        public int UnreachedWhileBentFrames { get; internal set; }

        /// <summary>The wearer's true measurements (from the session's ground-truth skeleton), or null without one.</summary>
        public BodyMeasurements TrueMeasurements { get; internal set; }

        /// <summary>The calibrated avatar's measurements (the fitted or uniformly scaled avatar), or null before calibration.</summary>
        public BodyMeasurements AvatarMeasurements { get; internal set; }

        /// <summary>
        /// The refinement from motion (<see cref="SessionEvaluator.EvaluateExercise"/> with refinement on), or null; then
        /// <see cref="AvatarMeasurements"/> are the refined avatar's.
        /// </summary>
        public RefinementReport Refinement { get; internal set; }

        /// <summary>Frames of the refinement exercise after calibration, not scored (0 without an exercise).</summary>
        public int ExerciseFrames { get; internal set; }

        /// <summary>How many times the pipeline found devices swapped (none should be, in a session without swaps).</summary>
        public int RoleSwaps { get; internal set; }

        /// <summary>What the injected disturbances did, when the evaluation injected any; else null.</summary>
        public DisturbanceReport Disturbance { get; internal set; }

        /// <summary>The fingers on the solved body, when the avatar has finger bones and the hands a controller profile; else null.</summary>
        public FingerReport Fingers { get; internal set; }
    }
}
