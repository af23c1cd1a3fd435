using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The fingers under other families' names: the Mixamo clip (the shared clip with finger bones) with its body and its
    /// fingers renamed as 3ds Max Biped (<c>Bip01_L_Finger0</c> the thumb, <c>Finger01</c> its second phalanx), MakeHuman
    /// (<c>finger1-1.L</c> the thumb, <c>finger2-1.L</c> the index), Daz Genesis and Character Creator (<c>lMid1</c>,
    /// <c>CC_Base_L_Mid1</c>), Unity's humanoid bone names (<c>LeftThumbProximal</c>), VRM 1.0 (<c>leftThumbMetacarpal</c>,
    /// <c>leftLittleDistal</c>), Xsens MVN's gloves (<c>LeftFirstMC</c>, <c>LeftSecondPP</c>) and Unreal (<c>index_01_l</c>). Every finger bone is found, so the controller sits in the palm
    /// and the fingers close as on the original; a finger the names miss would leave the hand on the walk-in offset.
    /// </summary>
    public class FingerNamingTests
    {
        private static readonly string[] FingerWords = { "Thumb", "Index", "Middle", "Ring", "Pinky" };

        // A family's name for a Mixamo joint: the body part after "Left"/"Right" (or unsided), or a finger and its phalanx
        // (1 proximal to 3 distal); null keeps Mixamo's name (the eyes and the head's end, which every family reads alike).
        private delegate string Namer(string side, string part, int finger, int phalanx);

        private static readonly Dictionary<string, Namer> Families = new Dictionary<string, Namer>
        {
            ["biped"] = (side, part, f, p) => f >= 0
                ? $"Bip01_{side[0]}_Finger{f}{(p == 1 ? "" : (p - 1).ToString())}"
                : Body(side, part, "Bip01_Pelvis", "Bip01_Spine", "Bip01_Spine1", "Bip01_Spine2", "Bip01_Neck", "Bip01_Head",
                    s => $"Bip01_{s[0]}_", "Clavicle", "UpperArm", "Forearm", "Hand", "Thigh", "Calf", "Foot", "Toe0", ""),
            ["makehuman"] = (side, part, f, p) => f >= 0
                ? $"finger{f + 1}-{p}.{side[0]}"
                : Body(side, part, "root", "spine05", "spine04", "spine03", "neck01", "head",
                    s => "", "clavicle", "upperarm01", "lowerarm01", "wrist", "upperleg01", "lowerleg01", "foot", "toe1-1", side == null ? "" : "." + side[0]),
            ["daz"] = (side, part, f, p) => f >= 0
                ? $"{char.ToLowerInvariant(side[0])}{(f == 2 ? "Mid" : FingerWords[f])}{p}"
                : Body(side, part, "hip", "abdomenLower", "abdomenUpper", "chestUpper", "neckLower", "head",
                    s => char.ToLowerInvariant(s[0]).ToString(), "Collar", "ShldrBend", "ForearmBend", "Hand", "ThighBend", "Shin", "Foot", "Toe", ""),
            ["cc"] = (side, part, f, p) => f >= 0
                ? $"CC_Base_{side[0]}_{(f == 2 ? "Mid" : FingerWords[f])}{p}"
                : Body(side, part, "CC_Base_Hip", "CC_Base_Waist", "CC_Base_Spine01", "CC_Base_Spine02", "CC_Base_NeckTwist01", "CC_Base_Head",
                    s => $"CC_Base_{s[0]}_", "Clavicle", "Upperarm", "Forearm", "Hand", "Thigh", "Calf", "Foot", "ToeBase", ""),
            ["unity"] = (side, part, f, p) => f >= 0
                ? $"{side}{(f == 4 ? "Little" : FingerWords[f])}{new[] { "Proximal", "Intermediate", "Distal" }[p - 1]}"
                : Body(side, part, "Hips", "Spine", "Chest", "UpperChest", "Neck", "Head",
                    s => s, "Shoulder", "UpperArm", "LowerArm", "Hand", "UpperLeg", "LowerLeg", "Foot", "Toes", ""),
            ["vrm1"] = (side, part, f, p) => f >= 0
                ? $"{side.ToLowerInvariant()}{(f == 4 ? "Little" : FingerWords[f])}{(f == 0 ? new[] { "Metacarpal", "Proximal", "Distal" } : new[] { "Proximal", "Intermediate", "Distal" })[p - 1]}"
                : Body(side, part, "hips", "spine", "chest", "upperChest", "neck", "head",
                    s => s.ToLowerInvariant(), "Shoulder", "UpperArm", "LowerArm", "Hand", "UpperLeg", "LowerLeg", "Foot", "Toes", ""),
            ["xsens"] = (side, part, f, p) => f >= 0
                ? $"{side}{new[] { "First", "Second", "Third", "Fourth", "Fifth" }[f]}{(f == 0 ? new[] { "MC", "PP", "DP" } : new[] { "PP", "MP", "DP" })[p - 1]}"
                : Body(side, part, "Pelvis", "L3", "T12", "T8", "Neck", "Head",
                    s => s, "Shoulder", "UpperArm", "ForeArm", "Hand", "UpperLeg", "LowerLeg", "Foot", "Toe", ""),
            ["unreal"] = (side, part, f, p) => f >= 0
                ? $"{FingerWords[f].ToLowerInvariant()}_0{p}_{char.ToLowerInvariant(side[0])}"
                : Body(side, part, "pelvis", "spine_01", "spine_02", "spine_03", "neck_01", "head",
                    s => "", "clavicle", "upperarm", "lowerarm", "hand", "thigh", "calf", "foot", "ball", side == null ? "" : "_" + char.ToLowerInvariant(side[0])),
        };

        // The body's names: the six unsided joints hips to head, then a sided prefix, the sided parts in Mixamo's order
        // (Shoulder, Arm, ForeArm, Hand, UpLeg, Leg, Foot, ToeBase) and a sided suffix.
        private static string Body(string side, string part, string hips, string spine, string spine1, string spine2, string neck, string head,
            Func<string, string> prefix, string shoulder, string arm, string foreArm, string hand, string upLeg, string leg, string foot, string toes, string suffix)
        {
            if (side == null)
                return part switch { "Hips" => hips, "Spine" => spine, "Spine1" => spine1, "Spine2" => spine2, "Neck" => neck, "Head" => head, _ => null };
            string name = part switch
            {
                "Shoulder" => shoulder, "Arm" => arm, "ForeArm" => foreArm, "Hand" => hand,
                "UpLeg" => upLeg, "Leg" => leg, "Foot" => foot, "ToeBase" => toes, _ => null,
            };
            return name == null ? null : prefix(side) + name + suffix;
        }

        private static readonly Regex MixamoJoint = new Regex(@"^mixamorig:(Left|Right)?(?:Hand(Thumb|Index|Middle|Ring|Pinky)([1-3])|(\w+))$");

        /// <summary>The Mixamo clip with every joint renamed by <paramref name="family"/>'s rules, read in metres.</summary>
        private static BvhClip Renamed(string text, Namer family)
        {
            string renamed = Regex.Replace(text, @"^(\s*(?:ROOT|JOINT)\s+)(\S+)", m =>
            {
                Match joint = MixamoJoint.Match(m.Groups[2].Value);
                if (!joint.Success) return m.Value;
                string side = joint.Groups[1].Success ? joint.Groups[1].Value : null;
                string name = joint.Groups[2].Success
                    ? family(side, null, Array.IndexOf(FingerWords, joint.Groups[2].Value), int.Parse(joint.Groups[3].Value))
                    : family(side, joint.Groups[4].Value, -1, 0);
                return m.Groups[1].Value + (name ?? m.Groups[2].Value);
            }, RegexOptions.Multiline);
            Assert.That(renamed, Is.Not.EqualTo(text));
            return BvhReader.Read(new StringReader(renamed), "renamed", new BvhReadOptions { ToMetres = true });
        }

        // The palm on the VIVE wand (the default placement, which needs the fingers), as `avatargo evaluate` runs it.
        private static EvaluationReport Evaluate(BvhClip clip)
        {
            ControllerProfile wand = RestConventionTests.ViveWand();
            using SessionReader reader = Sessions.Read(Sessions.Simulate(clip, new SimulationOptions { Seed = 2, Controller = wand }));
            var settings = new PipelineSettings();
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                settings.Hand(side).Controller = wand;
                settings.Hand(side).Placement = HandPlacement.PalmOnController;
            }
            return SessionEvaluator.Evaluate(reader, settings);
        }

        [TestCase("biped"), TestCase("makehuman"), TestCase("daz"), TestCase("cc"), TestCase("unity"), TestCase("vrm1"), TestCase("xsens"), TestCase("unreal")]
        public void AnotherFamilysFingerNamesGiveTheSameHands(string family)
        {
            string text = File.ReadAllText(TestData.Mocap("mixamo_fingers_30fps.bvh"));
            BvhClip original = BvhReader.Read(new StringReader(text), "original", new BvhReadOptions { ToMetres = true });
            BvhClip renamed = Renamed(text, Families[family]);
            HumanoidMap a = HumanoidNaming.Detect(original.Skeleton), b = HumanoidNaming.Detect(renamed.Skeleton);
            int fingers = 0;
            for (int bone = 0; bone < HumanoidBones.Count; bone++)
            {
                Assert.That(b[(HumanoidBone)bone], Is.EqualTo(a[(HumanoidBone)bone]),
                    $"{family}: {(HumanoidBone)bone} is the same joint ({(b.Has((HumanoidBone)bone) ? renamed.Skeleton.GetName(b[(HumanoidBone)bone]) : "missing")})");
                if (HumanoidBones.IsFinger((HumanoidBone)bone) && a.Has((HumanoidBone)bone)) fingers++;
            }
            Assert.That(fingers, Is.EqualTo(30), "the original's fingers: five of three phalanges on each hand");
            EvaluationReport own = Evaluate(original), other = Evaluate(renamed);
            Assert.That(other.Profile, Is.Not.Null, $"{family}: {other.CalibrationMessage}");
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.01), $"{family}: MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.01), $"{family}: end effectors median (mm)");
            Assert.That(other.EndEffectorMm.P95, Is.EqualTo(own.EndEffectorMm.P95).Within(0.01), $"{family}: end effectors p95 (mm)");
        }
    }
}
