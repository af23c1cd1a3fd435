using System;

namespace AvatarGo.Core
{
    /// <summary>Settings of a <see cref="SelfAvatarPipeline"/>: calibration thresholds, the offset mode and each hand's controller and grip.</summary>
    public sealed class PipelineSettings
    {
        private CalibrationSettings _calibration = new CalibrationSettings();

        /// <summary>The calibration's thresholds (stillness window, floor, which presses count).</summary>
        public CalibrationSettings Calibration
        {
            get => _calibration;
            set => _calibration = value ?? throw new ArgumentNullException(nameof(value));
        }

        /// <summary>Which samples are rejected and how lost devices' parts are eased and brought back.</summary>
        public TrackingSettings Tracking { get; } = new TrackingSettings();

        /// <summary>
        /// Exact offsets (the paper's method, the default) or the fixed-offset baseline; read when calibration completes
        /// or a profile is restored.
        /// </summary>
        public OffsetMode Offsets { get; set; } = OffsetMode.Exact;

        /// <summary>How the knees' bend direction is chosen (<see cref="KneeHintModel.OuterOfPelvisAndFoot"/>); read when calibration completes.</summary>
        public KneeHintModel KneeHints { get; set; } = KneeHintModel.OuterOfPelvisAndFoot;

        /// <summary>How the elbows' bend direction is chosen (<see cref="ElbowHintModel.HandAxis"/>); read when calibration completes.</summary>
        public ElbowHintModel ElbowHints { get; set; } = ElbowHintModel.HandAxis;

        private float _shrugReleaseSeconds = FullBodyIk.DefaultShrugReleaseSeconds;

        /// <summary>
        /// How slowly a shoulder releases the shrug its hand needed to reach the controller (seconds,
        /// <see cref="FullBodyIk.DefaultShrugReleaseSeconds"/>; 0 holds none); read when calibration completes.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float ShrugReleaseSeconds
        {
            get => _shrugReleaseSeconds;
            set => _shrugReleaseSeconds = SettingChecks.NotNegativeFinite(value, nameof(PipelineSettings), nameof(ShrugReleaseSeconds));
        }

        private float _spineChordNoiseMetres = FullBodyIk.DefaultChordNoiseMetres;

        /// <summary>
        /// The change in the hips-to-head distance that the back does not flex for (metres,
        /// <see cref="FullBodyIk.DefaultChordNoiseMetres"/>: the noise of two 1 mm devices; 0 for noise-free targets);
        /// <see cref="FullBodyIk.ChordNoiseMetres"/>. Read when calibration completes.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float SpineChordNoiseMetres
        {
            get => _spineChordNoiseMetres;
            set => _spineChordNoiseMetres = SettingChecks.NotNegativeFinite(value, nameof(PipelineSettings), nameof(SpineChordNoiseMetres));
        }

        private float _spineChordCutoffHz = FullBodyIk.DefaultChordCutoffHz;

        /// <summary>
        /// The cutoff (Hz, <see cref="FullBodyIk.DefaultChordCutoffHz"/>; 0 turns it off) of the filter on the hips-to-head
        /// distance the back bends for, which steadies the chest against the devices' noise;
        /// <see cref="FullBodyIk.ChordCutoffHz"/>. Read when calibration completes.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float SpineChordCutoffHz
        {
            get => _spineChordCutoffHz;
            set => _spineChordCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(PipelineSettings), nameof(SpineChordCutoffHz));
        }

        private float _straightLegCutoffHz = FullBodyIk.DefaultStraightLegCutoffHz;

        /// <summary>
        /// The cutoff (Hz, <see cref="FullBodyIk.DefaultStraightLegCutoffHz"/>; 0 turns it off) of the filter that steadies a
        /// leg held straight against the devices' noise; <see cref="FullBodyIk.StraightLegCutoffHz"/>. Read when calibration
        /// completes.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float StraightLegCutoffHz
        {
            get => _straightLegCutoffHz;
            set => _straightLegCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(PipelineSettings), nameof(StraightLegCutoffHz));
        }

        private float _straightArmCutoffHz = FullBodyIk.DefaultStraightArmCutoffHz;

        /// <summary>
        /// The cutoff (Hz, <see cref="FullBodyIk.DefaultStraightArmCutoffHz"/>; 0 turns it off) of the filter that steadies an
        /// arm held straight against the devices' noise, its clavicle taking up the difference so the hand stays on its goal;
        /// <see cref="FullBodyIk.StraightArmCutoffHz"/>. Read when calibration completes.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float StraightArmCutoffHz
        {
            get => _straightArmCutoffHz;
            set => _straightArmCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(PipelineSettings), nameof(StraightArmCutoffHz));
        }

        /// <summary>The left hand's controller and grip.</summary>
        public HandSettings LeftHand { get; } = new HandSettings();

        /// <summary>The right hand's controller and grip.</summary>
        public HandSettings RightHand { get; } = new HandSettings();

        /// <summary>The settings of one hand.</summary>
        public HandSettings Hand(BodySide side) => side == BodySide.Left ? LeftHand : RightHand;
    }
}
