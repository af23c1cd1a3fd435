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

        /// <summary>
        /// The end effectors: the joints the six devices drive (hips, head, both hands, both feet), in the order every error
        /// report lists them.
        /// </summary>
        public static readonly HumanoidBone[] EndEffectors =
            { HumanoidBone.Hips, HumanoidBone.Head, HumanoidBone.LeftHand, HumanoidBone.RightHand, HumanoidBone.LeftFoot, HumanoidBone.RightFoot };

        /// <summary>The mid joints no device drives, which the IK places: the elbows and the knees.</summary>
        public static readonly HumanoidBone[] MidJoints =
            { HumanoidBone.LeftLowerArm, HumanoidBone.RightLowerArm, HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg };

        private static readonly bool[] EndEffectorFlags = Flags(EndEffectors);
        private static readonly bool[] MidJointFlags = Flags(MidJoints);

        /// <summary>True for a bone of <see cref="EndEffectors"/> (a table read).</summary>
        public static bool IsEndEffector(HumanoidBone bone) => IsValid(bone) && EndEffectorFlags[(int)bone];

        /// <summary>True for a bone of <see cref="MidJoints"/> (a table read).</summary>
        public static bool IsMidJoint(HumanoidBone bone) => IsValid(bone) && MidJointFlags[(int)bone];

        private static bool[] Flags(HumanoidBone[] bones)
        {
            var flags = new bool[Count];
            foreach (HumanoidBone bone in bones) flags[(int)bone] = true;
            return flags;
        }

        /// <summary>True for a bone listed in <see cref="Required"/>.</summary>
        public static bool IsRequired(HumanoidBone bone) => Array.IndexOf(Required, bone) >= 0;

        /// <summary>True for a valid bone value (not <see cref="HumanoidBone.LastBone"/>, not out of range).</summary>
        public static bool IsValid(HumanoidBone bone) => bone >= HumanoidBone.Hips && bone < HumanoidBone.LastBone;

        /// <summary>True for the 30 finger bones.</summary>
        public static bool IsFinger(HumanoidBone bone) =>
            bone >= HumanoidBone.LeftThumbProximal && bone <= HumanoidBone.RightLittleDistal;

        /// <summary>True for a bone of the left side of the body.</summary>
        public static bool IsLeft(HumanoidBone bone) => IsValid(bone) && Sides[(int)bone] == SideOfLeft;

        /// <summary>True for a bone of the right side of the body.</summary>
        public static bool IsRight(HumanoidBone bone) => IsValid(bone) && Sides[(int)bone] == SideOfRight;

        /// <summary>
        /// The bone's parent in the humanoid hierarchy (for <see cref="HumanoidBone.Hips"/>, <see cref="HumanoidBone.LastBone"/>).
        /// Optional bones are included: the parent of <see cref="HumanoidBone.Neck"/> is <see cref="HumanoidBone.UpperChest"/>.
        /// </summary>
        public static HumanoidBone Parent(HumanoidBone bone) => IsValid(bone) ? Parents[(int)bone] : HumanoidBone.LastBone;

        /// <summary>The same bone on the other side of the body; a centre bone is its own mirror.</summary>
        public static HumanoidBone Mirror(HumanoidBone bone) => IsValid(bone) ? Mirrors[(int)bone] : bone;

        /// <summary>
        /// The bone on <paramref name="side"/> that <paramref name="leftBone"/> names on the left, for example
        /// <c>OnSide(HumanoidBone.LeftHand, BodySide.Right)</c> is <see cref="HumanoidBone.RightHand"/>.
        /// </summary>
        /// <exception cref="ArgumentException"><paramref name="leftBone"/> is not a bone of the left side.</exception>
        public static HumanoidBone OnSide(HumanoidBone leftBone, BodySide side)
        {
            if (!IsLeft(leftBone)) throw new ArgumentException($"{leftBone} is not a bone of the left side.", nameof(leftBone));
            return side == BodySide.Left ? leftBone : Mirrors[(int)leftBone];
        }

        /// <summary>The finger bone of one hand: <paramref name="finger"/>'s <paramref name="phalanx"/>.</summary>
        public static HumanoidBone Finger(BodySide side, Finger finger, Phalanx phalanx)
        {
            if ((uint)finger > 4) throw new ArgumentOutOfRangeException(nameof(finger), finger, "Not a finger.");
            if ((uint)phalanx > 2) throw new ArgumentOutOfRangeException(nameof(phalanx), phalanx, "Not a finger joint.");
            int first = side == BodySide.Left ? (int)HumanoidBone.LeftThumbProximal : (int)HumanoidBone.RightThumbProximal;
            return (HumanoidBone)(first + (int)finger * 3 + (int)phalanx);
        }

        private const byte SideOfCentre = 0, SideOfLeft = 1, SideOfRight = 2;
        private static readonly byte[] Sides = BuildSides();
        private static readonly HumanoidBone[] Mirrors = BuildMirrors();

        // Sides and mirrors from the enum names once, so the per-frame lookups above are table reads.
        private static byte[] BuildSides()
        {
            var sides = new byte[Count];
            for (int b = 0; b < Count; b++)
            {
                string name = ((HumanoidBone)b).ToString();
                sides[b] = name.StartsWith("Left", StringComparison.Ordinal) ? SideOfLeft
                    : name.StartsWith("Right", StringComparison.Ordinal) ? SideOfRight : SideOfCentre;
            }
            return sides;
        }

        private static HumanoidBone[] BuildMirrors()
        {
            var mirrors = new HumanoidBone[Count];
            for (int b = 0; b < Count; b++)
            {
                string name = ((HumanoidBone)b).ToString();
                mirrors[b] = name.StartsWith("Left", StringComparison.Ordinal) ? (HumanoidBone)Enum.Parse(typeof(HumanoidBone), "Right" + name.Substring(4))
                    : name.StartsWith("Right", StringComparison.Ordinal) ? (HumanoidBone)Enum.Parse(typeof(HumanoidBone), "Left" + name.Substring(5))
                    : (HumanoidBone)b;
            }
            return mirrors;
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
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HumanoidBone hand = side == BodySide.Left ? HumanoidBone.LeftHand : HumanoidBone.RightHand;
                for (Finger finger = Core.Finger.Thumb; finger <= Core.Finger.Little; finger++)
                {
                    p[(int)Finger(side, finger, Phalanx.Proximal)] = hand;
                    p[(int)Finger(side, finger, Phalanx.Intermediate)] = Finger(side, finger, Phalanx.Proximal);
                    p[(int)Finger(side, finger, Phalanx.Distal)] = Finger(side, finger, Phalanx.Intermediate);
                }
            }
            return p;
        }
    }
}
