namespace AvatarGo.Core
{
    /// <summary>The steps of the Walk-In-Avatar calibration.</summary>
    public enum CalibrationState
    {
        /// <summary>Waiting for the wearer to stand in T-pose and press a trigger.</summary>
        WaitingForTPose = 0,

        /// <summary>The avatar is shown; waiting for the wearer to walk into it and press again.</summary>
        WalkIn = 1,

        /// <summary>Offsets are computed: <see cref="Calibrator.Profile"/> is ready.</summary>
        Calibrated = 2,
    }
}
