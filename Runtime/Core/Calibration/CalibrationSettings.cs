using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// Tunable thresholds of the calibration; the defaults suit adults in room-scale VR. Every number is checked where it is
    /// set: a bad one throws an <see cref="ArgumentOutOfRangeException"/> naming the setting.
    /// </summary>
    public sealed class CalibrationSettings
    {
        /// <summary>Seconds of samples before a trigger press that are averaged (0.5 s).</summary>
        public float WindowSeconds
        {
            get => _windowSeconds;
            set => _windowSeconds = SettingChecks.PositiveFinite(value, nameof(CalibrationSettings), nameof(WindowSeconds));
        }

        private float _windowSeconds = 0.5f;

        /// <summary>Largest distance (m) of any sample from its device's mean for the wearer to count as still (2 cm).</summary>
        public float StillPosition
        {
            get => _stillPosition;
            set => _stillPosition = SettingChecks.Positive(value, nameof(CalibrationSettings), nameof(StillPosition));
        }

        private float _stillPosition = 0.02f;

        /// <summary>Largest angle (°) of any sample from its device's mean rotation to count as still (5°).</summary>
        public float StillRotationDegrees
        {
            get => _stillRotationDegrees;
            set => _stillRotationDegrees = SettingChecks.Positive(value, nameof(CalibrationSettings), nameof(StillRotationDegrees));
        }

        private float _stillRotationDegrees = 5f;

        /// <summary>
        /// The floor height in tracking space; 0 for the floor-level tracking origin of OpenXR and SteamVR
        /// (the default). NaN: estimate it from the foot trackers minus <see cref="FootTrackerHeight"/>.
        /// </summary>
        public float FloorHeight
        {
            get => _floorHeight;
            set => _floorHeight = float.IsNaN(value) ? value : SettingChecks.Finite(value, nameof(CalibrationSettings), nameof(FloorHeight));
        }

        private float _floorHeight;

        /// <summary>Height of a foot tracker's origin above the floor, used only when the floor is estimated (8 cm).</summary>
        public float FootTrackerHeight
        {
            get => _footTrackerHeight;
            set => _footTrackerHeight = SettingChecks.NotNegativeFinite(value, nameof(CalibrationSettings), nameof(FootTrackerHeight));
        }

        private float _footTrackerHeight = 0.08f;

        /// <summary>
        /// When false (the default) only a controller's trigger runs a calibration step; a press attributed to a tracker or
        /// the HMD is ignored (and the step result says so). Set it for runtimes that report presses on other devices.
        /// </summary>
        public bool AcceptTriggerFromAnyDevice { get; set; }

        /// <summary>
        /// Keep the avatar's joints between the hips and the head that are no humanoid bone (UE5's <c>spine_02</c> and
        /// <c>neck_02</c>, the CMU conversion's <c>Neck1</c>) in their bind rotation in the calibration pose, instead of standing
        /// them up with the spine bones around them (<see cref="TPoser"/>). For an avatar whose bones Unity's Animator writes
        /// (the Animator IK driver sets the humanoid bones' local rotations only, and humanoid animation does not move such
        /// joints, so they stay as bound), so that the pose the core solves has them where Unity has them; otherwise the spine bones' local rotations copied
        /// into Unity would sit on differently turned joints and move the neck and head off the solve. False (the default)
        /// when the core's pose is written whole (the Transforms driver) or compared with a simulated wearer, whose T-pose
        /// stands them up too. The proportion fit and the refinement exercise measure the stood-up T-pose either way.
        /// </summary>
        public bool SpineJointsAsBound { get; set; }

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
        public float FootTrackerForward
        {
            get => _footTrackerForward;
            set => _footTrackerForward = SettingChecks.Finite(value, nameof(CalibrationSettings), nameof(FootTrackerForward));
        }

        private float _footTrackerForward = 0.08f;
    }
}
