using System.Collections.Generic;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary><see cref="HumanoidDetection"/>: the names first, the structure when they fall short, the bones given explicitly winning.</summary>
    public class HumanoidDetectionTests
    {
        private static BvhClip MocapBank() => BvhReader.ReadFile(TestData.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });

        [Test]
        public void NamesThatFindEveryBoneAreUsedAsTheyAre()
        {
            BvhClip clip = MocapBank();
            HumanoidMap map = HumanoidDetection.Detect(clip, null, out string note);
            Assert.That(note, Is.Null);
            HumanoidMap byNames = HumanoidNaming.Detect(clip.Skeleton);
            for (int bone = 0; bone < HumanoidBones.Count; bone++) Assert.That(map[(HumanoidBone)bone], Is.EqualTo(byNames[(HumanoidBone)bone]));
        }

        [Test]
        public void NamesThatSayNothingLeaveItToTheStructureAndTheNoteSaysSo()
        {
            BvhClip clip = HumanoidStructureTests.Numbered(MocapBank());
            HumanoidMap map = HumanoidDetection.Detect(clip, null, out string note);
            Assert.That(map.IsComplete, Is.True, note);
            StringAssert.Contains("the names give 1 humanoid bone: all were found from the hierarchy and the motion", note);
            Assert.That(map[HumanoidBone.LeftLowerArm], Is.EqualTo(HumanoidStructure.Detect(clip, out _)[HumanoidBone.LeftLowerArm]));
        }

        [Test]
        public void BonesGivenExplicitlyWinOverTheStructure()
        {
            BvhClip clip = HumanoidStructureTests.Numbered(MocapBank());
            HumanoidMap found = HumanoidStructure.Detect(clip, out _);
            // Give the structure's neck joint as the head: the structure's head and neck give way to it.
            string neck = found.NameOf(HumanoidBone.Neck);
            HumanoidMap map = HumanoidDetection.Detect(clip, new Dictionary<string, HumanoidBone> { [neck] = HumanoidBone.Head }, out string note);
            Assert.That(map.IsComplete, Is.True, note);
            Assert.That(map.NameOf(HumanoidBone.Head), Is.EqualTo(neck));
            Assert.That(map.Has(HumanoidBone.Neck), Is.False);
            Assert.That(map[HumanoidBone.LeftHand], Is.EqualTo(found[HumanoidBone.LeftHand]), "the other bones are the structure's");
        }

        [Test]
        public void ABoneGivenExplicitlyInAnotherBonesPlaceLeavesThatBoneMissingAndSaysWhich()
        {
            BvhClip clip = HumanoidStructureTests.Numbered(MocapBank());
            HumanoidMap found = HumanoidStructure.Detect(clip, out _);
            string elbow = found.NameOf(HumanoidBone.LeftLowerArm);
            HumanoidMap map = HumanoidDetection.Detect(clip, new Dictionary<string, HumanoidBone> { [elbow] = HumanoidBone.LeftHand }, out string note);
            Assert.That(map.MissingRequired(), Is.EqualTo(new[] { HumanoidBone.LeftLowerArm }), "what is missing is what the note names");
            StringAssert.Contains("the names give 1 humanoid bone (and 1 humanoid bone given explicitly)", note);
            StringAssert.Contains("take the place of LeftLowerArm", note);
        }
    }
}
