using System;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Measures the wearer (<see cref="BodyMeasurements"/>) from T-pose <see cref="BodyFeatures"/> and fits the avatar's
    /// proportions to them. The model is the avatar itself: its legs, arms and overall scale are adjusted until its own
    /// T-pose (<see cref="TPoser"/>) shows the wearer's features (eye height, hips height, each controller's reach from the
    /// midline, where the avatar's hand would hold it), so the device-to-joint offsets and the parts no device observes
    /// (shoulder width, the hips-to-hip-joint drop, the ankles' height) come from the avatar's anatomy, scaled. Runs at
    /// calibration (it allocates: a few T-poses of the avatar), never per frame.
    /// </summary>
    /// <remarks>
    /// In <see cref="ScaleMode.Fitted"/> a group (both legs; the arms, together or per side) is refitted only when the
    /// feature it is fitted to differs from the uniformly scaled avatar's by more than the feature's uncertainty: a wearer
    /// whose proportions are the avatar's within what the devices can tell keeps the avatar's own. A refitted ratio is held
    /// within <see cref="ProportionSettings.MinRatio"/>…<see cref="ProportionSettings.MaxRatio"/> of the overall scale; the
    /// overall scale then makes the eye heights match, as uniform scaling does.
    /// </remarks>
    public static class ProportionFitter
    {
        private const int Iterations = 8;

        /// <summary>Handle radius assumed for the avatar's grip (2 cm): it moves the grip down, out of the palm, not along the arm.</summary>
        private const float HandleRadius = 0.02f;

        /// <summary>What the avatar's T-pose shows, in the same terms as a wearer's <see cref="BodyFeatures"/>, and the lengths behind it.</summary>
        internal struct AvatarShape
        {
            public BodyFeatures Features;
            public float UpperLegHeight;          // mean hip-joint height
            public float LeftArm, RightArm;       // shoulder to wrist, along the arm
            public float LeftArmReach, RightArmReach; // the arms' part of the reach (shoulder to wrist, laterally)
            public float LeftLeg, RightLeg;       // hip to knee plus knee to ankle
            public float ShoulderHeight, ShoulderWidth, ArmSpan;
        }

        /// <summary>
        /// Measures the wearer and fits the avatar: <paramref name="features"/> of the window(s) averaged, <paramref name="repeatability"/>
        /// the largest difference between two windows (0 for one), added to every uncertainty.
        /// </summary>
        /// <exception cref="ArgumentException">The features are not finite, or the avatar lacks a required bone.</exception>
        public static ProportionFit Fit(HumanoidMap avatar, in BodyFeatures features, ProportionSettings settings, float repeatability = 0f, int windows = 1)
        {
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (!features.IsFinite || !(features.Eye > 0f)) throw new ArgumentException("The wearer's features must be finite with the eyes above the floor.", nameof(features));
            avatar.RequireComplete(nameof(avatar));
            float legBand = settings.PelvisTrackerTolerance + repeatability;

            // Uniform: the paper's scale.
            float s0 = features.Eye / Shape(avatar, BodyProportions.Uniform, 1f).Features.Eye;
            AvatarShape uniform = Shape(avatar, BodyProportions.Uniform, s0);

            // The proportions the measurement gives, every group free and per side.
            // How far a grip may sit above or below the avatar's before it says the arms were not level (a hold, a hand).
            float gripBand = settings.ControllerTolerance + repeatability;
            BodyProportions measured = Solve(avatar, features, BodyProportions.Uniform, s0, true, true, true, gripBand, out float sm, out AvatarShape m);
            float widthBand = m.ShoulderWidth * legBand / Math.Max(0.1f, features.Eye - features.Hips);
            float armBand = settings.ControllerTolerance + 0.5f * widthBand + repeatability;

            var fit = new ProportionFit { Measured = measured, MeasuredScale = sm, Scale = s0 };
            var measurements = new BodyMeasurements
            {
                Windows = windows,
                EyeHeight = new Measurement(features.Eye, settings.HmdTolerance + repeatability),
                HipHeight = new Measurement(features.Hips, legBand),
                LeftLegLength = new Measurement(m.LeftLeg, legBand * m.LeftLeg / Math.Max(1e-3f, m.UpperLegHeight)),
                RightLegLength = new Measurement(m.RightLeg, legBand * m.RightLeg / Math.Max(1e-3f, m.UpperLegHeight)),
                ShoulderHeight = new Measurement(m.ShoulderHeight, settings.ControllerTolerance + repeatability),
                ShoulderWidth = new Measurement(m.ShoulderWidth, widthBand),
                ArmSpan = new Measurement(m.ArmSpan, 2f * settings.ControllerTolerance + repeatability),
                LeftArmLength = new Measurement(m.LeftArm, armBand),
                RightArmLength = new Measurement(m.RightArm, armBand),
            };
            fit.Measurements = measurements;
            if (settings.Mode == ScaleMode.Uniform)
            {
                fit.Explanation = "uniform scaling (ScaleMode.Uniform)";
                return fit;
            }

            // Fitted: only the groups whose feature the uniform avatar misses by more than its uncertainty.
            var why = new StringBuilder();
            float dHips = features.Hips - uniform.Features.Hips;
            bool legs = Math.Abs(dHips) > legBand;
            why.Append(FormattableString.Invariant($"legs {(legs ? "refitted" : "kept")}: hip height {dHips * 100:+0.0;-0.0;0.0} cm from the uniform avatar's (uncertainty {legBand * 100:0.0} cm)"));
            float dLeft = LevelReach(uniform, 1f, features, BodySide.Left, gripBand) - uniform.Features.LeftReach;
            float dRight = LevelReach(uniform, 1f, features, BodySide.Right, gripBand) - uniform.Features.RightReach;
            bool leftArm, rightArm;
            if (settings.PerSide)
            {
                leftArm = Math.Abs(dLeft) > armBand;
                rightArm = Math.Abs(dRight) > armBand;
            }
            else leftArm = rightArm = Math.Abs(0.5f * (dLeft + dRight)) > armBand;
            why.Append(FormattableString.Invariant($"; arms {(leftArm || rightArm ? "refitted" : "kept")}: reach {dLeft * 100:+0.0;-0.0;0.0} / {dRight * 100:+0.0;-0.0;0.0} cm from the uniform avatar's (uncertainty {armBand * 100:0.0} cm)"));

            // Started from the measured proportions (the same groups, averaged over the sides unless per side): a step or two.
            float startArm = settings.PerSide ? 1f : 0.5f * (measured.LeftArm + measured.RightArm);
            var start = new BodyProportions(legs ? measured.LeftLeg : 1f, legs ? measured.RightLeg : 1f,
                leftArm || rightArm ? (settings.PerSide ? measured.LeftArm : startArm) : 1f, leftArm || rightArm ? (settings.PerSide ? measured.RightArm : startArm) : 1f);
            BodyProportions chosen = Solve(avatar, features, start, sm, legs, leftArm || rightArm, settings.PerSide, gripBand, out float s, out _);
            chosen = new BodyProportions(chosen.LeftLeg, chosen.RightLeg, leftArm ? chosen.LeftArm : 1f, rightArm ? chosen.RightArm : 1f);
            var limited = new BodyProportions(Limit(chosen.LeftLeg, settings), Limit(chosen.RightLeg, settings), Limit(chosen.LeftArm, settings), Limit(chosen.RightArm, settings));
            if (!limited.Equals(chosen)) why.Append(FormattableString.Invariant($"; held within {settings.MinRatio:0.00}-{settings.MaxRatio:0.00} of the overall scale ({chosen} measured)"));
            // The overall scale for the ratios kept (a side kept, a ratio limited): the eyes match again.
            if (!limited.IsUniform) Solve(avatar, features, limited, s, false, false, false, gripBand, out s, out _);
            else s = s0;
            // The arms' ratios are of the overall scale, which the legs' fit moves: a kept arm keeps the uniform avatar's
            // length, whose reach matched the wearer's (ratio 1 of the new scale shortened it with the torso: legs held at
            // 1.25, 9.7 cm of reach lost), and is refitted when the torso's new width still makes it miss the reach by more
            // than its uncertainty; refitted arms are solved again (and limited again) when the legs' limit moved the scale after them.
            if (legs)
            {
                float kept = Limit(s0 / s, settings);
                limited = new BodyProportions(limited.LeftLeg, limited.RightLeg, leftArm ? limited.LeftArm : kept, rightArm ? limited.RightArm : kept);
                AvatarShape legsFitted = Shape(avatar, limited, s);
                float missLeft = LevelReach(legsFitted, 1f, features, BodySide.Left, gripBand) - legsFitted.Features.LeftReach;
                float missRight = LevelReach(legsFitted, 1f, features, BodySide.Right, gripBand) - legsFitted.Features.RightReach;
                bool legsLimited = limited.LeftLeg != chosen.LeftLeg || limited.RightLeg != chosen.RightLeg;
                bool againLeft = leftArm ? legsLimited : Math.Abs(settings.PerSide ? missLeft : 0.5f * (missLeft + missRight)) > armBand;
                bool againRight = rightArm ? legsLimited : Math.Abs(settings.PerSide ? missRight : 0.5f * (missLeft + missRight)) > armBand;
                if (againLeft || againRight)
                {
                    BodyProportions again = Solve(avatar, features, limited, s, false, true, settings.PerSide, gripBand, out s, out _);
                    limited = new BodyProportions(limited.LeftLeg, limited.RightLeg, againLeft ? Limit(again.LeftArm, settings) : limited.LeftArm, againRight ? Limit(again.RightArm, settings) : limited.RightArm);
                }
                if (!leftArm || !rightArm)
                    why.Append(FormattableString.Invariant($"; kept arms {(againLeft && !leftArm || againRight && !rightArm ? "refitted after the legs (their reach missed by " + (0.5f * (missLeft + missRight) * 100).ToString("+0.0;-0.0;0.0", System.Globalization.CultureInfo.InvariantCulture) + " cm)" : "at the uniform avatar's length")}"));
            }
            fit.Proportions = limited;
            fit.Scale = s;
            fit.Explanation = why.ToString();
            return fit;
        }

        /// <summary>
        /// The measurements of a skeleton itself (no uncertainty): its lengths, and heights in its canonical T-pose
        /// (<see cref="TPoser"/>). What a wearer's measurements are compared with in evaluation, and what a fitted avatar shows.
        /// </summary>
        public static BodyMeasurements MeasureSkeleton(HumanoidMap map)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            map.RequireComplete(nameof(map));
            AvatarShape m = Shape(map, BodyProportions.Uniform, 1f);
            return new BodyMeasurements
            {
                EyeHeight = new Measurement(m.Features.Eye, 0f), HipHeight = new Measurement(m.Features.Hips, 0f),
                LeftLegLength = new Measurement(m.LeftLeg, 0f), RightLegLength = new Measurement(m.RightLeg, 0f),
                ShoulderHeight = new Measurement(m.ShoulderHeight, 0f), ShoulderWidth = new Measurement(m.ShoulderWidth, 0f),
                ArmSpan = new Measurement(m.ArmSpan, 0f), LeftArmLength = new Measurement(m.LeftArm, 0f), RightArmLength = new Measurement(m.RightArm, 0f),
            };
        }

        private static float Limit(float ratio, ProportionSettings settings) => Math.Min(settings.MaxRatio, Math.Max(settings.MinRatio, ratio));

        /// <summary>The step (m, predicted by the linear model) below which a solve stops: 5 µm, far below what any device resolves.</summary>
        private const float Converged = 5e-6f;

        // Newton steps on a linear model of the avatar's T-pose, each checked against the avatar itself (one T-pose per
        // step). The model: scaling everything by k scales every feature; a leg ratio moves the hip joints, and with them
        // everything above, by the legs' part of the hip-joint height; an arm ratio moves the grip by the arm's part of the
        // reach. Solved exactly for the free groups and the overall scale together (the eyes, and the hips when the legs are
        // free, fix k), so that a few steps land within micrometres where alternating ratio and scale steps took up to
        // sixteen T-poses. The constant parts (eye offset of a rig without eye bones, the grip's handle radius) are what
        // the model leaves out; the steps that follow take them in.
        private static BodyProportions Solve(HumanoidMap avatar, in BodyFeatures wearer, BodyProportions start, float scale, bool legs, bool arms, bool perSide,
            float gripBand, out float finalScale, out AvatarShape shape)
        {
            BodyProportions p = start;
            float s = scale;
            shape = Shape(avatar, p, s);
            for (int it = 0; it < Iterations; it++)
            {
                // The overall factor k: with the legs free, from the eyes-to-hips distance (which the legs do not change);
                // otherwise from the eyes.
                float legPart = shape.UpperLegHeight;
                float k = Clamp(legs ? (wearer.Eye - wearer.Hips) / (shape.Features.Eye - shape.Features.Hips) : wearer.Eye / shape.Features.Eye);
                float leg = p.LeftLeg, la = p.LeftArm, ra = p.RightArm;
                if (legs) leg = p.LeftLeg * Clamp((wearer.Hips / k - (shape.Features.Hips - legPart)) / legPart);
                if (arms)
                {
                    float l = p.LeftArm * Clamp((LevelReach(shape, k, wearer, BodySide.Left, gripBand) - (shape.Features.LeftReach - shape.LeftArmReach)) / shape.LeftArmReach);
                    float r = p.RightArm * Clamp((LevelReach(shape, k, wearer, BodySide.Right, gripBand) - (shape.Features.RightReach - shape.RightArmReach)) / shape.RightArmReach);
                    if (perSide) { la = l; ra = r; }
                    else la = ra = 0.5f * (l + r);
                }
                // How far this step would move the features, in metres: nothing worth a T-pose, so converged.
                float move = Math.Max(Math.Abs(k - 1f) * shape.Features.Eye, Math.Abs(leg / p.LeftLeg - 1f) * legPart);
                move = Math.Max(move, Math.Max(Math.Abs(la / p.LeftArm - 1f) * shape.LeftArmReach, Math.Abs(ra / p.RightArm - 1f) * shape.RightArmReach));
                if (!(move > Converged)) break;
                p = new BodyProportions(leg, leg, la, ra);
                s *= k;
                shape = Shape(avatar, p, s);
            }
            finalScale = s;
            return p;
        }

        // The wearer's reach (in the model's units: divided by k) as it would be with the grip at the model's height: the
        // grip turned about the model's shoulder in the body's frontal plane, keeping its distance from it. A T-pose whose
        // arms droop (the posture check accepts up to about 18°) shortens the horizontal reach by the droop's cosine, which
        // read as short arms (found in review: the wearer's own arms, 15° down, fitted 4.8 % short). Only the part of the
        // height difference beyond gripBand counts: within it, a grip's height says as much about the hold and the model's
        // shoulder as about the arm (a pelvis strap assumed 2 cm off moves the model's shoulders by millimetres).
        private static float LevelReach(in AvatarShape shape, float k, in BodyFeatures wearer, BodySide side, float gripBand)
        {
            float shoulderOut = 0.5f * shape.ShoulderWidth, shoulderUp = shape.ShoulderHeight;
            float modelVertical = shape.Features.GripHeight(side) - shoulderUp;
            float below = wearer.GripHeight(side) / k - shape.Features.GripHeight(side);
            below = Math.Sign(below) * Math.Max(Math.Abs(below) - gripBand, 0f);
            float lateral = wearer.Reach(side) / k - shoulderOut, vertical = modelVertical + below;
            float level = lateral * lateral + vertical * vertical - modelVertical * modelVertical;
            // A grip nearer the shoulder than the model's grip lies below it: no level equivalent; the horizontal reach.
            return level > 0f && lateral > 0f ? shoulderOut + MathF.Sqrt(level) : wearer.Reach(side) / k;
        }

        // A ratio step is never more than a factor of 2 (a wildly wrong feature cannot flip the avatar inside out).
        private static float Clamp(float f) => Vectors.IsFinite(f) ? Math.Min(2f, Math.Max(0.5f, f)) : 1f;

        /// <summary>The avatar with proportions <paramref name="p"/> and overall scale <paramref name="scale"/>, in its T-pose, as features and lengths.</summary>
        internal static AvatarShape Shape(HumanoidMap avatar, BodyProportions p, float scale)
        {
            HumanoidMap fitted = p.Apply(avatar, scale);
            var pose = new SkeletonPose(fitted.Skeleton);
            TPoser.Apply(fitted, pose, RigidPose.Identity);
            RigidPose[] w = pose.World;
            Vector3 eye = TPoser.EyePosition(fitted, pose, Quaternion.Identity);
            Vector3 At(HumanoidBone b) => w[fitted[b]].Position;
            Vector3 lg = Grip(fitted, pose, BodySide.Left), rg = Grip(fitted, pose, BodySide.Right);
            var shape = new AvatarShape
            {
                Features = BodyFeatures.FromDevices(eye, At(HumanoidBone.Hips), lg, rg, 0f, 0f),
                UpperLegHeight = 0.5f * (At(HumanoidBone.LeftUpperLeg).Y + At(HumanoidBone.RightUpperLeg).Y),
                LeftArm = Chain(At(HumanoidBone.LeftUpperArm), At(HumanoidBone.LeftLowerArm), At(HumanoidBone.LeftHand)),
                RightArm = Chain(At(HumanoidBone.RightUpperArm), At(HumanoidBone.RightLowerArm), At(HumanoidBone.RightHand)),
                LeftArmReach = Math.Abs(At(HumanoidBone.LeftHand).X - At(HumanoidBone.LeftUpperArm).X),
                RightArmReach = Math.Abs(At(HumanoidBone.RightHand).X - At(HumanoidBone.RightUpperArm).X),
                LeftLeg = Chain(At(HumanoidBone.LeftUpperLeg), At(HumanoidBone.LeftLowerLeg), At(HumanoidBone.LeftFoot)),
                RightLeg = Chain(At(HumanoidBone.RightUpperLeg), At(HumanoidBone.RightLowerLeg), At(HumanoidBone.RightFoot)),
                ShoulderHeight = 0.5f * (At(HumanoidBone.LeftUpperArm).Y + At(HumanoidBone.RightUpperArm).Y),
                ShoulderWidth = Vector3.Distance(At(HumanoidBone.LeftUpperArm), At(HumanoidBone.RightUpperArm)),
                ArmSpan = Vector3.Distance(At(HumanoidBone.LeftHand), At(HumanoidBone.RightHand)),
            };
            return shape;
        }

        /// <summary>
        /// Where the hand of <paramref name="map"/>'s T-pose <paramref name="pose"/> holds a controller (world): the grip on
        /// the palm the finger bones give, or on the palm estimated for a hand without them (<see cref="HandModel.PalmWithoutFingers"/>).
        /// </summary>
        internal static Vector3 Grip(HumanoidMap map, SkeletonPose pose, BodySide side)
        {
            RigidPose wrist = pose.World[map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]];
            if (HandModel.CanModel(map, side, pose, out _))
            {
                var hand = new HandModel(map, side, pose);
                return (wrist * HandModel.GripPose(hand.PalmCentreInHand, hand.PalmNormalInHand, hand.AcrossInHand, HandleRadius)).Position;
            }
            HandModel.PalmWithoutFingers(map, pose, side, out Vector3 centre, out Vector3 normal, out Vector3 across);
            return HandModel.GripPose(centre, normal, across, HandleRadius).Position;
        }

        /// <summary>
        /// Where a controller (with a handle of <paramref name="handleRadius"/>) held in the hand of <paramref name="map"/>'s
        /// T-pose <paramref name="pose"/> sits (world): the grip on the palm the finger bones give, or on the palm estimated for
        /// a hand without them (<see cref="HandModel.PalmWithoutFingers"/>), as <see cref="Grip"/> places it.
        /// </summary>
        internal static RigidPose GripPose(HumanoidMap map, SkeletonPose pose, BodySide side, float handleRadius)
        {
            RigidPose wrist = pose.World[map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]];
            if (HandModel.CanModel(map, side, pose, out _))
            {
                var hand = new HandModel(map, side, pose);
                return wrist * HandModel.GripPose(hand.PalmCentreInHand, hand.PalmNormalInHand, hand.AcrossInHand, handleRadius);
            }
            HandModel.PalmWithoutFingers(map, pose, side, out Vector3 centre, out Vector3 normal, out Vector3 across);
            return HandModel.GripPose(centre, normal, across, handleRadius);
        }

        /// <summary>The handle radius (m) assumed where no controller profile gives one (2 cm).</summary>
        internal const float DefaultHandleRadius = HandleRadius;

        private static float Chain(Vector3 a, Vector3 b, Vector3 c) => Vector3.Distance(a, b) + Vector3.Distance(b, c);
    }
}
