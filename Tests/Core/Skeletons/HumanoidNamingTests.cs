using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class HumanoidNamingTests
    {
        // Builds a skeleton from "name<parent" entries (parent omitted for the root); "name!" marks an end site.
        private static Skeleton Build(params string[] entries)
        {
            var names = new List<string>();
            var parents = new List<int>();
            var ends = new List<bool>();
            var rest = new List<RigidPose>();
            foreach (string e in entries)
            {
                string[] parts = e.Split('<');
                string name = parts[0];
                bool end = name.EndsWith("!", StringComparison.Ordinal);
                if (end) name = name.Substring(0, name.Length - 1);
                names.Add(name);
                parents.Add(parts.Length > 1 ? names.IndexOf(parts[1]) : -1);
                ends.Add(end);
                rest.Add(RigidPose.Identity);
            }
            return new Skeleton(names, parents, rest, ends);
        }

        private static void Expect(HumanoidMap map, params string[] boneEqualsJoint)
        {
            foreach (string pair in boneEqualsJoint)
            {
                string[] p = pair.Split('=');
                var bone = (HumanoidBone)Enum.Parse(typeof(HumanoidBone), p[0]);
                Assert.That(map.NameOf(bone), Is.EqualTo(p[1]), p[0]);
            }
            AssertConsistent(map);
        }

        private static void AssertConsistent(HumanoidMap map)
        {
            var seen = new HashSet<int>();
            for (int b = 0; b < HumanoidBones.Count; b++)
            {
                int j = map[(HumanoidBone)b];
                if (j >= 0) Assert.That(seen.Add(j), Is.True, $"joint {j} plays two bones");
            }
        }

        private static string[] Mixamo(string ns) => new[]
        {
            ns + "Hips", ns + "Spine<" + ns + "Hips", ns + "Spine1<" + ns + "Spine", ns + "Spine2<" + ns + "Spine1",
            ns + "Neck<" + ns + "Spine2", ns + "Head<" + ns + "Neck", ns + "HeadTop_End<" + ns + "Head",
            ns + "LeftShoulder<" + ns + "Spine2", ns + "LeftArm<" + ns + "LeftShoulder", ns + "LeftForeArm<" + ns + "LeftArm",
            ns + "LeftHand<" + ns + "LeftForeArm", ns + "LeftHandIndex1<" + ns + "LeftHand", ns + "LeftHandIndex2<" + ns + "LeftHandIndex1",
            ns + "LeftHandIndex3<" + ns + "LeftHandIndex2", ns + "LeftHandIndex4<" + ns + "LeftHandIndex3",
            ns + "RightShoulder<" + ns + "Spine2", ns + "RightArm<" + ns + "RightShoulder", ns + "RightForeArm<" + ns + "RightArm",
            ns + "RightHand<" + ns + "RightForeArm", ns + "RightHandThumb1<" + ns + "RightHand",
            ns + "LeftUpLeg<" + ns + "Hips", ns + "LeftLeg<" + ns + "LeftUpLeg", ns + "LeftFoot<" + ns + "LeftLeg", ns + "LeftToeBase<" + ns + "LeftFoot",
            ns + "RightUpLeg<" + ns + "Hips", ns + "RightLeg<" + ns + "RightUpLeg", ns + "RightFoot<" + ns + "RightLeg",
        };

        [TestCase("mixamorig:")]
        [TestCase("mixamorig7:")]
        [TestCase("")]
        public void Mixamo_AnyNamespace(string ns)
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(Mixamo(ns)));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, $"Hips={ns}Hips", $"Spine={ns}Spine", $"Chest={ns}Spine1", $"UpperChest={ns}Spine2",
                $"Neck={ns}Neck", $"Head={ns}Head", $"LeftShoulder={ns}LeftShoulder", $"LeftUpperArm={ns}LeftArm",
                $"LeftLowerArm={ns}LeftForeArm", $"LeftHand={ns}LeftHand", $"LeftIndexProximal={ns}LeftHandIndex1",
                $"LeftIndexDistal={ns}LeftHandIndex3", $"RightThumbProximal={ns}RightHandThumb1",
                $"LeftUpperLeg={ns}LeftUpLeg", $"LeftLowerLeg={ns}LeftLeg", $"LeftFoot={ns}LeftFoot", $"LeftToes={ns}LeftToeBase",
                $"RightFoot={ns}RightFoot");
            Assert.That(map.BoneOf(map.Skeleton.IndexOf(ns + "LeftHandIndex4")), Is.EqualTo(HumanoidBone.LastBone));
        }

        [Test]
        public void LaFan()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg", "LeftFoot<LeftLeg", "LeftToe<LeftFoot",
                "RightUpLeg<Hips", "RightLeg<RightUpLeg", "RightFoot<RightLeg", "RightToe<RightFoot",
                "Spine<Hips", "Spine1<Spine", "Spine2<Spine1", "Neck<Spine2", "Head<Neck",
                "LeftShoulder<Spine2", "LeftArm<LeftShoulder", "LeftForeArm<LeftArm", "LeftHand<LeftForeArm",
                "RightShoulder<Spine2", "RightArm<RightShoulder", "RightForeArm<RightArm", "RightHand<RightForeArm"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "LeftShoulder=LeftShoulder", "LeftUpperArm=LeftArm", "RightToes=RightToe", "UpperChest=Spine2",
                "LeftLowerLeg=LeftLeg", "RightHand=RightHand");
        }

        [Test]
        public void Cmu_ShoulderIsTheUpperArmWhenThereIsACollar()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "Chest<Hips", "Chest2<Chest", "Neck<Chest2", "Head<Neck",
                "LeftCollar<Chest2", "LeftShoulder<LeftCollar", "LeftElbow<LeftShoulder", "LeftWrist<LeftElbow",
                "RightCollar<Chest2", "RightShoulder<RightCollar", "RightElbow<RightShoulder", "RightWrist<RightElbow",
                "LeftHip<Hips", "LeftKnee<LeftHip", "LeftAnkle<LeftKnee", "RightHip<Hips", "RightKnee<RightHip", "RightAnkle<RightKnee"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=Hips", "Spine=Chest", "Chest=Chest2", "LeftShoulder=LeftCollar", "LeftUpperArm=LeftShoulder",
                "LeftLowerArm=LeftElbow", "LeftHand=LeftWrist", "RightUpperLeg=RightHip", "RightLowerLeg=RightKnee", "RightFoot=RightAnkle");
        }

        [Test]
        public void Cmu_ShoulderIsTheUpperArmWhenItsChildIsAnElbowEvenWithoutCollar()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "Chest<Hips", "Neck<Chest", "Head<Neck",
                "LeftShoulder<Chest", "LeftElbow<LeftShoulder", "LeftWrist<LeftElbow",
                "RightShoulder<Chest", "RightElbow<RightShoulder", "RightWrist<RightElbow",
                "LeftHip<Hips", "LeftKnee<LeftHip", "LeftAnkle<LeftKnee", "RightHip<Hips", "RightKnee<RightHip", "RightAnkle<RightKnee"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "LeftUpperArm=LeftShoulder", "RightUpperArm=RightShoulder", "Spine=Chest");
            Assert.That(map.Has(HumanoidBone.LeftShoulder), Is.False);
        }

        [Test]
        public void Rigify_WithHandsFingersAndSidedPelvis()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "pelvis", "pelvis.L<pelvis", "pelvis.R<pelvis", "spine<pelvis", "spine.001<spine", "spine.002<spine.001",
                "neck<spine.002", "head<neck", "face<head",
                "shoulder.L<spine.002", "upper_arm.L<shoulder.L", "forearm.L<upper_arm.L", "hand.L<forearm.L",
                "thumb.01.L<hand.L", "thumb.02.L<thumb.01.L", "f_index.01.L<hand.L", "f_index.02.L<f_index.01.L",
                "f_pinky.01.L<hand.L", "f_pinky.02.L<f_pinky.01.L", "f_pinky.03.L<f_pinky.02.L",
                "shoulder.R<spine.002", "upper_arm.R<shoulder.R", "forearm.R<upper_arm.R", "hand.R<forearm.R",
                "thigh.L<pelvis", "shin.L<thigh.L", "foot.L<shin.L", "toe.L<foot.L",
                "thigh.R<pelvis", "shin.R<thigh.R", "foot.R<shin.R", "toe.R<foot.R"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=pelvis", "Spine=spine", "Chest=spine.001", "UpperChest=spine.002", "Head=head",
                "LeftShoulder=shoulder.L", "LeftUpperArm=upper_arm.L", "LeftLowerArm=forearm.L", "LeftHand=hand.L",
                "LeftThumbProximal=thumb.01.L", "LeftThumbIntermediate=thumb.02.L", "LeftIndexProximal=f_index.01.L",
                "LeftIndexIntermediate=f_index.02.L", "LeftLittleDistal=f_pinky.03.L", "RightUpperLeg=thigh.R",
                "RightLowerLeg=shin.R", "RightFoot=foot.R", "RightToes=toe.R");
            Assert.That(map.BoneOf(map.Skeleton.IndexOf("pelvis.L")), Is.EqualTo(HumanoidBone.LastBone));
            Assert.That(map.BoneOf(map.Skeleton.IndexOf("face")), Is.EqualTo(HumanoidBone.LastBone));
        }

        [Test]
        public void EndSitesStandInForAMissingHandFootAndHead()
        {
            // A forearm, a shin and a neck that end in End Sites: their ends are the wrist, ankle and head pivot.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "Spine<Hips", "Neck<Spine", "Neck_End!<Neck",
                "LeftArm<Spine", "LeftForeArm<LeftArm", "LeftForeArm_End!<LeftForeArm",
                "RightArm<Spine", "RightForeArm<RightArm", "RightForeArm_End!<RightForeArm",
                "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg", "LeftLeg_End!<LeftLeg",
                "RightUpLeg<Hips", "RightLeg<RightUpLeg", "RightFoot<RightLeg", "RightFoot_End!<RightFoot"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Head=Neck_End", "LeftHand=LeftForeArm_End", "RightHand=RightForeArm_End", "LeftFoot=LeftLeg_End",
                "RightFoot=RightFoot", "Spine=Spine");
            Assert.That(map.Has(HumanoidBone.RightToes), Is.False, "an End Site is not a toe");
        }

        [Test]
        public void MissingBonesAreReported()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build("Hips", "Spine<Hips", "Head<Spine", "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg"));
            Assert.That(map.MissingRequired(), Does.Contain(HumanoidBone.LeftFoot));
            Assert.That(map.MissingRequired(), Does.Contain(HumanoidBone.RightHand));
            Assert.That(map.MissingRequired(), Has.No.Member(HumanoidBone.Spine));
        }

        [Test]
        public void OverridesWinAndKeepTheMapConsistent()
        {
            Skeleton s = Build(Mixamo("mixamorig:"));
            var overrides = new Dictionary<string, HumanoidBone>
            {
                // Take a joint detection gave to another bone, and remap a detected bone.
                ["mixamorig:Spine2"] = HumanoidBone.Chest,
                ["mixamorig:LeftHandIndex1"] = HumanoidBone.LeftHand,
            };
            HumanoidMap map = HumanoidNaming.Detect(s, overrides);
            Expect(map, "Chest=mixamorig:Spine2", "LeftHand=mixamorig:LeftHandIndex1", "Spine=mixamorig:Spine");
            Assert.That(map.Has(HumanoidBone.UpperChest), Is.False, "Spine2 moved to Chest");
            Assert.That(map.Has(HumanoidBone.LeftIndexProximal), Is.False, "Index1 moved to LeftHand");
            Assert.That(map.BoneOf(s.IndexOf("mixamorig:LeftHand")), Is.EqualTo(HumanoidBone.LastBone));

            Assert.Throws<ArgumentException>(() => HumanoidNaming.Detect(s, new Dictionary<string, HumanoidBone> { ["nope"] = HumanoidBone.Head }));
        }

        [Test]
        public void UnrealNames()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "pelvis", "spine_01<pelvis", "spine_02<spine_01", "spine_03<spine_02", "neck_01<spine_03", "head<neck_01",
                "clavicle_l<spine_03", "upperarm_l<clavicle_l", "lowerarm_l<upperarm_l", "hand_l<lowerarm_l", "index_01_l<hand_l",
                "clavicle_r<spine_03", "upperarm_r<clavicle_r", "lowerarm_r<upperarm_r", "hand_r<lowerarm_r",
                "thigh_l<pelvis", "calf_l<thigh_l", "foot_l<calf_l", "ball_l<foot_l",
                "thigh_r<pelvis", "calf_r<thigh_r", "foot_r<calf_r"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Neck=neck_01", "UpperChest=spine_03", "LeftShoulder=clavicle_l", "LeftIndexProximal=index_01_l", "LeftToes=ball_l");
        }
    }
}
