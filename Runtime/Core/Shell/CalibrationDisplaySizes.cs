using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The calibrator's display sizes as its shell applies them: a serialized field can hold anything (a hand-edited asset,
    /// a script's value), and a NaN or infinite size would reach a Transform's scale or a TextMesh. Engine-free.
    /// </summary>
    public static class CalibrationDisplaySizes
    {
        /// <summary>The calibrator's default diameter of the device markers (m).</summary>
        public const float DefaultMarkerSize = 0.06f;

        /// <summary>The largest device marker (m): larger, it would hide the wearer's view.</summary>
        public const float MaxMarkerSize = 0.5f;

        /// <summary>The calibrator's default TextMesh character size of the instructions (world units per font unit).</summary>
        public const float DefaultTextSize = 0.0025f;

        /// <summary>The largest character size of the instructions (20 times the default).</summary>
        public const float MaxTextSize = 0.05f;

        /// <summary>
        /// A marker diameter fit for a Transform's scale: <see cref="DefaultMarkerSize"/> for NaN, zero or a negative size,
        /// at most <see cref="MaxMarkerSize"/> (an infinite one is the maximum).
        /// </summary>
        public static float ValidMarkerSize(float size) => Valid(size, MaxMarkerSize, DefaultMarkerSize);

        /// <summary>
        /// A character size fit for a TextMesh: <see cref="DefaultTextSize"/> for NaN, zero or a negative size, at most
        /// <see cref="MaxTextSize"/> (an infinite one is the maximum).
        /// </summary>
        public static float ValidTextSize(float size) => Valid(size, MaxTextSize, DefaultTextSize);

        private static float Valid(float size, float max, float fallback) => size > 0f ? Math.Min(max, size) : fallback; // NaN > 0 is false
    }
}
