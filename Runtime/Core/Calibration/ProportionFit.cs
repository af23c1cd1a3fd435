namespace AvatarGo.Core
{
    /// <summary>
    /// The result of <see cref="ProportionFitter.Fit"/>: the overall scale and the proportions to apply, the proportions
    /// the measurement alone gives (before the significance test and the limits), and the wearer's measurements.
    /// </summary>
    public sealed class ProportionFit
    {
        /// <summary>The overall scale to apply (eye heights match).</summary>
        public float Scale { get; internal set; }

        /// <summary>The proportions to apply (uniform in <see cref="ScaleMode.Uniform"/>).</summary>
        public BodyProportions Proportions { get; internal set; } = BodyProportions.Uniform;

        /// <summary>The proportions that match the measurement exactly, with their overall scale <see cref="MeasuredScale"/>.</summary>
        public BodyProportions Measured { get; internal set; } = BodyProportions.Uniform;

        /// <summary>The overall scale of <see cref="Measured"/>.</summary>
        public float MeasuredScale { get; internal set; }

        /// <summary>The wearer's measurements.</summary>
        public BodyMeasurements Measurements { get; internal set; }

        /// <summary>Why each group was or was not refitted (for the developer).</summary>
        public string Explanation { get; internal set; } = string.Empty;
    }
}
