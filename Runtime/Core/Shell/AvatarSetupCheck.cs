using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Checks an avatar before it is driven, the way the avatar inspector shows it: is it a humanoid with the bones the
    /// pipeline needs, which hands get finger IK, is its scale one the calibration can work with, and is its Animator
    /// set up so IK runs every frame, and would the calibrator bind it (<see cref="AvatarFacts.BindError"/>). Engine-free: the inspector fills <see cref="AvatarFacts"/> and draws the findings.
    /// </summary>
    public static class AvatarSetupCheck
    {
        /// <summary>The shortest head-above-feet height taken for a person's avatar (a small child's, in metres).</summary>
        public const float ShortestPlausibleHeight = 0.5f;

        /// <summary>The tallest head-above-feet height taken for a person's avatar, in metres.</summary>
        public const float TallestPlausibleHeight = 2.6f;

        /// <summary>How far the scale's axes may differ (relative) before it counts as non-uniform.</summary>
        public const float UniformScaleTolerance = 0.01f;

        /// <summary>Checks <paramref name="facts"/>; errors first, then warnings, then information.</summary>
        public static IReadOnlyList<SetupFinding> Check(AvatarFacts facts)
        {
            if (facts == null) throw new ArgumentNullException(nameof(facts));
            var findings = new List<SetupFinding>();
            if (!facts.HasAnimator)
                findings.Add(new SetupFinding(SetupSeverity.Error, "The avatar has no Animator. Assign the object that carries the model's Animator (the root of an imported humanoid model)."));
            else if (!facts.HasAvatar)
                findings.Add(new SetupFinding(SetupSeverity.Error, "The Animator has no Avatar. In the model's import settings, Rig tab, set Animation Type to Humanoid and Avatar Definition to Create From This Model, then Apply."));
            else if (!facts.AvatarIsValid || !facts.AvatarIsHuman)
                findings.Add(new SetupFinding(SetupSeverity.Error, "The Avatar is not a valid humanoid. In the model's import settings, Rig tab, set Animation Type to Humanoid, press Configure and fix the bones it marks red."));
            else
            {
                CheckBones(facts, findings);
                CheckScale(facts, findings);
                // What the binding refuses and no finding above names (its scale tolerance is 0.1 %, and it checks every bone's).
                if (!string.IsNullOrEmpty(facts.BindError) && !findings.Exists(f => f.Severity == SetupSeverity.Error))
                    findings.Add(new SetupFinding(SetupSeverity.Error, $"The calibrator cannot bind this avatar and disables itself when Play starts: {facts.BindError}."));
                if (!facts.CullsAlwaysAnimate)
                    findings.Add(new SetupFinding(SetupSeverity.Warning, "The Animator's Culling Mode is not Always Animate: IK stops whenever the avatar is out of every camera's view (the wearer's own body often is).", SetupFix.CullAlwaysAnimate));
                if (facts.AppliesRootMotion)
                    findings.Add(new SetupFinding(SetupSeverity.Warning, "The Animator applies root motion: the animation would move the avatar away from the wearer. Turn Apply Root Motion off.", SetupFix.DisableRootMotion));
            }
            findings.Sort((a, b) => b.Severity.CompareTo(a.Severity));
            return findings;
        }

        private static void CheckBones(AvatarFacts facts, List<SetupFinding> findings)
        {
            var missing = new List<string>();
            foreach (HumanoidBone bone in HumanoidBones.Required)
                if (!facts.Bones.Contains(bone)) missing.Add(bone.ToString());
            if (missing.Count > 0)
                findings.Add(new SetupFinding(SetupSeverity.Error, $"The Animator returns no transform for {string.Join(", ", missing)}. Map them in the Avatar's Configure window."));
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int found = 0, total = 0;
                for (Finger finger = Finger.Thumb; finger <= Finger.Little; finger++)
                    for (Phalanx phalanx = Phalanx.Proximal; phalanx <= Phalanx.Distal; phalanx++)
                    {
                        total++;
                        if (facts.Bones.Contains(HumanoidBones.Finger(side, finger, phalanx))) found++;
                    }
                string hand = side == BodySide.Left ? "left" : "right";
                if (found == 0)
                    findings.Add(new SetupFinding(SetupSeverity.Info, $"The {hand} hand has no finger bones: it holds the controller without closing its fingers."));
                else if (!HandModel.CanModelFromBones(facts.Bones.Contains, side, out string reason))
                    findings.Add(new SetupFinding(SetupSeverity.Warning, $"The {hand} hand has {found} of {total} finger bones but no finger IK: {reason}. Map the missing bones in the Avatar's Configure window if the model has them."));
                else if (found < total)
                    findings.Add(new SetupFinding(SetupSeverity.Info, $"The {hand} hand has {found} of {total} finger bones: the fingers without all three bones stay open."));
            }
            if (!facts.Bones.Contains(HumanoidBone.Chest))
                findings.Add(new SetupFinding(SetupSeverity.Info, "The avatar has no chest bone: the spine bends in fewer places."));
        }

        private static void CheckScale(AvatarFacts facts, List<SetupFinding> findings)
        {
            Vector3 s = facts.LossyScale;
            float largest = Math.Max(Math.Abs(s.X), Math.Max(Math.Abs(s.Y), Math.Abs(s.Z)));
            float smallest = Math.Min(Math.Abs(s.X), Math.Min(Math.Abs(s.Y), Math.Abs(s.Z)));
            if (!(smallest > 0f) || !Vectors.IsFinite(s))
                findings.Add(new SetupFinding(SetupSeverity.Error, $"The avatar's scale {Format(s)} has a zero or invalid axis."));
            else if (s.X < 0f || s.Y < 0f || s.Z < 0f)
                findings.Add(new SetupFinding(SetupSeverity.Error, $"The avatar's scale {Format(s)} mirrors it: left and right would swap. Use a positive scale."));
            else if (largest - smallest > UniformScaleTolerance * largest)
                findings.Add(string.IsNullOrEmpty(facts.BindError)
                    ? new SetupFinding(SetupSeverity.Warning, $"The avatar's scale {Format(s)} is not uniform: bones stretch as they turn. Calibration scales the avatar uniformly to the wearer anyway.", SetupFix.MakeScaleUniform)
                    : new SetupFinding(SetupSeverity.Error, $"The avatar's scale {Format(s)} is not uniform, and the calibrator cannot bind it: {facts.BindError}.", SetupFix.MakeScaleUniform));
            // Without the head or both feet there is no height to judge (the missing bones are reported already).
            if (!facts.Bones.Contains(HumanoidBone.Head) || !(facts.Bones.Contains(HumanoidBone.LeftFoot) || facts.Bones.Contains(HumanoidBone.RightFoot))) return;
            float h = facts.HeadAboveFeet;
            if (float.IsNaN(h) || h < ShortestPlausibleHeight || h > TallestPlausibleHeight)
            {
                string likely = h > 0f && h < ShortestPlausibleHeight / 10f ? " (it looks like a model in metres scaled by 0.01: check the import's Scale Factor)"
                    : h > TallestPlausibleHeight * 10f ? " (it looks like a model in centimetres: set the import's Scale Factor to 0.01 or enable Convert Units)"
                    : string.Empty;
                findings.Add(new SetupFinding(SetupSeverity.Warning, $"The avatar's head is {h:0.###} m above its feet{likely}. Calibration scales it to the wearer, but lighting, physics and the mirror see the imported size."));
            }
        }

        private static string Format(Vector3 v) => $"({v.X:0.###}, {v.Y:0.###}, {v.Z:0.###})";
    }
}
