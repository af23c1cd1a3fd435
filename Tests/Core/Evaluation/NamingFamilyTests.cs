using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The same motion under the joint names of other skeleton families: the MocapBank clip with every joint renamed as
    /// SMPL, Xsens MVN, Bandai Namco, Daz Genesis, 3ds Max Biped (as BVH writes it), VRoid/VRM, HumanIK, Character Creator,
    /// Unreal, Rigify's deform bones (DEF-, the neck and head numbered spine joints), MakeHuman, OptiTrack Motive, Kinect v2
    /// and Azure Kinect name them (the Kinects' clavicle-less v2 names given a ClavicleLeft for the clip's collar). The
    /// names find the same humanoid bones (<see cref="HumanoidNaming"/>), so calibration succeeds and every figure is the
    /// original's: a family the names miss would not calibrate at all.
    /// </summary>
    public class NamingFamilyTests
    {
        private static readonly string[] Joints =
        {
            "Hips", "Chest", "Chest2", "LeftCollar", "LeftShoulder", "LeftElbow", "LeftWrist", "RightCollar", "RightShoulder", "RightElbow",
            "RightWrist", "Neck", "Head", "LeftHip", "LeftKnee", "LeftAnkle", "RightHip", "RightKnee", "RightAnkle",
        };

        // Each family's names for the joints above, in that order.
        private static readonly Dictionary<string, string[]> Families = new Dictionary<string, string[]>
        {
            ["smpl"] = new[] { "Pelvis", "Spine1", "Spine3", "L_Collar", "L_Shoulder", "L_Elbow", "L_Wrist", "R_Collar", "R_Shoulder", "R_Elbow", "R_Wrist", "Neck", "Head", "L_Hip", "L_Knee", "L_Ankle", "R_Hip", "R_Knee", "R_Ankle" },
            ["xsens"] = new[] { "Pelvis", "T12", "T8", "LeftShoulder", "LeftUpperArm", "LeftForeArm", "LeftHand", "RightShoulder", "RightUpperArm", "RightForeArm", "RightHand", "Neck", "Head", "LeftUpperLeg", "LeftLowerLeg", "LeftFoot", "RightUpperLeg", "RightLowerLeg", "RightFoot" },
            ["bandai"] = new[] { "Hips", "Spine", "Chest", "Shoulder_L", "UpperArm_L", "LowerArm_L", "Hand_L", "Shoulder_R", "UpperArm_R", "LowerArm_R", "Hand_R", "Neck", "Head", "UpperLeg_L", "LowerLeg_L", "Foot_L", "UpperLeg_R", "LowerLeg_R", "Foot_R" },
            ["daz"] = new[] { "hip", "abdomenLower", "chestUpper", "lCollar", "lShldrBend", "lForearmBend", "lHand", "rCollar", "rShldrBend", "rForearmBend", "rHand", "neckLower", "head", "lThighBend", "lShin", "lFoot", "rThighBend", "rShin", "rFoot" },
            ["biped"] = new[] { "Bip01_Pelvis", "Bip01_Spine", "Bip01_Spine1", "Bip01_L_Clavicle", "Bip01_L_UpperArm", "Bip01_L_Forearm", "Bip01_L_Hand", "Bip01_R_Clavicle", "Bip01_R_UpperArm", "Bip01_R_Forearm", "Bip01_R_Hand", "Bip01_Neck", "Bip01_Head", "Bip01_L_Thigh", "Bip01_L_Calf", "Bip01_L_Foot", "Bip01_R_Thigh", "Bip01_R_Calf", "Bip01_R_Foot" },
            ["vroid"] = new[] { "J_Bip_C_Hips", "J_Bip_C_Spine", "J_Bip_C_Chest", "J_Bip_L_Shoulder", "J_Bip_L_UpperArm", "J_Bip_L_LowerArm", "J_Bip_L_Hand", "J_Bip_R_Shoulder", "J_Bip_R_UpperArm", "J_Bip_R_LowerArm", "J_Bip_R_Hand", "J_Bip_C_Neck", "J_Bip_C_Head", "J_Bip_L_UpperLeg", "J_Bip_L_LowerLeg", "J_Bip_L_Foot", "J_Bip_R_UpperLeg", "J_Bip_R_LowerLeg", "J_Bip_R_Foot" },
            ["humanik"] = new[] { "Character1_Hips", "Character1_Spine", "Character1_Spine1", "Character1_LeftShoulder", "Character1_LeftArm", "Character1_LeftForeArm", "Character1_LeftHand", "Character1_RightShoulder", "Character1_RightArm", "Character1_RightForeArm", "Character1_RightHand", "Character1_Neck", "Character1_Head", "Character1_LeftUpLeg", "Character1_LeftLeg", "Character1_LeftFoot", "Character1_RightUpLeg", "Character1_RightLeg", "Character1_RightFoot" },
            ["cc"] = new[] { "CC_Base_Hip", "CC_Base_Waist", "CC_Base_Spine01", "CC_Base_L_Clavicle", "CC_Base_L_Upperarm", "CC_Base_L_Forearm", "CC_Base_L_Hand", "CC_Base_R_Clavicle", "CC_Base_R_Upperarm", "CC_Base_R_Forearm", "CC_Base_R_Hand", "CC_Base_NeckTwist01", "CC_Base_Head", "CC_Base_L_Thigh", "CC_Base_L_Calf", "CC_Base_L_Foot", "CC_Base_R_Thigh", "CC_Base_R_Calf", "CC_Base_R_Foot" },
            ["rigify-def"] = new[] { "DEF-spine", "DEF-spine.001", "DEF-spine.003", "DEF-shoulder.L", "DEF-upper_arm.L", "DEF-forearm.L", "DEF-hand.L", "DEF-shoulder.R", "DEF-upper_arm.R", "DEF-forearm.R", "DEF-hand.R", "DEF-spine.004", "DEF-spine.006", "DEF-thigh.L", "DEF-shin.L", "DEF-foot.L", "DEF-thigh.R", "DEF-shin.R", "DEF-foot.R" },
            ["makehuman"] = new[] { "root", "spine05", "spine01", "clavicle.L", "upperarm01.L", "lowerarm01.L", "wrist.L", "clavicle.R", "upperarm01.R", "lowerarm01.R", "wrist.R", "neck01", "head", "upperleg01.L", "lowerleg01.L", "foot.L", "upperleg01.R", "lowerleg01.R", "foot.R" },
            ["optitrack"] = new[] { "Hip", "Ab", "Chest", "LShoulder", "LUArm", "LFArm", "LHand", "RShoulder", "RUArm", "RFArm", "RHand", "Neck", "Head", "LThigh", "LShin", "LFoot", "RThigh", "RShin", "RFoot" },
            ["kinect"] = new[] { "SpineBase", "SpineMid", "SpineShoulder", "ClavicleLeft", "ShoulderLeft", "ElbowLeft", "WristLeft", "ClavicleRight", "ShoulderRight", "ElbowRight", "WristRight", "Neck", "Head", "HipLeft", "KneeLeft", "AnkleLeft", "HipRight", "KneeRight", "AnkleRight" },
            ["azure-kinect"] = new[] { "PELVIS", "SPINE_NAVEL", "SPINE_CHEST", "CLAVICLE_LEFT", "SHOULDER_LEFT", "ELBOW_LEFT", "WRIST_LEFT", "CLAVICLE_RIGHT", "SHOULDER_RIGHT", "ELBOW_RIGHT", "WRIST_RIGHT", "NECK", "HEAD", "HIP_LEFT", "KNEE_LEFT", "ANKLE_LEFT", "HIP_RIGHT", "KNEE_RIGHT", "ANKLE_RIGHT" },
            ["unreal"] = new[] { "pelvis", "spine_01", "spine_02", "clavicle_l", "upperarm_l", "lowerarm_l", "hand_l", "clavicle_r", "upperarm_r", "lowerarm_r", "hand_r", "neck_01", "head", "thigh_l", "calf_l", "foot_l", "thigh_r", "calf_r", "foot_r" },
        };

        /// <summary>A family's names for the MocapBank clip's joints.</summary>
        internal static string[] FamilyNames(string family) => Families[family];

        /// <summary>The MocapBank clip's text with its joints renamed to <paramref name="names"/> (in <see cref="Joints"/>' order), read in metres.</summary>
        internal static BvhClip Renamed(string text, string[] names)
        {
            var rename = new Dictionary<string, string>();
            for (int i = 0; i < Joints.Length; i++) rename[Joints[i]] = names[i];
            string renamed = Regex.Replace(text, @"^(\s*(?:ROOT|JOINT)\s+)(\S+)", m => m.Groups[1].Value + (rename.TryGetValue(m.Groups[2].Value, out string n) ? n : m.Groups[2].Value), RegexOptions.Multiline);
            return BvhReader.Read(new StringReader(renamed), "renamed", new BvhReadOptions { ToMetres = true });
        }

        private static EvaluationReport Evaluate(BvhClip clip)
        {
            using SessionReader reader = Sessions.Read(Sessions.Simulate(clip, new SimulationOptions { Seed = 2 }));
            return SessionEvaluator.Evaluate(reader, new PipelineSettings());
        }

        [TestCase("smpl"), TestCase("xsens"), TestCase("bandai"), TestCase("daz"), TestCase("biped"), TestCase("vroid"), TestCase("humanik"), TestCase("cc"), TestCase("unreal"), TestCase("rigify-def"), TestCase("makehuman"), TestCase("optitrack"), TestCase("kinect"), TestCase("azure-kinect")]
        public void AnotherFamilysNamesGiveTheSameAvatar(string family)
        {
            string text = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip original = BvhReader.Read(new StringReader(text), "original", new BvhReadOptions { ToMetres = true });
            BvhClip renamed = Renamed(text, Families[family]);
            HumanoidMap a = HumanoidNaming.Detect(original.Skeleton), b = HumanoidNaming.Detect(renamed.Skeleton);
            Assert.That(b.MissingRequired(), Is.Empty, family);
            for (int bone = 0; bone < HumanoidBones.Count; bone++)
                Assert.That(b[(HumanoidBone)bone], Is.EqualTo(a[(HumanoidBone)bone]), $"{family}: {(HumanoidBone)bone} is the same joint");
            EvaluationReport own = Evaluate(original), other = Evaluate(renamed);
            Assert.That(other.Profile, Is.Not.Null, $"{family}: {other.CalibrationMessage}");
            Assert.That(other.Frames, Is.EqualTo(own.Frames));
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(0.01), $"{family}: MPJPE (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(0.01), $"{family}: elbows and knees median (mm)");
        }

        /// <summary>
        /// The CMU database as most people get it, its BVH conversion: <c>Hips</c>, then <c>LHipJoint</c> (at the hips) above
        /// <c>LeftUpLeg</c>, <c>LeftLeg</c>, <c>LeftFoot</c>; <c>LowerBack</c> (at the hips) above <c>Spine</c> and
        /// <c>Spine1</c>, which carries <c>LeftShoulder</c> (the clavicle), <c>LeftArm</c>, <c>LeftForeArm</c>, <c>LeftHand</c>
        /// and <c>Neck</c>, <c>Neck1</c>, <c>Head</c>. The hip joints are not the thighs and the second neck joint is not the
        /// head. The spine gains a joint at the hips (Spine is LowerBack, as Unity's humanoid maps it), so the back bends from
        /// lower down and one more joint is measured: MPJPE 17.81 → 19.59 mm, elbows and knees median 32.2 → 35.9 mm (seed 2),
        /// end effectors unchanged (the neck's target, which the spine is bent again to reach, is 20 mm off since the wearer
        /// calibrates looking straight ahead, and a back that bends from the hips carries that into the chest: 17.26 → 17.88
        /// and 43.3 → 41.7 mm before; the CMU names with the original spine, Neck1 alone, give the original's figures).
        /// Since the back flexes about the hip line with a stiffness (2026-12-02), 17.47 → 19.71 mm: the original gained
        /// 0.34 mm, the CMU spine lost 0.12 (its flexion starts a joint lower), so the bound is 2.5 mm, was 2; elbows and
        /// knees 30.3 → 36.0 mm (the original's gained 1.9 mm, the CMU's none), bound 6 mm, was 4. Since the knees follow
        /// the outer plane (session 15), 14.02 → 16.76 mm (17.42 → 19.48 with the planes added): the kneeling knees, which
        /// sat 13–15 cm off at p95 in both, now sit 64 / 64 mm and 66 / 83 mm off (their p95 differed by 10–15 mm between the
        /// two hierarchies before too), so the bound is 3 mm, was 2.5.
        /// </summary>
        [Test]
        public void TheCmuDatabasesBvhConversionGivesTheSameAvatar()
        {
            string text = File.ReadAllText(TestData.Mocap("mocapbank_30fps.bvh"));
            BvhClip original = BvhReader.Read(new StringReader(text), "original", new BvhReadOptions { ToMetres = true });
            var names = new Dictionary<string, string>
            {
                ["Chest"] = "Spine", ["Chest2"] = "Spine1", ["LeftCollar"] = "LeftShoulder", ["LeftShoulder"] = "LeftArm", ["LeftElbow"] = "LeftForeArm",
                ["LeftWrist"] = "LeftHand", ["RightCollar"] = "RightShoulder", ["RightShoulder"] = "RightArm", ["RightElbow"] = "RightForeArm",
                ["RightWrist"] = "RightHand", ["LeftHip"] = "LeftUpLeg", ["LeftKnee"] = "LeftLeg", ["LeftAnkle"] = "LeftFoot",
                ["RightHip"] = "RightUpLeg", ["RightKnee"] = "RightLeg", ["RightAnkle"] = "RightFoot",
            };
            string renamed = Regex.Replace(text, @"^(\s*(?:ROOT|JOINT)\s+)(\S+)", m => m.Groups[1].Value + (names.TryGetValue(m.Groups[2].Value, out string n) ? n : m.Groups[2].Value), RegexOptions.Multiline);
            BvhClip cmu = Topology.WithJointsAbove(BvhReader.Read(new StringReader(renamed), "cmu", new BvhReadOptions { ToMetres = true }),
                ("LeftUpLeg", "LHipJoint", 0f), ("RightUpLeg", "RHipJoint", 0f), ("Spine", "LowerBack", 0f), ("Head", "Neck1", 0.5f));

            HumanoidMap a = HumanoidNaming.Detect(original.Skeleton), b = HumanoidNaming.Detect(cmu.Skeleton);
            Assert.That(b.MissingRequired(), Is.Empty);
            for (int bone = 0; bone < HumanoidBones.Count; bone++)
            {
                var humanoid = (HumanoidBone)bone;
                if (humanoid == HumanoidBone.Spine || humanoid == HumanoidBone.Chest || humanoid == HumanoidBone.UpperChest) continue;
                string expected = a.Has(humanoid) ? original.Skeleton.GetName(a[humanoid]) : null;
                string found = b.Has(humanoid) ? cmu.Skeleton.GetName(b[humanoid]) : null;
                Assert.That(found, Is.EqualTo(expected == null ? null : names.TryGetValue(expected, out string n) ? n : expected), humanoid.ToString());
            }
            Assert.That(new[] { b[HumanoidBone.Spine], b[HumanoidBone.Chest], b[HumanoidBone.UpperChest] }.Select(j => cmu.Skeleton.GetName(j)),
                Is.EqualTo(new[] { "LowerBack", "Spine", "Spine1" }), "the spine: the unsided joints between the hips and the neck");

            EvaluationReport own = Evaluate(original), other = Evaluate(cmu);
            Assert.That(other.Profile, Is.Not.Null, other.CalibrationMessage);
            Assert.That(other.AllJointsMm.Mean, Is.EqualTo(own.AllJointsMm.Mean).Within(3.0), "MPJPE (mm)");
            Assert.That(other.EndEffectorMm.Median, Is.EqualTo(own.EndEffectorMm.Median).Within(0.1), "end effectors median (mm)");
            Assert.That(other.MidJointMm.Median, Is.EqualTo(own.MidJointMm.Median).Within(6.0), "elbows and knees median (mm)");
        }
}
}
