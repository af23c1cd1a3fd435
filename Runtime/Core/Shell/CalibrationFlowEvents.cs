using System;

namespace AvatarGo.Core
{
    /// <summary>What happened to the calibration in a frame, as <see cref="CalibrationFlow"/> reports it (any combination).</summary>
    [Flags]
    public enum CalibrationFlowEvents
    {
        /// <summary>Nothing.</summary>
        None = 0,

        /// <summary>The T-pose step succeeded: the devices are identified and the scaled avatar is shown for the walk-in.</summary>
        TPoseAccepted = 1 << 0,

        /// <summary>The walk-in step succeeded: the exact offsets are measured and the avatar follows.</summary>
        Calibrated = 1 << 1,

        /// <summary>A step ran and was refused (the message says what to change).</summary>
        StepRefused = 1 << 2,

        /// <summary>A trigger press ran no step (the explanation says why).</summary>
        PressIgnored = 1 << 3,

        /// <summary>A saved profile was restored instead of calibrating.</summary>
        Restored = 1 << 4,

        /// <summary>The calibration was reset (cancel or redo).</summary>
        Reset = 1 << 5,

        /// <summary>A new calibration is ready to be saved.</summary>
        SaveProfile = 1 << 6,
    }
}
