namespace AvatarGo.Core
{
    /// <summary>
    /// Which way the elbows bend (the elbow hint of <see cref="BodyTargetMapper"/>): the swivel of the elbow about the
    /// shoulder-to-wrist axis, which the six devices do not observe. Documentation~/solver.md compares them on recorded motion.
    /// </summary>
    public enum ElbowHintModel
    {
        /// <summary>
        /// The default: the forearm continues the hand (the elbow lies back along the hand's direction, wrist to knuckles, off
        /// the shoulder-to-wrist axis), so the hand's roll about its own axis (forearm twist) never moves the elbow; where the
        /// hand points along the arm's axis and says little, the elbow falls down, out and back from the torso (the hand's
        /// direction weighted by its part off the arm's axis, this one by <see cref="BodyTargetMapper.FallbackWeight"/>, fading
        /// where the arm itself points within 15° of down, out and back).
        /// </summary>
        HandAxis = 0,

        /// <summary>
        /// Down, out and back from the torso alone, in equal parts (the torso from the pelvis and head trackers): where the
        /// elbow falls with the upper arm hanging and the hands forward.
        /// </summary>
        DownOutBack = 1,

        /// <summary>
        /// The first implementation: where the elbow was relative to the hand at calibration, pushed back and down one arm
        /// length, carried by the controller (its roll, forearm twist, swings the elbow).
        /// </summary>
        CalibrationFrame = 2,
    }
}
