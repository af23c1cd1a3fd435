namespace AvatarGo.Core
{
    /// <summary>
    /// The wearer's body measured at calibration (<see cref="ProportionFitter.Fit"/>), in metres, each with its
    /// uncertainty: from the device poses averaged over the T-pose window and the walk-in window (the wearer stands in
    /// the same T-pose in both), with the device-to-joint offsets accounted for through an anatomical model (the
    /// avatar's own skeleton fitted to the devices). Immutable.
    /// </summary>
    /// <remarks>
    /// What the six devices observe directly: the eyes (HMD), the controllers' grips (hence the wrists, through the hand's
    /// grip) and the pelvis tracker (hence the hips joint, through its nominal strap offset, whose tolerance dominates the
    /// legs' uncertainty). The shoulders are not observed: their height is the wrists' (arms level in the T-pose) and their
    /// width the avatar's scaled by the fitted torso, so the arms' lengths carry the shoulder width's uncertainty.
    /// Documentation~/calibration.md lists the model and the tolerances.
    /// </remarks>
    public sealed class BodyMeasurements
    {
        /// <summary>Eye height above the floor (the HMD's centre eye).</summary>
        public Measurement EyeHeight { get; internal set; }

        /// <summary>Shoulder (upper-arm joint) height above the floor.</summary>
        public Measurement ShoulderHeight { get; internal set; }

        /// <summary>Distance between the shoulder (upper-arm) joints.</summary>
        public Measurement ShoulderWidth { get; internal set; }

        /// <summary>Wrist-to-wrist distance in the T-pose.</summary>
        public Measurement ArmSpan { get; internal set; }

        /// <summary>The left arm's length: shoulder to elbow plus elbow to wrist.</summary>
        public Measurement LeftArmLength { get; internal set; }

        /// <summary>The right arm's length: shoulder to elbow plus elbow to wrist.</summary>
        public Measurement RightArmLength { get; internal set; }

        /// <summary>Height of the hips joint (the pelvis) above the floor.</summary>
        public Measurement HipHeight { get; internal set; }

        /// <summary>The left leg's length: hip to knee plus knee to ankle.</summary>
        public Measurement LeftLegLength { get; internal set; }

        /// <summary>The right leg's length: hip to knee plus knee to ankle.</summary>
        public Measurement RightLegLength { get; internal set; }

        /// <summary>How many still windows were averaged (1 after the T-pose, 2 after the walk-in).</summary>
        public int Windows { get; internal set; }

        /// <summary>The arm length of one side.</summary>
        public Measurement ArmLength(BodySide side) => side == BodySide.Left ? LeftArmLength : RightArmLength;

        /// <summary>The leg length of one side.</summary>
        public Measurement LegLength(BodySide side) => side == BodySide.Left ? LeftLegLength : RightLegLength;

        /// <summary>Every measurement with its name (for reports and the profile file), in a fixed order.</summary>
        public (string name, Measurement value)[] All() => new[]
        {
            ("eyeHeight", EyeHeight), ("shoulderHeight", ShoulderHeight), ("shoulderWidth", ShoulderWidth), ("armSpan", ArmSpan),
            ("leftArmLength", LeftArmLength), ("rightArmLength", RightArmLength), ("hipHeight", HipHeight),
            ("leftLegLength", LeftLegLength), ("rightLegLength", RightLegLength),
        };

        /// <summary>Sets a measurement by its name in <see cref="All"/>; false for an unknown name.</summary>
        internal bool Set(string name, Measurement m)
        {
            switch (name)
            {
                case "eyeHeight": EyeHeight = m; return true;
                case "shoulderHeight": ShoulderHeight = m; return true;
                case "shoulderWidth": ShoulderWidth = m; return true;
                case "armSpan": ArmSpan = m; return true;
                case "leftArmLength": LeftArmLength = m; return true;
                case "rightArmLength": RightArmLength = m; return true;
                case "hipHeight": HipHeight = m; return true;
                case "leftLegLength": LeftLegLength = m; return true;
                case "rightLegLength": RightLegLength = m; return true;
                default: return false;
            }
        }
    }
}
