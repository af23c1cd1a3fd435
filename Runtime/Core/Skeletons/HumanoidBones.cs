using System;

namespace AvatarGo.Core
{
    /// <summary>Facts about <see cref="HumanoidBone"/> values: which are required, the humanoid hierarchy, sides.</summary>
    public static class HumanoidBones
    {
        /// <summary>The number of bones (<see cref="HumanoidBone.LastBone"/>).</summary>
        public const int Count = (int)HumanoidBone.LastBone;

        // Humanoid parent of every bone, as in Unity's human template (optional bones skipped when absent).
        private static readonly HumanoidBone[] Parents = BuildParents();

        /// <summary>
        /// The bones every humanoid rig must have (the ones Unity's Avatar requires):
        /// hips, spine, head, and the three bones of each leg and arm.
        /// </summary>
        public static readonly HumanoidBone[] Required =
        {
            HumanoidBone.Hips, HumanoidBone.Spine, HumanoidBone.Head,
            HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot,
            HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot,
            HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand,
            HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, HumanoidBone.RightHand,
        };

        /// <summary>True for a bone listed in <see cref="Required"/>.</summary>
        public static bool IsRequired(HumanoidBone bone) => Array.IndexOf(Required, bone) >= 0;

        /// <summary>True for a valid bone value (not <see cref="HumanoidBone.LastBone"/>, not out of range).</summary>
        public static bool IsValid(HumanoidBone bone) => bone >= HumanoidBone.Hips && bone < HumanoidBone.LastBone;

        /// <summary>True for the 30 finger bones.</summary>
        public static bool IsFinger(HumanoidBone bone) =>
            bone >= HumanoidBone.LeftThumbProximal && bone <= HumanoidBone.RightLittleDistal;

        /// <summary>True for a bone of the left side of the body.</summary>
        public static bool IsLeft(HumanoidBone bone) =>
            bone.ToString().StartsWith("Left", StringComparison.Ordinal);

        /// <summary>True for a bone of the right side of the body.</summary>
        public static bool IsRight(HumanoidBone bone) =>
            bone.ToString().StartsWith("Right", StringComparison.Ordinal);

        /// <summary>
        /// The bone's parent in the humanoid hierarchy (for <see cref="HumanoidBone.Hips"/>, <see cref="HumanoidBone.LastBone"/>).
        /// Optional bones are included: the parent of <see cref="HumanoidBone.Neck"/> is <see cref="HumanoidBone.UpperChest"/>.
        /// </summary>
        public static HumanoidBone Parent(HumanoidBone bone) => IsValid(bone) ? Parents[(int)bone] : HumanoidBone.LastBone;

        /// <summary>The same bone on the other side of the body; a centre bone is its own mirror.</summary>
        public static HumanoidBone Mirror(HumanoidBone bone)
        {
            string name = bone.ToString();
            if (name.StartsWith("Left", StringComparison.Ordinal))
                return (HumanoidBone)Enum.Parse(typeof(HumanoidBone), "Right" + name.Substring(4));
            if (name.StartsWith("Right", StringComparison.Ordinal))
                return (HumanoidBone)Enum.Parse(typeof(HumanoidBone), "Left" + name.Substring(5));
            return bone;
        }

        /// <summary>
        /// The finger bone for a hand side, finger index (0 thumb … 4 little) and phalanx (0 proximal … 2 distal).
        /// </summary>
        public static HumanoidBone Finger(bool left, int finger, int phalanx)
        {
            if ((uint)finger > 4 || (uint)phalanx > 2) throw new ArgumentOutOfRangeException(nameof(finger));
            int first = left ? (int)HumanoidBone.LeftThumbProximal : (int)HumanoidBone.RightThumbProximal;
            return (HumanoidBone)(first + finger * 3 + phalanx);
        }

        private static HumanoidBone[] BuildParents()
        {
            var p = new HumanoidBone[Count];
            p[(int)HumanoidBone.Hips] = HumanoidBone.LastBone;
            p[(int)HumanoidBone.LeftUpperLeg] = HumanoidBone.Hips;
            p[(int)HumanoidBone.RightUpperLeg] = HumanoidBone.Hips;
            p[(int)HumanoidBone.LeftLowerLeg] = HumanoidBone.LeftUpperLeg;
            p[(int)HumanoidBone.RightLowerLeg] = HumanoidBone.RightUpperLeg;
            p[(int)HumanoidBone.LeftFoot] = HumanoidBone.LeftLowerLeg;
            p[(int)HumanoidBone.RightFoot] = HumanoidBone.RightLowerLeg;
            p[(int)HumanoidBone.LeftToes] = HumanoidBone.LeftFoot;
            p[(int)HumanoidBone.RightToes] = HumanoidBone.RightFoot;
            p[(int)HumanoidBone.Spine] = HumanoidBone.Hips;
            p[(int)HumanoidBone.Chest] = HumanoidBone.Spine;
            p[(int)HumanoidBone.UpperChest] = HumanoidBone.Chest;
            p[(int)HumanoidBone.Neck] = HumanoidBone.UpperChest;
            p[(int)HumanoidBone.Head] = HumanoidBone.Neck;
            p[(int)HumanoidBone.LeftEye] = HumanoidBone.Head;
            p[(int)HumanoidBone.RightEye] = HumanoidBone.Head;
            p[(int)HumanoidBone.Jaw] = HumanoidBone.Head;
            p[(int)HumanoidBone.LeftShoulder] = HumanoidBone.UpperChest;
            p[(int)HumanoidBone.RightShoulder] = HumanoidBone.UpperChest;
            p[(int)HumanoidBone.LeftUpperArm] = HumanoidBone.LeftShoulder;
            p[(int)HumanoidBone.RightUpperArm] = HumanoidBone.RightShoulder;
            p[(int)HumanoidBone.LeftLowerArm] = HumanoidBone.LeftUpperArm;
            p[(int)HumanoidBone.RightLowerArm] = HumanoidBone.RightUpperArm;
            p[(int)HumanoidBone.LeftHand] = HumanoidBone.LeftLowerArm;
            p[(int)HumanoidBone.RightHand] = HumanoidBone.RightLowerArm;
            for (int side = 0; side < 2; side++)
            {
                bool left = side == 0;
                HumanoidBone hand = left ? HumanoidBone.LeftHand : HumanoidBone.RightHand;
                for (int finger = 0; finger < 5; finger++)
                {
                    p[(int)Finger(left, finger, 0)] = hand;
                    p[(int)Finger(left, finger, 1)] = Finger(left, finger, 0);
                    p[(int)Finger(left, finger, 2)] = Finger(left, finger, 1);
                }
            }
            return p;
        }
    }
}
