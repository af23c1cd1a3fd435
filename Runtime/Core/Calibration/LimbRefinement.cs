using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// What a <see cref="ProportionRefinement"/> found for one limb, in metres. An arm: the length its controller's robust
    /// longest reach from the shoulder (<see cref="ProportionRefinement.Percentile"/> of the exercise's frames) needs; a leg:
    /// the robust longest distance from its hip joint to the ankle's target. The residual is that minus the limb's length:
    /// positive, the limb is that much too short; negative, too long (an arm) or never stretched that far. An immutable value.
    /// </summary>
    public readonly struct LimbRefinement
    {
        /// <summary>Creates a limb's result.</summary>
        public LimbRefinement(int samples, float lengthBefore, float reach, float lengthAfter, bool refined, float shoulderOffset = float.NaN)
        {
            ShoulderOffset = shoulderOffset;
            Samples = samples;
            LengthBefore = lengthBefore;
            Reach = reach;
            LengthAfter = lengthAfter;
            Refined = refined;
        }

        /// <summary>How many frames of the exercise had this limb's target tracked.</summary>
        public int Samples { get; }

        /// <summary>The avatar's limb length (upper segment plus lower) before the refinement.</summary>
        public float LengthBefore { get; }

        /// <summary>An arm: the length its reach in the exercise needs; a leg: the robust longest hip-to-ankle-target distance (NaN without samples).</summary>
        public float Reach { get; }

        /// <summary>The avatar's limb length after the refinement (<see cref="LengthBefore"/> when not refined).</summary>
        public float LengthAfter { get; }

        /// <summary>
        /// For an arm: how far (m) the centre of its motion (the sphere its targets lie on, in the torso's frame) is from
        /// the avatar's shoulder joint, the reach being measured from that centre; NaN for a leg, or where the fit was
        /// ill-posed and the reach is measured from the avatar's shoulder.
        /// </summary>
        public float ShoulderOffset { get; }

        /// <summary>True when the limb's length was changed.</summary>
        public bool Refined { get; }

        /// <summary><see cref="Reach"/> minus <see cref="LengthBefore"/>: the reach deficit (arm) or length mismatch (leg) before.</summary>
        public float ResidualBefore => Reach - LengthBefore;

        /// <summary>
        /// <see cref="Reach"/> minus <see cref="LengthAfter"/>: the residual the refined avatar has on the exercise's targets,
        /// predicted (the arms' controllers do not depend on the arms' length).
        /// </summary>
        public float ResidualAfter => Reach - LengthAfter;

        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"{LengthBefore * 1000:0} -> {LengthAfter * 1000:0} mm ({(Refined ? "refined" : "kept")}), residual {ResidualBefore * 1000:+0.0;-0.0;0.0} -> {ResidualAfter * 1000:+0.0;-0.0;0.0} mm over {Samples} frames{(float.IsNaN(ShoulderOffset) ? "" : $", centre {ShoulderOffset * 1000:0} mm from the shoulder")}");
    }
}
