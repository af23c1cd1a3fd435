using System;

namespace AvatarGo.Core
{
    /// <summary>Tunable thresholds of the calibration; the defaults suit adults in room-scale VR.</summary>
    public sealed class CalibrationSettings
    {
        /// <summary>Seconds of samples before a trigger press that are averaged (0.5 s).</summary>
        public float WindowSeconds { get; set; } = 0.5f;

        /// <summary>Largest distance (m) of any sample from its device's mean for the wearer to count as still (2 cm).</summary>
        public float StillPosition { get; set; } = 0.02f;

        /// <summary>Largest angle (°) of any sample from its device's mean rotation to count as still (5°).</summary>
        public float StillRotationDegrees { get; set; } = 5f;

        /// <summary>
        /// The floor height in tracking space; 0 for the floor-level tracking origin of OpenXR and SteamVR
        /// (the default). NaN: estimate it from the foot trackers minus <see cref="FootTrackerHeight"/>.
        /// </summary>
        public float FloorHeight { get; set; }

        /// <summary>Height of a foot tracker's origin above the floor, used only when the floor is estimated (8 cm).</summary>
        public float FootTrackerHeight { get; set; } = 0.08f;

        /// <summary>
        /// When false (the default) only a controller's trigger runs a calibration step; a press attributed to a tracker or
        /// the HMD is ignored (and the step result says so). Set it for runtimes that report presses on other devices.
        /// </summary>
        public bool AcceptTriggerFromAnyDevice { get; set; }

        private ProportionSettings _proportions = new ProportionSettings();

        /// <summary>
        /// How the avatar is scaled: uniformly (the default, the paper's) or with its legs and arms fitted to the wearer's
        /// measured proportions, the limits and the measurement tolerances (<see cref="ProportionFitter"/>).
        /// </summary>
        public ProportionSettings Proportions
        {
            get => _proportions;
            set => _proportions = value ?? throw new ArgumentNullException(nameof(value));
        }

        /// <summary>How far in front of the ankle a foot tracker sits, used to place the avatar (8 cm).</summary>
        public float FootTrackerForward { get; set; } = 0.08f;
    }
}
