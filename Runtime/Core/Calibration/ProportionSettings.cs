using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// How the avatar is scaled to the wearer (<see cref="CalibrationSettings.Proportions"/>): uniformly by eye height (the
    /// paper's, the default) or with its legs and arms fitted to the measured proportions, within limits that keep it
    /// plausible, and the tolerances the measurements' uncertainties come from. Read at calibration.
    /// </summary>
    public sealed class ProportionSettings
    {
        private float _minRatio = 0.8f, _maxRatio = 1.25f;

        /// <summary><see cref="ScaleMode.Uniform"/> (the default) or <see cref="ScaleMode.Fitted"/>.</summary>
        public ScaleMode Mode { get; set; } = ScaleMode.Uniform;

        /// <summary>
        /// Fit each arm on its own (false, the default: both arms get the mean of the two, as people's arms differ by less
        /// than the measurement's uncertainty, and a side-to-side difference mostly measures how the controllers are held).
        /// Legs are always fitted together: one pelvis tracker measures one hip height.
        /// </summary>
        public bool PerSide { get; set; }

        /// <summary>
        /// The smallest limb scale relative to the overall (torso) scale (0.8). With <see cref="MaxRatio"/> it keeps the
        /// avatar plausible: adult limb-to-stature ratios vary by about ±10 % between people; a limb fitted beyond the
        /// limits is set to the limit (and the measurement still reports what was measured).
        /// </summary>
        public float MinRatio
        {
            get => _minRatio;
            set
            {
                if (!(value > 0f && value <= 1f)) throw new ArgumentOutOfRangeException(nameof(value), value, "MinRatio must be in (0, 1].");
                _minRatio = value;
            }
        }

        /// <summary>The largest limb scale relative to the overall (torso) scale (1.25); see <see cref="MinRatio"/>.</summary>
        public float MaxRatio
        {
            get => _maxRatio;
            set
            {
                if (!(value >= 1f && value <= 4f)) throw new ArgumentOutOfRangeException(nameof(value), value, "MaxRatio must be in [1, 4].");
                _maxRatio = value;
            }
        }

        /// <summary>
        /// How far the pelvis tracker's origin sits above the hips joint, in metres (3 cm: a belt strap over the sacrum,
        /// as <see cref="CalibrationSettings.FootTrackerForward"/> is the foot trackers' nominal offset).
        /// </summary>
        public float PelvisTrackerAboveHips
        {
            get => _pelvisTrackerAboveHips;
            set => _pelvisTrackerAboveHips = SettingChecks.Finite(value, nameof(ProportionSettings), nameof(PelvisTrackerAboveHips));
        }

        private float _pelvisTrackerAboveHips = 0.03f;

        /// <summary>
        /// How far that offset may be off, in metres (2 cm: straps never sit twice in the same place). The hip height's and
        /// the legs' uncertainty; the legs are refitted only when the measured hip height differs from the uniformly scaled
        /// avatar's by more than the uncertainty.
        /// </summary>
        public float PelvisTrackerTolerance
        {
            get => _pelvisTrackerTolerance;
            set => _pelvisTrackerTolerance = SettingChecks.NotNegativeFinite(value, nameof(ProportionSettings), nameof(PelvisTrackerTolerance));
        }

        private float _pelvisTrackerTolerance = 0.02f;

        /// <summary>
        /// How far the wrist may be from where the avatar's hand puts it relative to the controller's grip, in metres (1 cm:
        /// a hold varies by millimetres, a hand's size by about a centimetre at the palm). The arms' uncertainty, with half
        /// the shoulder width's; the arms are refitted only when the measured reach differs from the uniformly scaled
        /// avatar's by more than it.
        /// </summary>
        public float ControllerTolerance
        {
            get => _controllerTolerance;
            set => _controllerTolerance = SettingChecks.NotNegativeFinite(value, nameof(ProportionSettings), nameof(ControllerTolerance));
        }

        private float _controllerTolerance = 0.01f;

        /// <summary>How far the HMD's reported centre eye may be from the eyes, in metres (3 mm).</summary>
        public float HmdTolerance
        {
            get => _hmdTolerance;
            set => _hmdTolerance = SettingChecks.NotNegativeFinite(value, nameof(ProportionSettings), nameof(HmdTolerance));
        }

        private float _hmdTolerance = 0.003f;
    }
}
