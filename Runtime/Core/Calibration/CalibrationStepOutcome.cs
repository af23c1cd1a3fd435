namespace AvatarGo.Core
{
    /// <summary>What a frame did to the calibration (<see cref="CalibrationStep.Outcome"/>).</summary>
    public enum CalibrationStepOutcome
    {
        /// <summary>No trigger press this frame: nothing changed.</summary>
        Waiting = 0,

        /// <summary>A press was ignored (not a controller's, too soon after the last step, or nothing left to do); <see cref="CalibrationStep.Explanation"/> says why.</summary>
        PressIgnored = 1,

        /// <summary>The step ran and was refused: <see cref="CalibrationStep.Error"/> and the wearer's message say why.</summary>
        Refused = 2,

        /// <summary>The step ran and succeeded: the state advanced.</summary>
        Advanced = 3,
    }
}
