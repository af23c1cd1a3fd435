using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The result of <see cref="ProportionRefinement.Solve"/>: each limb's length before and after with its residual, the
    /// proportions to apply and why. Immutable once returned.
    /// </summary>
    public sealed class RefinementReport
    {
        internal readonly LimbRefinement[] Limbs = new LimbRefinement[4];

        /// <summary>How many frames were recorded (at most the capacity; <see cref="Truncated"/> says when more came).</summary>
        public int Frames { get; internal set; }

        /// <summary>True when the exercise had more frames than the refinement's capacity (the later ones were not used).</summary>
        public bool Truncated { get; internal set; }

        /// <summary>The proportions before the refinement.</summary>
        public BodyProportions Before { get; internal set; } = BodyProportions.Uniform;

        /// <summary>The proportions after it (equal to <see cref="Before"/> when nothing was refined).</summary>
        public BodyProportions After { get; internal set; } = BodyProportions.Uniform;

        /// <summary>True when any length changed (the avatar is rebuilt and the exact offsets computed again on it).</summary>
        public bool Changed => !After.Equals(Before);

        /// <summary>Why each limb was or was not refined (for the developer).</summary>
        public string Explanation { get; internal set; } = string.Empty;

        /// <summary>One arm's result (shoulder to the wrist's target).</summary>
        public LimbRefinement Arm(BodySide side) => Limbs[side == BodySide.Left ? 0 : 1];

        /// <summary>One leg's result (hip joint to the ankle's target).</summary>
        public LimbRefinement Leg(BodySide side) => Limbs[side == BodySide.Left ? 2 : 3];

        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"arms {Arm(BodySide.Left)} / {Arm(BodySide.Right)}; legs {Leg(BodySide.Left)} / {Leg(BodySide.Right)}; {Explanation}");
    }
}
