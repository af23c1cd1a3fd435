using System;
using System.Globalization;

namespace AvatarGo.Core
{
    /// <summary>
    /// A double as the shortest invariant text that parses back to the same value, on every runtime. .NET's "R" is that
    /// on .NET Core 3.0 and later; on 64-bit .NET Framework "R" is documented to fail to round-trip some doubles (whether
    /// Unity's Mono does too was not checked), so the text is parsed back and, where it differs, written with 17
    /// significant digits (always exact). Floats keep "R", which round-trips on both. Allocation-free for spans.
    /// </summary>
    internal static class RoundTripNumber
    {
        /// <summary>Writes <paramref name="value"/> into <paramref name="destination"/>; false when it does not fit.</summary>
        public static bool TryFormat(double value, Span<char> destination, out int written)
        {
            if (!value.TryFormat(destination, out written, "R".AsSpan(), CultureInfo.InvariantCulture)) return false;
            if (ParsesBackTo(destination.Slice(0, written), value)) return true;
            return value.TryFormat(destination, out written, "G17".AsSpan(), CultureInfo.InvariantCulture);
        }

        /// <summary><paramref name="value"/> as round-trip text.</summary>
        public static string Format(double value)
        {
            string text = value.ToString("R", CultureInfo.InvariantCulture);
            return ParsesBackTo(text.AsSpan(), value) ? text : value.ToString("G17", CultureInfo.InvariantCulture);
        }

        // NaN and the infinities parse back to themselves as text too (the writers refuse them before formatting).
        private static bool ParsesBackTo(ReadOnlySpan<char> text, double value) =>
            double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double back)
            && (back.Equals(value));
    }
}
