namespace AvatarGo.Core
{
    /// <summary>
    /// The result of feeding a frame to the <see cref="Calibrator"/> (or of restoring a profile): the state after it, what
    /// happened, the error if a step was refused, what to tell the wearer, and notes on choices made. An immutable value.
    /// </summary>
    public readonly struct CalibrationStep
    {
        /// <summary>The calibration state after this frame.</summary>
        public readonly CalibrationState State;

        /// <summary>What this frame did.</summary>
        public readonly CalibrationStepOutcome Outcome;

        /// <summary>Why the step was refused (<see cref="CalibrationError.None"/> otherwise).</summary>
        public readonly CalibrationError Error;

        /// <summary>What to tell the wearer now: the next instruction, or what to change and why.</summary>
        public readonly string Message;

        /// <summary>Notes for the developer (which extra devices were ignored, why a press was ignored), or empty.</summary>
        public readonly string Explanation;

        /// <summary>Creates a step result.</summary>
        public CalibrationStep(CalibrationState state, CalibrationStepOutcome outcome, CalibrationError error, string message, string explanation)
        {
            State = state;
            Outcome = outcome;
            Error = error;
            Message = message ?? string.Empty;
            Explanation = explanation ?? string.Empty;
        }

        /// <inheritdoc/>
        public override string ToString() =>
            $"{State} ({Outcome}{(Error != CalibrationError.None ? ", " + Error : "")}): {Message}{(Explanation.Length > 0 ? " [" + Explanation + "]" : "")}";
    }
}
