using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The paper's vector t for one hand: per finger joint a value in [0, 1] blending its open rotation (0) to its
    /// closed one (1), and the thumb's second parameter at its first joint, its spread (a radial lift, like Unity's
    /// Thumb Spread muscle). <see cref="FingerSolver"/> writes it, <see cref="HandModel.Apply"/> poses a hand from it.
    /// </summary>
    public sealed class FingerParameters
    {
        /// <summary>The number of parameters: five fingers of three joints, plus the thumb's spread.</summary>
        public const int Count = 16;

        // Storage order: finger-major (thumb 0–2, index 3–5, …, little 12–14), then the thumb's spread (15).
        internal const int ThumbSpreadIndex = 15;
        internal readonly float[] Values = new float[Count];

        /// <summary>The closing of one finger joint, 0 (open) to 1 (closed).</summary>
        public float this[Finger finger, Phalanx joint]
        {
            get => Values[IndexOf(finger, joint)];
            set => Values[IndexOf(finger, joint)] = value;
        }

        /// <summary>The thumb's spread at its first joint, 0 (in the palm's plane) to 1 (lifted <see cref="HandModel.ThumbSpreadDegrees"/>).</summary>
        public float ThumbSpread
        {
            get => Values[ThumbSpreadIndex];
            set => Values[ThumbSpreadIndex] = value;
        }

        /// <summary>Every parameter 0: the open hand, the pose the hand model was built from (in the pipeline the calibration T-pose's relaxed fingers).</summary>
        public void Clear() => Array.Clear(Values, 0, Count);

        /// <summary>Copies every parameter of <paramref name="other"/>.</summary>
        public void CopyFrom(FingerParameters other)
        {
            if (other == null) throw new ArgumentNullException(nameof(other));
            Array.Copy(other.Values, Values, Count);
        }

        /// <summary>A copy of every parameter, finger-major (thumb, index, middle, ring, little; proximal to distal), then the thumb's spread. Allocates: for tools and tests.</summary>
        public float[] ToArray() => (float[])Values.Clone();

        internal static int IndexOf(Finger finger, Phalanx joint)
        {
            if ((uint)finger > 4) throw new ArgumentOutOfRangeException(nameof(finger), finger, "Not a finger.");
            if ((uint)joint > 2) throw new ArgumentOutOfRangeException(nameof(joint), joint, "Not a finger joint.");
            return (int)finger * 3 + (int)joint;
        }
    }
}
