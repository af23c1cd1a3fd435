namespace AvatarGo.Core
{
    /// <summary>How the avatar is scaled to the wearer at calibration (<see cref="ProportionSettings.Mode"/>).</summary>
    public enum ScaleMode
    {
        /// <summary>The paper's: the whole avatar scaled by the wearer's eye height over the avatar's.</summary>
        Uniform,

        /// <summary>
        /// Legs and arms fitted to the measured proportions (<see cref="BodyMeasurements"/>) within plausible limits, the
        /// rest scaled so that the eye height matches (<see cref="ProportionFitter"/>).
        /// </summary>
        Fitted,
    }
}
