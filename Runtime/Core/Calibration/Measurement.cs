using System;
using System.Globalization;

namespace AvatarGo.Core
{
    /// <summary>A measured length in metres with its uncertainty: the bound (not a standard deviation) within which the
    /// true value is expected, from the devices' mounting tolerances and the samples' spread.</summary>
    public readonly struct Measurement : IEquatable<Measurement>
    {
        /// <summary>The measured value, in metres.</summary>
        public readonly float Value;

        /// <summary>The uncertainty bound, in metres (non-negative).</summary>
        public readonly float Uncertainty;

        /// <summary>Creates a measurement.</summary>
        public Measurement(float value, float uncertainty)
        {
            Value = value;
            Uncertainty = Math.Abs(uncertainty);
        }

        /// <summary>True when both numbers are finite.</summary>
        public bool IsFinite => Vectors.IsFinite(Value) && Vectors.IsFinite(Uncertainty);

        /// <inheritdoc/>
        public bool Equals(Measurement other) => Value.Equals(other.Value) && Uncertainty.Equals(other.Uncertainty);

        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is Measurement m && Equals(m);

        /// <inheritdoc/>
        public override int GetHashCode() => (Value.GetHashCode() * 397) ^ Uncertainty.GetHashCode();

        /// <inheritdoc/>
        public override string ToString() => string.Format(CultureInfo.InvariantCulture, "{0:0.000} ± {1:0.000} m", Value, Uncertainty);
    }
}
