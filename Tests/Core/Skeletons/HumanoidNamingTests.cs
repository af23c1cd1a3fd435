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
        public void RigifyDeformBones_NumberedSpineTwistSegmentsAndAFloorRoot()
        {
            // A Rigify rig exported with its deform bones only: every name has DEF-, the neck and head are spine.004 and
            // spine.006, the limbs have .001 twist segments, and a floor-level root sits above the spine.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "root", "DEF-spine<root", "DEF-pelvis.L<DEF-spine", "DEF-pelvis.R<DEF-spine",
                "DEF-spine.001<DEF-spine", "DEF-spine.002<DEF-spine.001", "DEF-spine.003<DEF-spine.002",
                "DEF-spine.004<DEF-spine.003", "DEF-spine.005<DEF-spine.004", "DEF-spine.006<DEF-spine.005",
                "DEF-jaw<DEF-spine.006", "DEF-eye.L<DEF-spine.006", "DEF-eye.R<DEF-spine.006", "DEF-breast.L<DEF-spine.003",
                "DEF-shoulder.L<DEF-spine.003", "DEF-upper_arm.L<DEF-shoulder.L", "DEF-upper_arm.L.001<DEF-upper_arm.L",
                "DEF-forearm.L<DEF-upper_arm.L.001", "DEF-forearm.L.001<DEF-forearm.L", "DEF-hand.L<DEF-forearm.L.001",
                "DEF-f_index.01.L<DEF-hand.L", "DEF-thumb.01.L<DEF-hand.L",
                "DEF-shoulder.R<DEF-spine.003", "DEF-upper_arm.R<DEF-shoulder.R", "DEF-upper_arm.R.001<DEF-upper_arm.R",
                "DEF-forearm.R<DEF-upper_arm.R.001", "DEF-forearm.R.001<DEF-forearm.R", "DEF-hand.R<DEF-forearm.R.001",
                "DEF-thigh.L<DEF-spine", "DEF-thigh.L.001<DEF-thigh.L", "DEF-shin.L<DEF-thigh.L.001", "DEF-shin.L.001<DEF-shin.L",
                "DEF-foot.L<DEF-shin.L.001", "DEF-toe.L<DEF-foot.L",
                "DEF-thigh.R<DEF-spine", "DEF-thigh.R.001<DEF-thigh.R", "DEF-shin.R<DEF-thigh.R.001", "DEF-shin.R.001<DEF-shin.R",
                "DEF-foot.R<DEF-shin.R.001", "DEF-toe.R<DEF-foot.R"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=DEF-spine", "Spine=DEF-spine.001", "Chest=DEF-spine.002", "UpperChest=DEF-spine.003",
                "Neck=DEF-spine.004", "Head=DEF-spine.006", "LeftEye=DEF-eye.L", "Jaw=DEF-jaw",
                "LeftShoulder=DEF-shoulder.L", "LeftUpperArm=DEF-upper_arm.L", "LeftLowerArm=DEF-forearm.L", "LeftHand=DEF-hand.L",
                "LeftIndexProximal=DEF-f_index.01.L", "LeftThumbProximal=DEF-thumb.01.L", "RightLowerArm=DEF-forearm.R",
                "LeftUpperLeg=DEF-thigh.L", "LeftLowerLeg=DEF-shin.L", "LeftFoot=DEF-foot.L", "LeftToes=DEF-toe.L",
                "RightUpperLeg=DEF-thigh.R", "RightLowerLeg=DEF-shin.R", "RightFoot=DEF-foot.R");
        }

        [Test]
        public void MakeHumanNames_ClavicleBesideAShoulderAndNumberedSegments()
        {
            // MakeHuman's default skeleton: the limbs in numbered segments (upperarm01, upperarm02), a shoulder01 between the
            // clavicle and the upper arm, five spine joints counting down from the hips and a root at the pelvis.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "root", "spine05<root", "spine04<spine05", "spine03<spine04", "spine02<spine03", "spine01<spine02",
                "neck01<spine01", "neck02<neck01", "neck03<neck02", "head<neck03", "eye.L<head", "eye.R<head",
                "clavicle.L<spine01", "shoulder01.L<clavicle.L", "upperarm01.L<shoulder01.L", "upperarm02.L<upperarm01.L",
                "lowerarm01.L<upperarm02.L", "lowerarm02.L<lowerarm01.L", "wrist.L<lowerarm02.L",
                "clavicle.R<spine01", "shoulder01.R<clavicle.R", "upperarm01.R<shoulder01.R", "upperarm02.R<upperarm01.R",
                "lowerarm01.R<upperarm02.R", "lowerarm02.R<lowerarm01.R", "wrist.R<lowerarm02.R",
                "pelvis.L<root", "upperleg01.L<pelvis.L", "upperleg02.L<upperleg01.L", "lowerleg01.L<upperleg02.L",
                "lowerleg02.L<lowerleg01.L", "foot.L<lowerleg02.L", "toe1-1.L<foot.L",
                "pelvis.R<root", "upperleg01.R<pelvis.R", "upperleg02.R<upperleg01.R", "lowerleg01.R<upperleg02.R",
                "lowerleg02.R<lowerleg01.R", "foot.R<lowerleg02.R"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=root", "Spine=spine05", "Chest=spine04", "UpperChest=spine01", "Neck=neck01", "Head=head",
                "LeftShoulder=clavicle.L", "LeftUpperArm=upperarm01.L", "LeftLowerArm=lowerarm01.L", "LeftHand=wrist.L",
                "RightShoulder=clavicle.R", "RightUpperArm=upperarm01.R", "LeftUpperLeg=upperleg01.L", "LeftLowerLeg=lowerleg01.L",
                "LeftFoot=foot.L", "RightUpperLeg=upperleg01.R", "RightLowerLeg=lowerleg01.R", "RightFoot=foot.R", "LeftEye=eye.L");
        }

        [Test]
        public void ANumberedSpineWithoutNeckOrHeadNamesEndsInTheHead()
        {
            // Joints named like the one carrying the arms go on to the head; a jaw or a hair strand under it is not followed.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "Bone1<Hips", "Bone2<Bone1", "Bone3<Bone2", "Bone4<Bone3", "Jaw_C<Bone4", "Hair1<Bone4", "Hair2<Hair1",
                "LeftShoulder<Bone2", "LeftArm<LeftShoulder", "LeftForeArm<LeftArm", "LeftHand<LeftForeArm",
                "RightShoulder<Bone2", "RightArm<RightShoulder", "RightForeArm<RightArm", "RightHand<RightForeArm",
                "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg", "LeftFoot<LeftLeg", "RightUpLeg<Hips", "RightLeg<RightUpLeg", "RightFoot<RightLeg"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Neck=Bone3", "Head=Bone4", "Spine=Bone1", "Chest=Bone2");
        }

        [Test]
        public void OtherNamesAboveTheArmsLeaveTheHeadMissingRatherThanGuessed()
        {
            // Found in review: following single children made a jaw, a hair strand or a backpack strap the head.
            foreach (string[] above in new[]
            {
                new[] { "Bone.007<Chest", "Bone.008<Bone.007", "Jaw<Bone.008" },
                new[] { "Backpack<Chest", "Backpack_Strap<Backpack" },
            })
            {
                var entries = new List<string> { "Hips", "Spine<Hips", "Chest<Spine" };
                entries.AddRange(above);
                entries.AddRange(new[]
                {
                    "LeftShoulder<Chest", "LeftArm<LeftShoulder", "LeftForeArm<LeftArm", "LeftHand<LeftForeArm",
                    "RightShoulder<Chest", "RightArm<RightShoulder", "RightForeArm<RightArm", "RightHand<RightForeArm",
                    "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg", "LeftFoot<LeftLeg", "RightUpLeg<Hips", "RightLeg<RightUpLeg", "RightFoot<RightLeg",
                });
                HumanoidMap map = HumanoidNaming.Detect(Build(entries.ToArray()));
                Assert.That(map.MissingRequired(), Is.EqualTo(new[] { HumanoidBone.Head }), above[0]);
                Assert.That(map.Has(HumanoidBone.Neck), Is.False, above[0]);
            }
        }

        [Test]
        public void ACollarBoneBesideTheShoulderIsNotTheClavicle()
        {
            // Found in review: a Bandai-style rig with cloth collar bones lost its upper arms when a collar was preferred.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Hips", "Spine<Hips", "Chest<Spine", "Neck<Chest", "Head<Neck", "Collar_L<Chest", "Collar_R<Chest",
                "Shoulder_L<Chest", "UpperArm_L<Shoulder_L", "LowerArm_L<UpperArm_L", "Hand_L<LowerArm_L",
                "Shoulder_R<Chest", "UpperArm_R<Shoulder_R", "LowerArm_R<UpperArm_R", "Hand_R<LowerArm_R",
                "UpperLeg_L<Hips", "LowerLeg_L<UpperLeg_L", "Foot_L<LowerLeg_L", "UpperLeg_R<Hips", "LowerLeg_R<UpperLeg_R", "Foot_R<LowerLeg_R"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "LeftShoulder=Shoulder_L", "LeftUpperArm=UpperArm_L", "RightShoulder=Shoulder_R", "RightUpperArm=UpperArm_R");
        }

        [Test]
        public void OptiTrackMotiveNames()
        {
            // Motive's skeleton, as its exports name it (a "Skeleton 002:" namespace in some of them), with toes and an End Site.
            string ns = "Skeleton 002:";
            HumanoidMap map = HumanoidNaming.Detect(Build(
                ns + "Hip", ns + "Ab<" + ns + "Hip", ns + "Chest<" + ns + "Ab", ns + "Neck<" + ns + "Chest", ns + "Head<" + ns + "Neck",
                ns + "LShoulder<" + ns + "Chest", ns + "LUArm<" + ns + "LShoulder", ns + "LFArm<" + ns + "LUArm", ns + "LHand<" + ns + "LFArm",
                ns + "RShoulder<" + ns + "Chest", ns + "RUArm<" + ns + "RShoulder", ns + "RFArm<" + ns + "RUArm", ns + "RHand<" + ns + "RFArm",
                ns + "LThigh<" + ns + "Hip", ns + "LShin<" + ns + "LThigh", ns + "LFoot<" + ns + "LShin", ns + "LToe<" + ns + "LFoot", "LToe_End!<" + ns + "LToe",
                ns + "RThigh<" + ns + "Hip", ns + "RShin<" + ns + "RThigh", ns + "RFoot<" + ns + "RShin", ns + "RToe<" + ns + "RFoot"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=" + ns + "Hip", "Spine=" + ns + "Ab", "Chest=" + ns + "Chest", "Neck=" + ns + "Neck", "Head=" + ns + "Head",
                "LeftShoulder=" + ns + "LShoulder", "LeftUpperArm=" + ns + "LUArm", "LeftLowerArm=" + ns + "LFArm", "LeftHand=" + ns + "LHand",
                "RightUpperArm=" + ns + "RUArm", "LeftUpperLeg=" + ns + "LThigh", "LeftLowerLeg=" + ns + "LShin", "LeftFoot=" + ns + "LFoot",
                "LeftToes=" + ns + "LToe", "RightLowerLeg=" + ns + "RShin");
        }

        [Test]
        public void KinectNames()
        {
            // Kinect v2's joints, as its SDK names and links them: no clavicle, the shoulder is the upper arm, a wrist above
            // the hand and an ankle above the foot; the side a last word, not a word ending in it.
            HumanoidMap v2 = HumanoidNaming.Detect(Build(
                "SpineBase", "SpineMid<SpineBase", "SpineShoulder<SpineMid", "Neck<SpineShoulder", "Head<Neck",
                "ShoulderLeft<SpineShoulder", "ElbowLeft<ShoulderLeft", "WristLeft<ElbowLeft", "HandLeft<WristLeft", "HandTipLeft<HandLeft", "ThumbLeft<HandLeft",
                "ShoulderRight<SpineShoulder", "ElbowRight<ShoulderRight", "WristRight<ElbowRight", "HandRight<WristRight",
                "HipLeft<SpineBase", "KneeLeft<HipLeft", "AnkleLeft<KneeLeft", "FootLeft<AnkleLeft",
                "HipRight<SpineBase", "KneeRight<HipRight", "AnkleRight<KneeRight", "FootRight<AnkleRight", "Upright<Head"));
            Assert.That(v2.MissingRequired(), Is.Empty);
            Expect(v2, "Hips=SpineBase", "Spine=SpineMid", "Chest=SpineShoulder", "Neck=Neck", "Head=Head", "LeftUpperArm=ShoulderLeft",
                "LeftLowerArm=ElbowLeft", "LeftHand=WristLeft", "RightHand=WristRight", "LeftUpperLeg=HipLeft", "LeftLowerLeg=KneeLeft",
                "LeftFoot=AnkleLeft", "LeftToes=FootLeft", "RightToes=FootRight");
            Assert.That(v2.Has(HumanoidBone.LeftShoulder), Is.False);
            Assert.That(v2.BoneOf(v2.Skeleton.IndexOf("Upright")), Is.EqualTo(HumanoidBone.LastBone), "upright is not a right-side joint");

            HumanoidMap azure = HumanoidNaming.Detect(Build(
                "PELVIS", "SPINE_NAVEL<PELVIS", "SPINE_CHEST<SPINE_NAVEL", "NECK<SPINE_CHEST", "HEAD<NECK", "EYE_LEFT<HEAD", "EYE_RIGHT<HEAD",
                "CLAVICLE_LEFT<SPINE_CHEST", "SHOULDER_LEFT<CLAVICLE_LEFT", "ELBOW_LEFT<SHOULDER_LEFT", "WRIST_LEFT<ELBOW_LEFT", "HAND_LEFT<WRIST_LEFT",
                "CLAVICLE_RIGHT<SPINE_CHEST", "SHOULDER_RIGHT<CLAVICLE_RIGHT", "ELBOW_RIGHT<SHOULDER_RIGHT", "WRIST_RIGHT<ELBOW_RIGHT",
                "HIP_LEFT<PELVIS", "KNEE_LEFT<HIP_LEFT", "ANKLE_LEFT<KNEE_LEFT", "FOOT_LEFT<ANKLE_LEFT",
                "HIP_RIGHT<PELVIS", "KNEE_RIGHT<HIP_RIGHT", "ANKLE_RIGHT<KNEE_RIGHT", "FOOT_RIGHT<ANKLE_RIGHT"));
            Assert.That(azure.MissingRequired(), Is.Empty);
            Expect(azure, "Hips=PELVIS", "Spine=SPINE_NAVEL", "Chest=SPINE_CHEST", "LeftShoulder=CLAVICLE_LEFT", "LeftUpperArm=SHOULDER_LEFT",
                "LeftLowerArm=ELBOW_LEFT", "LeftHand=WRIST_LEFT", "LeftUpperLeg=HIP_LEFT", "LeftFoot=ANKLE_LEFT", "LeftToes=FOOT_LEFT",
                "LeftEye=EYE_LEFT", "RightUpperArm=SHOULDER_RIGHT");
        }

        // A Unity-style rig in one name pattern: NAME(bone) gives each joint's name ("Left" + bone, "LEFT" + bone, ...).
        private static string[] Rig(Func<string, string> left, Func<string, string> right, params string[] spine)
        {
            var e = new List<string> { spine[0] };
            for (int i = 1; i < spine.Length; i++) e.Add(spine[i] + "<" + spine[i - 1]);
            string chest = spine[spine.Length - 3], neck = spine[spine.Length - 2];
            foreach (Func<string, string> side in new[] { left, right })
            {
                e.Add(side("Shoulder") + "<" + chest); e.Add(side("Arm") + "<" + side("Shoulder")); e.Add(side("ForeArm") + "<" + side("Arm")); e.Add(side("Hand") + "<" + side("ForeArm"));
                e.Add(side("UpLeg") + "<" + spine[0]); e.Add(side("Leg") + "<" + side("UpLeg")); e.Add(side("Foot") + "<" + side("Leg"));
            }
            return e.ToArray();
        }

        [Test]
        public void MotionCaptureSideRulesLeaveOtherRigsAsTheyWere()
        {
            // Found in review: the OptiTrack and Kinect side rules, read on every rig, took names in capitals (LEFTARM, LUMBAR,
            // UPRIGHT) apart and let a facial EyeLeft or a helper HandRight take a bone. They are read only where they side
            // more joints than the other rules.
            HumanoidMap caps = HumanoidNaming.Detect(Build(Rig(b => "LEFT" + b.ToUpperInvariant(), b => "RIGHT" + b.ToUpperInvariant(), "HIPS", "LUMBAR", "UPRIGHT", "CHEST", "NECK", "HEAD")));
            Assert.That(caps.MissingRequired(), Is.Empty);
            Expect(caps, "LeftUpperArm=LEFTARM", "RightHand=RIGHTHAND", "LeftLowerLeg=LEFTLEG", "Spine=LUMBAR", "Chest=UPRIGHT", "UpperChest=CHEST");

            var withFace = new List<string>(Rig(b => "Left" + b, b => "Right" + b, "Hips", "Spine", "Chest", "Neck", "Head"));
            withFace.InsertRange(6, new[] { "EyeLeft<Head", "EyeRight<Head", "BrowLeft<Head", "LeftEye<Head", "RightEye<Head", "HandRight<Chest" });
            HumanoidMap face = HumanoidNaming.Detect(Build(withFace.ToArray()));
            Expect(face, "LeftEye=LeftEye", "RightEye=RightEye", "RightHand=RightHand");
            Assert.That(face.BoneOf(face.Skeleton.IndexOf("EyeLeft")), Is.EqualTo(HumanoidBone.LastBone));
        }

        [Test]
        public void MotiveTakePrefixAndSmplFbxNames()
        {
            // Motive's take prefix (Skeleton1_LUArm) and SMPL's FBX prefix (m_avg_L_Hip, m_avg_Neck).
            HumanoidMap motive = HumanoidNaming.Detect(Build(
                "Skeleton1_Hip", "Skeleton1_Ab<Skeleton1_Hip", "Skeleton1_Chest<Skeleton1_Ab", "Skeleton1_Neck<Skeleton1_Chest", "Skeleton1_Head<Skeleton1_Neck",
                "Skeleton1_LShoulder<Skeleton1_Chest", "Skeleton1_LUArm<Skeleton1_LShoulder", "Skeleton1_LFArm<Skeleton1_LUArm", "Skeleton1_LHand<Skeleton1_LFArm",
                "Skeleton1_RShoulder<Skeleton1_Chest", "Skeleton1_RUArm<Skeleton1_RShoulder", "Skeleton1_RFArm<Skeleton1_RUArm", "Skeleton1_RHand<Skeleton1_RFArm",
                "Skeleton1_LThigh<Skeleton1_Hip", "Skeleton1_LShin<Skeleton1_LThigh", "Skeleton1_LFoot<Skeleton1_LShin",
                "Skeleton1_RThigh<Skeleton1_Hip", "Skeleton1_RShin<Skeleton1_RThigh", "Skeleton1_RFoot<Skeleton1_RShin"));
            Assert.That(motive.MissingRequired(), Is.Empty);
            Expect(motive, "LeftUpperArm=Skeleton1_LUArm", "RightLowerLeg=Skeleton1_RShin", "Spine=Skeleton1_Ab");

            HumanoidMap smpl = HumanoidNaming.Detect(Build(
                "m_avg_root", "m_avg_Pelvis<m_avg_root", "m_avg_Spine1<m_avg_Pelvis", "m_avg_Spine2<m_avg_Spine1", "m_avg_Spine3<m_avg_Spine2",
                "m_avg_Neck<m_avg_Spine3", "m_avg_Head<m_avg_Neck",
                "m_avg_L_Collar<m_avg_Spine3", "m_avg_L_Shoulder<m_avg_L_Collar", "m_avg_L_Elbow<m_avg_L_Shoulder", "m_avg_L_Wrist<m_avg_L_Elbow", "m_avg_L_Hand<m_avg_L_Wrist",
                "m_avg_R_Collar<m_avg_Spine3", "m_avg_R_Shoulder<m_avg_R_Collar", "m_avg_R_Elbow<m_avg_R_Shoulder", "m_avg_R_Wrist<m_avg_R_Elbow",
                "m_avg_L_Hip<m_avg_Pelvis", "m_avg_L_Knee<m_avg_L_Hip", "m_avg_L_Ankle<m_avg_L_Knee", "m_avg_L_Foot<m_avg_L_Ankle",
                "m_avg_R_Hip<m_avg_Pelvis", "m_avg_R_Knee<m_avg_R_Hip", "m_avg_R_Ankle<m_avg_R_Knee"));
            Assert.That(smpl.MissingRequired(), Is.Empty);
            Expect(smpl, "Hips=m_avg_Pelvis", "Neck=m_avg_Neck", "Head=m_avg_Head", "LeftShoulder=m_avg_L_Collar", "LeftUpperArm=m_avg_L_Shoulder",
                "LeftHand=m_avg_L_Wrist", "LeftFoot=m_avg_L_Ankle", "LeftToes=m_avg_L_Foot");
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

        [Test]
        public void VRoidNames()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Root", "J_Bip_C_Hips<Root", "J_Bip_C_Spine<J_Bip_C_Hips", "J_Bip_C_Chest<J_Bip_C_Spine", "J_Bip_C_UpperChest<J_Bip_C_Chest",
                "J_Bip_C_Neck<J_Bip_C_UpperChest", "J_Bip_C_Head<J_Bip_C_Neck", "J_Adj_L_FaceEye<J_Bip_C_Head", "J_Sec_Hair1_01<J_Bip_C_Head",
                "J_Bip_L_Shoulder<J_Bip_C_UpperChest", "J_Bip_L_UpperArm<J_Bip_L_Shoulder", "J_Bip_L_LowerArm<J_Bip_L_UpperArm", "J_Bip_L_Hand<J_Bip_L_LowerArm",
                "J_Bip_L_Index1<J_Bip_L_Hand", "J_Bip_L_Index2<J_Bip_L_Index1", "J_Bip_L_Thumb1<J_Bip_L_Hand",
                "J_Bip_R_Shoulder<J_Bip_C_UpperChest", "J_Bip_R_UpperArm<J_Bip_R_Shoulder", "J_Bip_R_LowerArm<J_Bip_R_UpperArm", "J_Bip_R_Hand<J_Bip_R_LowerArm",
                "J_Bip_L_UpperLeg<J_Bip_C_Hips", "J_Bip_L_LowerLeg<J_Bip_L_UpperLeg", "J_Bip_L_Foot<J_Bip_L_LowerLeg", "J_Bip_L_ToeBase<J_Bip_L_Foot",
                "J_Bip_R_UpperLeg<J_Bip_C_Hips", "J_Bip_R_LowerLeg<J_Bip_R_UpperLeg", "J_Bip_R_Foot<J_Bip_R_LowerLeg"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=J_Bip_C_Hips", "Spine=J_Bip_C_Spine", "Chest=J_Bip_C_Chest", "UpperChest=J_Bip_C_UpperChest", "Neck=J_Bip_C_Neck",
                "Head=J_Bip_C_Head", "LeftShoulder=J_Bip_L_Shoulder", "LeftUpperArm=J_Bip_L_UpperArm", "LeftLowerArm=J_Bip_L_LowerArm",
                "LeftHand=J_Bip_L_Hand", "LeftIndexProximal=J_Bip_L_Index1", "LeftIndexIntermediate=J_Bip_L_Index2", "LeftThumbProximal=J_Bip_L_Thumb1",
                "RightUpperLeg=J_Bip_R_UpperLeg", "RightLowerLeg=J_Bip_R_LowerLeg", "LeftToes=J_Bip_L_ToeBase");
        }

        [Test]
        public void BipedNames()
        {
            // 3ds Max Biped as BVH exporters write it (spaces become underscores); its thighs hang from the pelvis.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Bip01", "Bip01_Pelvis<Bip01", "Bip01_Spine<Bip01_Pelvis", "Bip01_Spine1<Bip01_Spine", "Bip01_Neck<Bip01_Spine1", "Bip01_Head<Bip01_Neck",
                "Bip01_L_Clavicle<Bip01_Neck", "Bip01_L_UpperArm<Bip01_L_Clavicle", "Bip01_L_Forearm<Bip01_L_UpperArm", "Bip01_L_Hand<Bip01_L_Forearm",
                "Bip01_R_Clavicle<Bip01_Neck", "Bip01_R_UpperArm<Bip01_R_Clavicle", "Bip01_R_Forearm<Bip01_R_UpperArm", "Bip01_R_Hand<Bip01_R_Forearm",
                "Bip01_L_Thigh<Bip01_Pelvis", "Bip01_L_Calf<Bip01_L_Thigh", "Bip01_L_Foot<Bip01_L_Calf", "Bip01_L_Toe0<Bip01_L_Foot",
                "Bip01_R_Thigh<Bip01_Pelvis", "Bip01_R_Calf<Bip01_R_Thigh", "Bip01_R_Foot<Bip01_R_Calf"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=Bip01_Pelvis", "Spine=Bip01_Spine", "Chest=Bip01_Spine1", "Neck=Bip01_Neck", "Head=Bip01_Head",
                "LeftShoulder=Bip01_L_Clavicle", "LeftUpperArm=Bip01_L_UpperArm", "LeftLowerArm=Bip01_L_Forearm", "RightHand=Bip01_R_Hand",
                "LeftUpperLeg=Bip01_L_Thigh", "LeftLowerLeg=Bip01_L_Calf", "LeftFoot=Bip01_L_Foot", "LeftToes=Bip01_L_Toe0");
        }

        [Test]
        public void BipedFingersWithoutTheThumbAreNotReadAsMakeHumans()
        {
            // A Biped hand exported without its thumb (Finger0): Finger1 is still the index finger and Finger11 its second
            // phalanx, not MakeHuman's finger1-1 thumb (found in review: every finger took the one before it).
            var entries = new List<string>
            {
                "Bip01", "Bip01_Pelvis<Bip01", "Bip01_Spine<Bip01_Pelvis", "Bip01_Spine1<Bip01_Spine", "Bip01_Neck<Bip01_Spine1", "Bip01_Head<Bip01_Neck",
                "Bip01_L_Clavicle<Bip01_Neck", "Bip01_L_UpperArm<Bip01_L_Clavicle", "Bip01_L_Forearm<Bip01_L_UpperArm", "Bip01_L_Hand<Bip01_L_Forearm",
                "Bip01_R_Clavicle<Bip01_Neck", "Bip01_R_UpperArm<Bip01_R_Clavicle", "Bip01_R_Forearm<Bip01_R_UpperArm", "Bip01_R_Hand<Bip01_R_Forearm",
                "Bip01_L_Thigh<Bip01_Pelvis", "Bip01_L_Calf<Bip01_L_Thigh", "Bip01_L_Foot<Bip01_L_Calf",
                "Bip01_R_Thigh<Bip01_Pelvis", "Bip01_R_Calf<Bip01_R_Thigh", "Bip01_R_Foot<Bip01_R_Calf",
            };
            for (int finger = 1; finger <= 4; finger++)
                entries.AddRange(new[] { $"Bip01_L_Finger{finger}<Bip01_L_Hand", $"Bip01_L_Finger{finger}1<Bip01_L_Finger{finger}", $"Bip01_L_Finger{finger}2<Bip01_L_Finger{finger}1" });
            HumanoidMap map = HumanoidNaming.Detect(Build(entries.ToArray()));
            Assert.That(map.Has(HumanoidBone.LeftThumbProximal), Is.False, "no thumb");
            Expect(map, "LeftIndexProximal=Bip01_L_Finger1", "LeftIndexIntermediate=Bip01_L_Finger11", "LeftIndexDistal=Bip01_L_Finger12",
                "LeftMiddleProximal=Bip01_L_Finger2", "LeftRingProximal=Bip01_L_Finger3", "LeftLittleProximal=Bip01_L_Finger4", "LeftLittleDistal=Bip01_L_Finger42");
        }

        [Test]
        public void DazGenesisNames()
        {
            // Genesis 8: "hip" above "pelvis" (the legs under it, the spine beside it), bend and twist bones along each limb.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "hip", "pelvis<hip", "abdomenLower<hip", "abdomenUpper<abdomenLower", "chestLower<abdomenUpper", "chestUpper<chestLower",
                "neckLower<chestUpper", "neckUpper<neckLower", "head<neckUpper",
                "lCollar<chestUpper", "lShldrBend<lCollar", "lShldrTwist<lShldrBend", "lForearmBend<lShldrTwist", "lForearmTwist<lForearmBend", "lHand<lForearmTwist",
                "rCollar<chestUpper", "rShldrBend<rCollar", "rShldrTwist<rShldrBend", "rForearmBend<rShldrTwist", "rForearmTwist<rForearmBend", "rHand<rForearmTwist",
                "lThighBend<pelvis", "lThighTwist<lThighBend", "lShin<lThighTwist", "lFoot<lShin", "lMetatarsals<lFoot", "lToe<lMetatarsals",
                "rThighBend<pelvis", "rThighTwist<rThighBend", "rShin<rThighTwist", "rFoot<rShin"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=hip", "Spine=abdomenLower", "Chest=abdomenUpper", "UpperChest=chestUpper", "Neck=neckLower", "Head=head",
                "LeftShoulder=lCollar", "LeftUpperArm=lShldrBend", "LeftLowerArm=lForearmBend", "LeftHand=lHand", "RightUpperArm=rShldrBend",
                "LeftUpperLeg=lThighBend", "LeftLowerLeg=lShin", "LeftFoot=lFoot", "LeftToes=lToe", "RightLowerLeg=rShin");
        }

        [Test]
        public void SmplXsensAndBandaiNames()
        {
            HumanoidMap smpl = HumanoidNaming.Detect(Build(
                "Pelvis", "L_Hip<Pelvis", "L_Knee<L_Hip", "L_Ankle<L_Knee", "L_Foot<L_Ankle", "R_Hip<Pelvis", "R_Knee<R_Hip", "R_Ankle<R_Knee",
                "Spine1<Pelvis", "Spine2<Spine1", "Spine3<Spine2", "Neck<Spine3", "Head<Neck",
                "L_Collar<Spine3", "L_Shoulder<L_Collar", "L_Elbow<L_Shoulder", "L_Wrist<L_Elbow", "L_Hand<L_Wrist",
                "R_Collar<Spine3", "R_Shoulder<R_Collar", "R_Elbow<R_Shoulder", "R_Wrist<R_Elbow"));
            Assert.That(smpl.MissingRequired(), Is.Empty);
            // SMPL's L_Foot is the toes' joint, below the ankle; its L_Hand is the knuckles', below the wrist.
            Expect(smpl, "Hips=Pelvis", "LeftUpperLeg=L_Hip", "LeftLowerLeg=L_Knee", "LeftFoot=L_Ankle", "LeftShoulder=L_Collar",
                "LeftUpperArm=L_Shoulder", "LeftLowerArm=L_Elbow", "LeftHand=L_Wrist", "UpperChest=Spine3");

            HumanoidMap xsens = HumanoidNaming.Detect(Build(
                "Pelvis", "L5<Pelvis", "L3<L5", "T12<L3", "T8<T12", "Neck<T8", "Head<Neck",
                "RightShoulder<T8", "RightUpperArm<RightShoulder", "RightForeArm<RightUpperArm", "RightHand<RightForeArm",
                "LeftShoulder<T8", "LeftUpperArm<LeftShoulder", "LeftForeArm<LeftUpperArm", "LeftHand<LeftForeArm",
                "RightUpperLeg<Pelvis", "RightLowerLeg<RightUpperLeg", "RightFoot<RightLowerLeg", "RightToe<RightFoot",
                "LeftUpperLeg<Pelvis", "LeftLowerLeg<LeftUpperLeg", "LeftFoot<LeftLowerLeg", "LeftToe<LeftFoot"));
            Assert.That(xsens.MissingRequired(), Is.Empty);
            Expect(xsens, "Hips=Pelvis", "Spine=L5", "Chest=L3", "UpperChest=T8", "LeftShoulder=LeftShoulder", "LeftUpperArm=LeftUpperArm", "LeftToes=LeftToe");

            HumanoidMap bandai = HumanoidNaming.Detect(Build(
                "Hips", "Spine<Hips", "Chest<Spine", "Neck<Chest", "Head<Neck",
                "Shoulder_L<Chest", "UpperArm_L<Shoulder_L", "LowerArm_L<UpperArm_L", "Hand_L<LowerArm_L",
                "Shoulder_R<Chest", "UpperArm_R<Shoulder_R", "LowerArm_R<UpperArm_R", "Hand_R<LowerArm_R",
                "UpperLeg_L<Hips", "LowerLeg_L<UpperLeg_L", "Foot_L<LowerLeg_L", "Toes_L<Foot_L",
                "UpperLeg_R<Hips", "LowerLeg_R<UpperLeg_R", "Foot_R<LowerLeg_R"));
            Assert.That(bandai.MissingRequired(), Is.Empty);
            Expect(bandai, "LeftShoulder=Shoulder_L", "LeftUpperArm=UpperArm_L", "RightLowerArm=LowerArm_R", "LeftToes=Toes_L");
        }

        [Test]
        public void CharacterCreatorNames()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "RL_BoneRoot", "CC_Base_Hip<RL_BoneRoot", "CC_Base_Pelvis<CC_Base_Hip", "CC_Base_Waist<CC_Base_Hip", "CC_Base_Spine01<CC_Base_Waist",
                "CC_Base_Spine02<CC_Base_Spine01", "CC_Base_NeckTwist01<CC_Base_Spine02", "CC_Base_NeckTwist02<CC_Base_NeckTwist01", "CC_Base_Head<CC_Base_NeckTwist02",
                "CC_Base_L_Clavicle<CC_Base_Spine02", "CC_Base_L_Upperarm<CC_Base_L_Clavicle", "CC_Base_L_Forearm<CC_Base_L_Upperarm", "CC_Base_L_Hand<CC_Base_L_Forearm",
                "CC_Base_R_Clavicle<CC_Base_Spine02", "CC_Base_R_Upperarm<CC_Base_R_Clavicle", "CC_Base_R_Forearm<CC_Base_R_Upperarm", "CC_Base_R_Hand<CC_Base_R_Forearm",
                "CC_Base_L_Thigh<CC_Base_Pelvis", "CC_Base_L_Calf<CC_Base_L_Thigh", "CC_Base_L_Foot<CC_Base_L_Calf", "CC_Base_L_ToeBase<CC_Base_L_Foot",
                "CC_Base_R_Thigh<CC_Base_Pelvis", "CC_Base_R_Calf<CC_Base_R_Thigh", "CC_Base_R_Foot<CC_Base_R_Calf"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=CC_Base_Hip", "Spine=CC_Base_Waist", "Chest=CC_Base_Spine01", "UpperChest=CC_Base_Spine02", "Neck=CC_Base_NeckTwist01",
                "Head=CC_Base_Head", "LeftShoulder=CC_Base_L_Clavicle", "LeftUpperArm=CC_Base_L_Upperarm", "LeftUpperLeg=CC_Base_L_Thigh",
                "LeftLowerLeg=CC_Base_L_Calf", "LeftToes=CC_Base_L_ToeBase");
        }

        [Test]
        public void APelvisAboveTheHipsLeavesTheHipsTheHips()
        {
            // Found in review: the shallowest of hips/pelvis/hip once took a Pelvis above a Hips joint.
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "Armature", "Pelvis<Armature", "Hips<Pelvis", "Spine<Hips", "Chest<Spine", "Neck<Chest", "Head<Neck",
                "LeftShoulder<Chest", "LeftArm<LeftShoulder", "LeftForeArm<LeftArm", "LeftHand<LeftForeArm",
                "RightShoulder<Chest", "RightArm<RightShoulder", "RightForeArm<RightArm", "RightHand<RightForeArm",
                "LeftUpLeg<Hips", "LeftLeg<LeftUpLeg", "LeftAnkle<LeftLeg", "LeftFoot<LeftAnkle", "LeftToeBase<LeftFoot",
                "RightUpLeg<Hips", "RightLeg<RightUpLeg", "RightFoot<RightLeg"));
            // An ankle above a foot is the foot bone; the toe-named joint below stays the toes.
            Expect(map, "Hips=Hips", "Spine=Spine", "Chest=Chest", "LeftFoot=LeftAnkle", "LeftToes=LeftToeBase", "RightFoot=RightFoot");
        }

        [Test]
        public void HumanIkArKitAndMetaNames()
        {
            HumanoidMap humanIk = HumanoidNaming.Detect(Build(
                "Character1_Reference", "Character1_Hips<Character1_Reference", "Character1_Spine<Character1_Hips", "Character1_Spine1<Character1_Spine",
                "Character1_Neck<Character1_Spine1", "Character1_Head<Character1_Neck",
                "Character1_LeftShoulder<Character1_Spine1", "Character1_LeftArm<Character1_LeftShoulder", "Character1_LeftForeArm<Character1_LeftArm", "Character1_LeftHand<Character1_LeftForeArm",
                "Character1_RightShoulder<Character1_Spine1", "Character1_RightArm<Character1_RightShoulder", "Character1_RightForeArm<Character1_RightArm", "Character1_RightHand<Character1_RightForeArm",
                "Character1_LeftUpLeg<Character1_Hips", "Character1_LeftLeg<Character1_LeftUpLeg", "Character1_LeftFoot<Character1_LeftLeg", "Character1_LeftToeBase<Character1_LeftFoot",
                "Character1_RightUpLeg<Character1_Hips", "Character1_RightLeg<Character1_RightUpLeg", "Character1_RightFoot<Character1_RightLeg"));
            Assert.That(humanIk.MissingRequired(), Is.Empty);
            Expect(humanIk, "Hips=Character1_Hips", "Spine=Character1_Spine", "LeftShoulder=Character1_LeftShoulder", "LeftUpperArm=Character1_LeftArm",
                "LeftLowerLeg=Character1_LeftLeg", "LeftToes=Character1_LeftToeBase", "Head=Character1_Head");

            HumanoidMap arKit = HumanoidNaming.Detect(Build(
                "root", "hips_joint<root", "spine_1_joint<hips_joint", "spine_2_joint<spine_1_joint", "spine_3_joint<spine_2_joint",
                "neck_1_joint<spine_3_joint", "head_joint<neck_1_joint",
                "left_shoulder_1_joint<spine_3_joint", "left_arm_joint<left_shoulder_1_joint", "left_forearm_joint<left_arm_joint", "left_hand_joint<left_forearm_joint",
                "right_shoulder_1_joint<spine_3_joint", "right_arm_joint<right_shoulder_1_joint", "right_forearm_joint<right_arm_joint", "right_hand_joint<right_forearm_joint",
                "left_upLeg_joint<hips_joint", "left_leg_joint<left_upLeg_joint", "left_foot_joint<left_leg_joint", "left_toes_joint<left_foot_joint",
                "right_upLeg_joint<hips_joint", "right_leg_joint<right_upLeg_joint", "right_foot_joint<right_leg_joint"));
            Assert.That(arKit.MissingRequired(), Is.Empty);
            Expect(arKit, "Hips=hips_joint", "Spine=spine_1_joint", "Neck=neck_1_joint", "Head=head_joint", "LeftShoulder=left_shoulder_1_joint",
                "LeftUpperArm=left_arm_joint", "LeftUpperLeg=left_upLeg_joint", "LeftToes=left_toes_joint");

            HumanoidMap meta = HumanoidNaming.Detect(Build(
                "FullBody_Root", "FullBody_Hips<FullBody_Root", "FullBody_SpineLower<FullBody_Hips", "FullBody_SpineMiddle<FullBody_SpineLower",
                "FullBody_SpineUpper<FullBody_SpineMiddle", "FullBody_Chest<FullBody_SpineUpper", "FullBody_Neck<FullBody_Chest", "FullBody_Head<FullBody_Neck",
                "FullBody_LeftShoulder<FullBody_Chest", "FullBody_LeftScapula<FullBody_LeftShoulder", "FullBody_LeftArmUpper<FullBody_LeftScapula",
                "FullBody_LeftArmLower<FullBody_LeftArmUpper", "FullBody_LeftHandWristTwist<FullBody_LeftArmLower", "FullBody_LeftHandWrist<FullBody_LeftHandWristTwist",
                "FullBody_RightShoulder<FullBody_Chest", "FullBody_RightScapula<FullBody_RightShoulder", "FullBody_RightArmUpper<FullBody_RightScapula",
                "FullBody_RightArmLower<FullBody_RightArmUpper", "FullBody_RightHandWrist<FullBody_RightArmLower",
                "FullBody_LeftLegUpper<FullBody_Hips", "FullBody_LeftLegLower<FullBody_LeftLegUpper", "FullBody_LeftFootAnkleTwist<FullBody_LeftLegLower",
                "FullBody_LeftFootAnkle<FullBody_LeftFootAnkleTwist", "FullBody_LeftFootBall<FullBody_LeftFootAnkle",
                "FullBody_RightLegUpper<FullBody_Hips", "FullBody_RightLegLower<FullBody_RightLegUpper", "FullBody_RightFootAnkle<FullBody_RightLegLower"));
            Assert.That(meta.MissingRequired(), Is.Empty);
            Expect(meta, "Hips=FullBody_Hips", "Spine=FullBody_SpineLower", "UpperChest=FullBody_Chest", "LeftShoulder=FullBody_LeftShoulder",
                "LeftUpperArm=FullBody_LeftArmUpper", "LeftLowerArm=FullBody_LeftArmLower", "LeftHand=FullBody_LeftHandWrist",
                "LeftUpperLeg=FullBody_LeftLegUpper", "LeftLowerLeg=FullBody_LeftLegLower", "LeftFoot=FullBody_LeftFootAnkle", "LeftToes=FullBody_LeftFootBall");
        }

        [Test]
        public void CmuAsfNames()
        {
            HumanoidMap map = HumanoidNaming.Detect(Build(
                "root", "lowerback<root", "upperback<lowerback", "thorax<upperback", "lowerneck<thorax", "upperneck<lowerneck", "head<upperneck",
                "lclavicle<thorax", "lhumerus<lclavicle", "lradius<lhumerus", "lwrist<lradius", "lhand<lwrist", "lfingers<lhand", "lthumb<lwrist",
                "rclavicle<thorax", "rhumerus<rclavicle", "rradius<rhumerus", "rwrist<rradius", "rhand<rwrist",
                "lhipjoint<root", "lfemur<lhipjoint", "ltibia<lfemur", "lfoot<ltibia", "ltoes<lfoot",
                "rhipjoint<root", "rfemur<rhipjoint", "rtibia<rfemur", "rfoot<rtibia", "rtoes<rfoot"));
            Assert.That(map.MissingRequired(), Is.Empty);
            Expect(map, "Hips=root", "Spine=lowerback", "Chest=upperback", "UpperChest=thorax", "Neck=lowerneck", "Head=head",
                "LeftShoulder=lclavicle", "LeftUpperArm=lhumerus", "LeftLowerArm=lradius", "LeftHand=lwrist", "RightHand=rwrist",
                "LeftUpperLeg=lfemur", "LeftLowerLeg=ltibia", "LeftFoot=lfoot", "LeftToes=ltoes", "RightUpperLeg=rfemur");
        }
    }
}
