using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// How the avatar's segments are scaled relative to its overall scale (<see cref="CalibrationProfile.AvatarScale"/>):
    /// each leg's thigh and shin, each arm's upper arm and forearm. 1 everywhere is the paper's uniform scaling. The
    /// torso, head, hands and feet take the overall scale. An immutable value.
    /// </summary>
    public readonly struct BodyProportions : IEquatable<BodyProportions>
    {
        /// <summary>The left leg's scale relative to the overall scale.</summary>
        public readonly float LeftLeg;

        /// <summary>The right leg's scale relative to the overall scale.</summary>
        public readonly float RightLeg;

        /// <summary>The left arm's scale relative to the overall scale.</summary>
        public readonly float LeftArm;

        /// <summary>The right arm's scale relative to the overall scale.</summary>
        public readonly float RightArm;

        /// <summary>Creates proportions.</summary>
        public BodyProportions(float leftLeg, float rightLeg, float leftArm, float rightArm)
        {
            LeftLeg = leftLeg;
            RightLeg = rightLeg;
            LeftArm = leftArm;
            RightArm = rightArm;
        }

        /// <summary>Uniform scaling: every ratio 1.</summary>
        public static BodyProportions Uniform => new BodyProportions(1f, 1f, 1f, 1f);

        /// <summary>True when every ratio is exactly 1.</summary>
        public bool IsUniform => LeftLeg == 1f && RightLeg == 1f && LeftArm == 1f && RightArm == 1f;

        /// <summary>True when every ratio is positive and finite.</summary>
        public bool IsValid => Ok(LeftLeg) && Ok(RightLeg) && Ok(LeftArm) && Ok(RightArm);

        /// <summary>One leg's ratio.</summary>
        public float Leg(BodySide side) => side == BodySide.Left ? LeftLeg : RightLeg;

        /// <summary>One arm's ratio.</summary>
        public float Arm(BodySide side) => side == BodySide.Left ? LeftArm : RightArm;

        private static bool Ok(float f) => f > 0f && Vectors.IsFinite(f);

        /// <summary>
        /// The factor each joint's local position (its offset from its parent) is multiplied by, relative to the unscaled
        /// avatar, for <paramref name="map"/>'s skeleton: <paramref name="overallScale"/> times the leg ratio for the knees
        /// and ankles, times the arm ratio for the elbows and wrists (and for the joints between them and the joint above,
        /// such as twist joints inserted along a thigh or forearm), and the overall scale for every other joint. Applying
        /// it to a hierarchy's local positions (rotations untouched) gives the fitted avatar in any pose: what a Unity
        /// shell does to the bone transforms at runtime (with <paramref name="overallScale"/> 1 when the root carries the
        /// uniform scale as its local scale). A new array, one factor per joint.
        /// </summary>
        /// <exception cref="ArgumentException">The proportions are not valid or the scale is not positive.</exception>
        public float[] LocalPositionFactors(HumanoidMap map, float overallScale = 1f)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (!IsValid) throw new ArgumentException($"Proportions must be positive and finite: {this}.");
            if (!(overallScale > 0f) || !Vectors.IsFinite(overallScale)) throw new ArgumentOutOfRangeException(nameof(overallScale), overallScale, "The scale must be positive and finite.");
            var factors = new float[map.Skeleton.JointCount];
            LocalPositionFactors(map, overallScale, factors);
            return factors;
        }

        /// <summary>
        /// <see cref="LocalPositionFactors(HumanoidMap, float)"/> into <paramref name="factors"/> (one per joint of the map's
        /// skeleton), allocating nothing.
        /// </summary>
        /// <exception cref="ArgumentException">The proportions are not valid, the scale is not positive, or the span's length is not the joint count.</exception>
        public void LocalPositionFactors(HumanoidMap map, float overallScale, Span<float> factors)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (!IsValid) throw new ArgumentException($"Proportions must be positive and finite: {this}.");
            if (!(overallScale > 0f) || !Vectors.IsFinite(overallScale)) throw new ArgumentOutOfRangeException(nameof(overallScale), overallScale, "The scale must be positive and finite.");
            if (factors.Length != map.Skeleton.JointCount) throw new ArgumentException($"Expected {map.Skeleton.JointCount} factors, got {factors.Length}.", nameof(factors));
            for (int j = 0; j < factors.Length; j++) factors[j] = overallScale;
            for (int s = 0; s < 2; s++)
            {
                var side = (BodySide)s;
                SetSegment(map, factors, HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side), HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side), overallScale * Leg(side));
                SetSegment(map, factors, HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side), HumanoidBones.OnSide(HumanoidBone.LeftFoot, side), overallScale * Leg(side));
                SetSegment(map, factors, HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side), HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side), overallScale * Arm(side));
                SetSegment(map, factors, HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side), HumanoidBones.OnSide(HumanoidBone.LeftHand, side), overallScale * Arm(side));
            }
        }

        // Every joint from the segment's end up to, not including, its start: the end joint itself and the joints between
        // (twist joints inserted along the bone, as Daz Genesis' lThighTwist above lShin), so that the whole bone takes the
        // ratio; with only the end joint, a twist joint halfway along halved the change.
        private static void SetSegment(HumanoidMap map, Span<float> factors, HumanoidBone start, HumanoidBone end, float factor)
        {
            int first = map[start], last = map[end];
            if (last < 0) return;
            factors[last] = factor;
            if (first < 0 || first == last || !map.Skeleton.IsAncestorOrSelf(first, last)) return;
            for (int k = map.Skeleton.GetParent(last); k != first; k = map.Skeleton.GetParent(k)) factors[k] = factor;
        }

        /// <summary>
        /// The avatar with these proportions and the overall scale: a new skeleton (same names, hierarchy and rest
        /// rotations) whose rest local positions are multiplied by <see cref="LocalPositionFactors(HumanoidMap, float)"/>, with the same map.
        /// </summary>
        public HumanoidMap Apply(HumanoidMap map, float overallScale)
        {
            float[] factors = LocalPositionFactors(map, overallScale);
            Skeleton s = map.Skeleton;
            var rest = new RigidPose[s.JointCount];
            for (int j = 0; j < rest.Length; j++)
            {
                RigidPose r = s.GetRestLocal(j);
                rest[j] = new RigidPose(r.Position * factors[j], r.Rotation);
            }
            return new HumanoidMap(s.WithRestLocal(rest), new List<KeyValuePair<HumanoidBone, string>>(map.Pairs()));
        }

        /// <inheritdoc/>
        public bool Equals(BodyProportions o) => LeftLeg.Equals(o.LeftLeg) && RightLeg.Equals(o.RightLeg) && LeftArm.Equals(o.LeftArm) && RightArm.Equals(o.RightArm);

        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is BodyProportions p && Equals(p);

        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(LeftLeg, RightLeg, LeftArm, RightArm);

        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant($"legs {LeftLeg:0.000}/{RightLeg:0.000}, arms {LeftArm:0.000}/{RightArm:0.000}");
    }
}
