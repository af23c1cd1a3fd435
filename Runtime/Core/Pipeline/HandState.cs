namespace AvatarGo.Core
{
    /// <summary>
    /// One hand after a frame of the <see cref="SelfAvatarPipeline"/>: whether the arm reached its controller, where the
    /// virtual controller is drawn (at the tracked pose, or in the hand when the arm cannot reach, as the paper does),
    /// and how the fingers hold it. Updated in place every frame; read it, do not keep copies of its parts.
    /// </summary>
    public sealed class HandState
    {
        internal HandState(BodySide side) => Side = side;

        /// <summary>Which hand.</summary>
        public BodySide Side { get; }

        /// <summary>How the wrist is placed from the controller (<see cref="HandPlacement.CalibratedOffset"/> when the hand has no finger IK).</summary>
        public HandPlacement Placement { get; internal set; } = HandPlacement.CalibratedOffset;

        /// <summary>True when the controller was tracked this frame (otherwise the arm kept its last pose).</summary>
        public bool ControllerTracked { get; internal set; }

        /// <summary>True when the wrist reached the pose the controller asks for (within <see cref="TwoBoneIk.ReachedTolerance"/>).</summary>
        public bool Reached { get; internal set; }

        /// <summary>How far (m) the wrist is from where the controller asks for it; 0 when reached.</summary>
        public float DistanceLeft { get; internal set; }

        /// <summary>
        /// Where to draw the virtual controller this frame: the tracked pose while the hand reaches it; in the hand, in the
        /// grip the wrist is placed with, while it cannot (or while the controller is not tracked), as the paper does. The two
        /// meet where the hand stops reaching (within <see cref="TwoBoneIk.ReachedTolerance"/>), so switching does not jump.
        /// </summary>
        public RigidPose ControllerPose { get; internal set; } = RigidPose.Identity;

        /// <summary>True when the controller is drawn in the hand rather than at its tracked pose.</summary>
        public bool DrawnInHand { get; internal set; }

        /// <summary>True when this hand's fingers are solved on a controller (a profile is set and the rig has finger bones).</summary>
        public bool HasFingerIk { get; internal set; }

        /// <summary>Why the hand has no finger IK, or null when it has (before calibration and after a reset: not calibrated).</summary>
        public string NoFingerIkReason { get; internal set; } = NotCalibrated;

        internal const string NotCalibrated = "the pipeline is not calibrated";

        /// <summary>The fingers' joint parameters (the paper's t) applied to the pose this frame; all 0 without finger IK.</summary>
        public FingerParameters Fingers { get; } = new FingerParameters();

        /// <summary>True when the fingers closed on the controller; false when they opened because the palm was too far from it.</summary>
        public bool Holding { get; internal set; }

        /// <summary>
        /// After this frame's solve, the signed distance (m) from the controller's surface to the skin at a finger point
        /// (negative: penetration); NaN without finger IK or for a finger the rig lacks.
        /// </summary>
        public float SurfaceGap(Finger finger, FingerPoint point) => Solver != null ? Solver.SurfaceGap(finger, point) : float.NaN;

        /// <summary>After this frame's solve, how far (m) the thumb's or the index's tip is from the thumb rest or the trigger; NaN without finger IK.</summary>
        public float GoalDistance(Finger finger) => Solver != null ? Solver.GoalDistance(finger) : float.NaN;

        internal FingerSolver Solver;
    }
}
