namespace AvatarGo.Core
{
    /// <summary>How one hand of the avatar holds its controller (a part of <see cref="PipelineSettings"/>).</summary>
    public sealed class HandSettings
    {
        /// <summary>
        /// The controller held in this hand, whose surface the fingers close on; null for no finger IK (the fingers keep
        /// the calibration T-pose's: side by side, relaxed). An avatar without finger bones has no finger IK either (<see cref="HandModel.CanModel(HumanoidMap, BodySide, SkeletonPose, out string)"/>).
        /// </summary>
        public ControllerProfile Controller { get; set; }

        /// <summary>How the wrist is placed from the controller: the palm on the grip (the default, the paper's) or the walk-in's measured offset.</summary>
        public HandPlacement Placement { get; set; } = HandPlacement.PalmOnController;

        /// <summary>What the fingers do: hold the controller (the default, as the paper's avatar always does), open, point, or follow the trigger and grip.</summary>
        public GripMode Grip { get; set; } = GripMode.Hold;
    }
}
