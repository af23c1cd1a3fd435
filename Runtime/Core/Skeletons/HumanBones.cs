using System;

namespace AvatarGo.Core
{
    /// <summary>Facts about <see cref="HumanBone"/> values: which are required, the humanoid hierarchy, sides.</summary>
    public static class HumanBones
    {
        /// <summary>The number of bones (<see cref="HumanBone.LastBone"/>).</summary>
        public const int Count = (int)HumanBone.LastBone;

        // Humanoid parent of every bone, as in Unity's human template (optional bones skipped when absent).
        private static readonly HumanBone[] Parents = BuildParents();

        /// <summary>
        /// The bones every humanoid rig must have (the ones Unity's Avatar requires):
        /// hips, spine, head, and the three bones of each leg and arm.
        /// </summary>
        public static readonly HumanBone[] Required =
        {
            HumanBone.Hips, HumanBone.Spine, HumanBone.Head,
            HumanBone.LeftUpperLeg, HumanBone.LeftLowerLeg, HumanBone.LeftFoot,
            HumanBone.RightUpperLeg, HumanBone.RightLowerLeg, HumanBone.RightFoot,
            HumanBone.LeftUpperArm, HumanBone.LeftLowerArm, HumanBone.LeftHand,
            HumanBone.RightUpperArm, HumanBone.RightLowerArm, HumanBone.RightHand,
        };

        /// <summary>True for a bone listed in <see cref="Required"/>.</summary>
        public static bool IsRequired(HumanBone bone) => Array.IndexOf(Required, bone) >= 0;

        /// <summary>True for a valid bone value (not <see cref="HumanBone.LastBone"/>, not out of range).</summary>
        public static bool IsValid(HumanBone bone) => bone >= HumanBone.Hips && bone < HumanBone.LastBone;

        /// <summary>True for the 30 finger bones.</summary>
        public static bool IsFinger(HumanBone bone) =>
            bone >= HumanBone.LeftThumbProximal && bone <= HumanBone.RightLittleDistal;

        /// <summary>True for a bone of the left side of the body.</summary>
        public static bool IsLeft(HumanBone bone) =>
            bone.ToString().StartsWith("Left", StringComparison.Ordinal);

        /// <summary>True for a bone of the right side of the body.</summary>
        public static bool IsRight(HumanBone bone) =>
            bone.ToString().StartsWith("Right", StringComparison.Ordinal);

        /// <summary>
        /// The bone's parent in the humanoid hierarchy (for <see cref="HumanBone.Hips"/>, <see cref="HumanBone.LastBone"/>).
        /// Optional bones are included: the parent of <see cref="HumanBone.Neck"/> is <see cref="HumanBone.UpperChest"/>.
        /// </summary>
        public static HumanBone Parent(HumanBone bone) => IsValid(bone) ? Parents[(int)bone] : HumanBone.LastBone;

        /// <summary>The same bone on the other side of the body; a centre bone is its own mirror.</summary>
        public static HumanBone Mirror(HumanBone bone)
        {
            string name = bone.ToString();
            if (name.StartsWith("Left", StringComparison.Ordinal))
                return (HumanBone)Enum.Parse(typeof(HumanBone), "Right" + name.Substring(4));
            if (name.StartsWith("Right", StringComparison.Ordinal))
                return (HumanBone)Enum.Parse(typeof(HumanBone), "Left" + name.Substring(5));
            return bone;
        }

        /// <summary>
        /// The finger bone for a hand side, finger index (0 thumb … 4 little) and phalanx (0 proximal … 2 distal).
        /// </summary>
        public static HumanBone Finger(bool left, int finger, int phalanx)
        {
            if ((uint)finger > 4 || (uint)phalanx > 2) throw new ArgumentOutOfRangeException(nameof(finger));
            int first = left ? (int)HumanBone.LeftThumbProximal : (int)HumanBone.RightThumbProximal;
            return (HumanBone)(first + finger * 3 + phalanx);
        }

        private static HumanBone[] BuildParents()
        {
            var p = new HumanBone[Count];
            p[(int)HumanBone.Hips] = HumanBone.LastBone;
            p[(int)HumanBone.LeftUpperLeg] = HumanBone.Hips;
            p[(int)HumanBone.RightUpperLeg] = HumanBone.Hips;
            p[(int)HumanBone.LeftLowerLeg] = HumanBone.LeftUpperLeg;
            p[(int)HumanBone.RightLowerLeg] = HumanBone.RightUpperLeg;
            p[(int)HumanBone.LeftFoot] = HumanBone.LeftLowerLeg;
            p[(int)HumanBone.RightFoot] = HumanBone.RightLowerLeg;
            p[(int)HumanBone.LeftToes] = HumanBone.LeftFoot;
            p[(int)HumanBone.RightToes] = HumanBone.RightFoot;
            p[(int)HumanBone.Spine] = HumanBone.Hips;
            p[(int)HumanBone.Chest] = HumanBone.Spine;
            p[(int)HumanBone.UpperChest] = HumanBone.Chest;
            p[(int)HumanBone.Neck] = HumanBone.UpperChest;
            p[(int)HumanBone.Head] = HumanBone.Neck;
            p[(int)HumanBone.LeftEye] = HumanBone.Head;
            p[(int)HumanBone.RightEye] = HumanBone.Head;
            p[(int)HumanBone.Jaw] = HumanBone.Head;
            p[(int)HumanBone.LeftShoulder] = HumanBone.UpperChest;
            p[(int)HumanBone.RightShoulder] = HumanBone.UpperChest;
            p[(int)HumanBone.LeftUpperArm] = HumanBone.LeftShoulder;
            p[(int)HumanBone.RightUpperArm] = HumanBone.RightShoulder;
            p[(int)HumanBone.LeftLowerArm] = HumanBone.LeftUpperArm;
            p[(int)HumanBone.RightLowerArm] = HumanBone.RightUpperArm;
            p[(int)HumanBone.LeftHand] = HumanBone.LeftLowerArm;
            p[(int)HumanBone.RightHand] = HumanBone.RightLowerArm;
            for (int side = 0; side < 2; side++)
            {
                bool left = side == 0;
                HumanBone hand = left ? HumanBone.LeftHand : HumanBone.RightHand;
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
