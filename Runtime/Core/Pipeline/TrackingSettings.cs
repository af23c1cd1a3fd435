namespace AvatarGo.Core
{
    /// <summary>
    /// How the pipeline treats bad and missing device data (a part of <see cref="PipelineSettings"/>): which samples are
    /// rejected, how a lost device's part eases to a plausible pose, and how it comes back. Defaults chosen by measurement
    /// (Documentation~/solver.md, "Tracking loss").
    /// </summary>
    /// <remarks>
    /// Every setter refuses a value that would break the pipeline (NaN, a negative time, a zero speed limit that would
    /// never let a part recover) with an <see cref="System.ArgumentOutOfRangeException"/> naming the setting, so that a bad value
    /// fails where it is set, not in a later frame. Where it makes sense, positive infinity turns a limit off (no speed
    /// limit, never reacquire, hold for good).
    /// </remarks>
    public sealed class TrackingSettings
    {
        private const string Owner = nameof(TrackingSettings);

        /// <summary>A sample that would move its device faster than this (m/s) since its last accepted one is a glitch, not motion (20 m/s: faster than a kick or a throw).</summary>
        public float MaxSpeed
        {
            get => _maxSpeed;
            set => _maxSpeed = SettingChecks.Positive(value, Owner, nameof(MaxSpeed));
        }

        private float _maxSpeed = 20f;

        /// <summary>A sample that would turn its device faster than this (°/s) is a glitch (3000 °/s: faster than a wrist flick).</summary>
        public float MaxAngularSpeedDegrees
        {
            get => _maxAngularSpeedDegrees;
            set => _maxAngularSpeedDegrees = SettingChecks.Positive(value, Owner, nameof(MaxAngularSpeedDegrees));
        }

        private float _maxAngularSpeedDegrees = 3000f;

        /// <summary>
        /// A device rejected for a jump is taken back at its new place once its samples have agreed with each other there for
        /// this long (0.5 s): the tracking space really moved (a recentre), it was not a glitch.
        /// </summary>
        public float ReacquireSeconds
        {
            get => _reacquireSeconds;
            set => _reacquireSeconds = SettingChecks.NotNegative(value, Owner, nameof(ReacquireSeconds));
        }

        private float _reacquireSeconds = 0.5f;

        /// <summary>
        /// A device farther from the HMD than this many times its distance at the walk-in (plus <see cref="BodyReachMargin"/>)
        /// cannot be on the wearer's body and is rejected (1.3).
        /// </summary>
        public float BodyReachFactor
        {
            get => _bodyReachFactor;
            set => _bodyReachFactor = SettingChecks.PositiveFinite(value, Owner, nameof(BodyReachFactor));
        }

        private float _bodyReachFactor = 1.3f;

        /// <summary>Metres added to the reach bound (0.2).</summary>
        public float BodyReachMargin
        {
            get => _bodyReachMargin;
            set => _bodyReachMargin = SettingChecks.NotNegative(value, Owner, nameof(BodyReachMargin));
        }

        private float _bodyReachMargin = 0.2f;

        /// <summary>A lost device's part first holds its last pose relative to the body this long (0.25 s): most losses are shorter.</summary>
        public float HoldSeconds
        {
            get => _holdSeconds;
            set => _holdSeconds = SettingChecks.NotNegative(value, Owner, nameof(HoldSeconds));
        }

        private float _holdSeconds = 0.25f;

        /// <summary>Then it eases to a plausible pose over this long (1 s): a lost foot under the hips on the floor, a lost hand hanging from the shoulder, a lost pelvis under the head.</summary>
        public float EaseSeconds
        {
            get => _easeSeconds;
            set => _easeSeconds = SettingChecks.NotNegative(value, Owner, nameof(EaseSeconds));
        }

        private float _easeSeconds = 1f;

        /// <summary>A device that comes back is blended in: the difference from where its part was shown decays with this time constant (0.05 s)…</summary>
        public float RecoveryTimeConstant
        {
            get => _recoveryTimeConstant;
            set => _recoveryTimeConstant = SettingChecks.NotNegative(value, Owner, nameof(RecoveryTimeConstant));
        }

        private float _recoveryTimeConstant = 0.05f;

        /// <summary>…but never faster than this (m/s, 1.2: 13 mm a frame at 90 Hz), so nothing snaps.</summary>
        public float RecoveryMaxSpeed
        {
            get => _recoveryMaxSpeed;
            set => _recoveryMaxSpeed = SettingChecks.Positive(value, Owner, nameof(RecoveryMaxSpeed));
        }

        private float _recoveryMaxSpeed = 1.2f;

        /// <summary>…nor turns faster than this (°/s, 360).</summary>
        public float RecoveryMaxAngularSpeedDegrees
        {
            get => _recoveryMaxAngularSpeedDegrees;
            set => _recoveryMaxAngularSpeedDegrees = SettingChecks.Positive(value, Owner, nameof(RecoveryMaxAngularSpeedDegrees));
        }

        private float _recoveryMaxAngularSpeedDegrees = 360f;

        /// <summary>
        /// Smooths every accepted device pose with a <see cref="OneEuroFilter"/> before the body is solved. Off by default:
        /// at the noise of current trackers it costs more (latency) than it gives (Documentation~/solver.md, "Jitter").
        /// </summary>
        public bool Smoothing { get; set; }

        /// <summary>The smoothing's cutoff for a still device, in Hz (<see cref="OneEuroFilter"/>).</summary>
        public float SmoothingMinCutoff
        {
            get => _smoothingMinCutoff;
            set => _smoothingMinCutoff = SettingChecks.PositiveFinite(value, Owner, nameof(SmoothingMinCutoff));
        }

        private float _smoothingMinCutoff = 2f;

        /// <summary>How fast the smoothing's cutoff rises with speed (Hz per m/s, and per rad/s).</summary>
        public float SmoothingBeta
        {
            get => _smoothingBeta;
            set => _smoothingBeta = SettingChecks.NotNegativeFinite(value, Owner, nameof(SmoothingBeta));
        }

        private float _smoothingBeta = 30f;

        /// <summary>
        /// When true (the default), controllers found in the other hands, or foot trackers on the other feet, after
        /// calibration (<see cref="RoleSwapDetector"/>) are given each other's roles at once; when false, the swap is only
        /// reported (<see cref="SelfAvatarPipeline.LastSwap"/>).
        /// </summary>
        public bool ReassignSwappedDevices { get; set; } = true;

        /// <summary>How long a pair must look swapped before it is (3 s): crossing the arms or legs for a moment is not a swap.</summary>
        public float SwapWindowSeconds
        {
            get => _swapWindowSeconds;
            set => _swapWindowSeconds = SettingChecks.Positive(value, Owner, nameof(SwapWindowSeconds));
        }

        private float _swapWindowSeconds = 3f;

        /// <summary>How far (m) the left device must be to the right of the right one to count as swapped in a frame (0.2).</summary>
        public float SwapMargin
        {
            get => _swapMargin;
            set => _swapMargin = SettingChecks.NotNegativeFinite(value, Owner, nameof(SwapMargin));
        }

        private float _swapMargin = 0.2f;
    }
}
