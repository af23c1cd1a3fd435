namespace AvatarGo.Core
{
    /// <summary>How the pipeline places a wrist from its controller (<see cref="HandSettings.Placement"/>).</summary>
    public enum HandPlacement
    {
        /// <summary>
        /// The paper's: the controller's grip sits under the avatar's palm, the wrist at the palm's exact offset from it
        /// (<see cref="HandModel.WristInController"/>), so the fingers always close on the controller. Needs a controller
        /// profile and finger bones; otherwise the hand uses <see cref="CalibratedOffset"/>.
        /// </summary>
        PalmOnController = 0,

        /// <summary>The controller-to-wrist offset measured at the walk-in, like every other device's exact offset.</summary>
        CalibratedOffset = 1,
    }
}
