using System;
using System.Collections.Generic;
using System.Globalization;

namespace AvatarGo.Core
{
    /// <summary>
    /// Finds the humanoid bones of a skeleton from its joint names and hierarchy. Recognises Mixamo
    /// (<c>mixamorig:LeftUpLeg</c>, any <c>prefix:</c>), Ubisoft/LaFAN (<c>LeftUpLeg</c>, <c>LeftLeg</c>,
    /// <c>LeftToe</c>, <c>Spine1</c>), CMU/MocapBank (<c>Chest</c>, <c>LeftCollar</c>, <c>LeftShoulder</c> = upper
    /// arm, <c>LeftElbow</c>, <c>LeftWrist</c>, <c>LeftHip</c>, <c>LeftKnee</c>, <c>LeftAnkle</c>), Rigify
    /// (<c>pelvis</c>, <c>spine.001</c>, <c>upper_arm.L</c>, <c>thigh.L</c>, <c>shin.L</c>, <c>f_index.01.L</c>), Unreal
    /// (<c>thigh_l</c>, <c>calf_l</c>, <c>upperarm_l</c>, <c>neck_01</c>, <c>index_01_l</c>), Unity-style names
    /// (<c>LeftUpperArm</c>, <c>LeftLowerLeg</c>; Xsens MVN's <c>T8</c>, <c>LeftForeArm</c>; Bandai Namco's <c>UpperArm_L</c>),
    /// SMPL (<c>L_Collar</c>, <c>L_Shoulder</c> = upper arm, <c>L_Elbow</c>, <c>L_Knee</c>), VRoid/VRM
    /// (<c>J_Bip_C_Hips</c>, <c>J_Bip_L_UpperArm</c>), 3ds Max Biped (<c>Bip01_L_Clavicle</c>, <c>Bip01_L_Calf</c>), Character
    /// Creator / iClone (<c>CC_Base_Hip</c>, <c>CC_Base_L_Upperarm</c>, <c>CC_Base_NeckTwist01</c>), Daz Genesis (<c>hip</c>,
    /// <c>lShldrBend</c>, <c>lForearmBend</c>, <c>lThighBend</c>, <c>lShin</c>, <c>neckLower</c>), HumanIK
    /// (<c>Character1_LeftArm</c>), ARKit (<c>left_upLeg_joint</c>, <c>left_shoulder_1_joint</c>) and Meta
    /// (<c>FullBody_LeftArmUpper</c>, <c>FullBody_LeftFootAnkle</c>), and the CMU database's ASF names (<c>root</c>,
    /// <c>lowerback</c>, <c>lclavicle</c>, <c>lhumerus</c>, <c>lradius</c>, <c>lwrist</c>, <c>lfemur</c>, <c>ltibia</c>),
    /// Rigify's deform bones (<c>DEF-upper_arm.L</c>, the neck and head <c>DEF-spine.004</c> and <c>DEF-spine.006</c>) and
    /// MakeHuman (<c>upperarm01.L</c>, <c>lowerleg01.L</c>, <c>clavicle.L</c>) and OptiTrack Motive (<c>Hip</c>, <c>Ab</c>,
    /// <c>LShoulder</c>, <c>LUArm</c>, <c>LFArm</c>, <c>LThigh</c>, <c>LShin</c>), Kinect v2 (<c>SpineBase</c>,
    /// <c>ShoulderLeft</c> = upper arm, <c>ElbowLeft</c>, <c>HipLeft</c>, <c>AnkleLeft</c> above <c>FootLeft</c>) and Azure
    /// Kinect (<c>PELVIS</c>, <c>CLAVICLE_LEFT</c>, <c>SHOULDER_LEFT</c>, <c>WRIST_LEFT</c> above <c>HAND_LEFT</c>). Fingers
    /// numbered by finger (<c>LeftHandIndex1</c>, <c>lMid1</c>), named by phalanx (<c>LeftIndexProximal</c>, VRM 1.0's
    /// <c>leftThumbMetacarpal</c>), 3ds Max Biped's <c>Finger0</c> to <c>Finger42</c>, MakeHuman's <c>finger1-1</c> to
    /// <c>finger5-3</c> and Xsens MVN's gloves (<c>LeftFirstMC</c> to <c>LeftFifthDP</c>). Explicit overrides win.
    /// </summary>
    /// <remarks>
    /// Rules worth knowing: <c>Shoulder</c> is the clavicle when the same side also has an <c>Arm</c>/<c>UpperArm</c>
    /// joint, otherwise (CMU, with a <c>Collar</c>) the upper arm; every key is tried as written before any is tried as a
    /// numbered segment, so MakeHuman's <c>clavicle</c> wins over its <c>shoulder01</c>. The spine chain is the unsided joints between
    /// the hips and the neck: the first is Spine, the second Chest, the third UpperChest. When a rig has no hand
    /// (or foot, or head) joint, the End Site that ends the forearm (shin, neck) plays it, so that every required
    /// bone is found on rigs like Rigify exports whose forearm ends in an End Site. A limb name missing as it is is tried as
    /// the first of numbered segments (<c>upperarm01</c>). Without a neck or head name, the spine goes on above the joint
    /// that carries the arms through joints named like it (<c>spine.003</c>, <c>spine.004</c>): the first is the neck, the
    /// last the head.
    /// </remarks>
    public static class HumanoidNaming
    {
        private enum Side { None, Left, Right }

        /// <summary>
        /// Detects the humanoid map of <paramref name="skeleton"/>. <paramref name="overrides"/> (joint name → bone)
        /// are applied first and win over detection. Bones that cannot be found are left unmapped; check
        /// <see cref="HumanoidMap.MissingRequired"/>.
        /// </summary>
        /// <exception cref="ArgumentException">An override names a joint the skeleton does not have.</exception>
        public static HumanoidMap Detect(Skeleton skeleton, IReadOnlyDictionary<string, HumanoidBone> overrides = null)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            int n = skeleton.JointCount;
            var sides = new Side[n];
            var cores = new string[n];
            ReadNames(skeleton, sides, cores);

            var bones = new Dictionary<HumanoidBone, int>();
            var used = new HashSet<int>();
            if (overrides != null)
            {
                foreach (var pair in overrides)
                {
                    int joint = skeleton.IndexOf(pair.Key);
                    if (joint < 0) throw new ArgumentException($"Override names joint '{pair.Key}', which the skeleton does not have.", nameof(overrides));
                    bones[pair.Value] = joint;
                    used.Add(joint);
                }
            }

            void Put(HumanoidBone bone, int joint)
            {
                if (joint < 0 || bones.ContainsKey(bone) || used.Contains(joint)) return;
                bones[bone] = joint;
                used.Add(joint);
            }

            // Hips: a "hips" joint, else the unsided pelvis/hip joint nearest the root (Daz and Character Creator have a "hip"
            // above their "pelvis", the legs under the one and the spine under the other), else the first root with children.
            // Without such a name (Rigify's DEF-spine, MakeHuman's root), the joint both thighs hang from, else the first root.
            int hips = Find(skeleton, cores, sides, Side.None, -1, "hips");
            if (hips < 0) hips = Shallowest(skeleton, cores, sides, "pelvis", "hip");
            if (hips < 0) hips = CommonAncestor(skeleton, Find(skeleton, cores, sides, Side.Left, -1, UpperLegKeys), Find(skeleton, cores, sides, Side.Right, -1, UpperLegKeys), required: true);
            if (hips < 0) hips = 0;
            Put(HumanoidBone.Hips, hips);
            hips = bones.TryGetValue(HumanoidBone.Hips, out int h) ? h : hips;

            foreach (Side side in new[] { Side.Left, Side.Right })
            {
                bool left = side == Side.Left;
                // Legs.
                int upLeg = Find(skeleton, cores, sides, side, hips, UpperLegKeys);
                int lowLeg = Find(skeleton, cores, sides, side, upLeg, "leg", "lowerleg", "shin", "knee", "calf", "tibia", "leglower");
                // An "ankle" above a "foot" is the foot bone (the shin ends there): the toes are a toe-named joint below it, else
                // the "foot" (SMPL: L_Ankle, then L_Foot at the toes).
                int foot = Find(skeleton, cores, sides, side, lowLeg, "foot", "ankle", "footankle");
                int ankle = Find(skeleton, cores, sides, side, lowLeg, "ankle");
                int toes = Find(skeleton, cores, sides, side, foot, "toebase", "toe", "toes", "ball", "toe0", "football", "toe11"); // toe11: MakeHuman's big toe, toe1-1
                if (ankle >= 0 && foot >= 0 && foot != ankle && skeleton.IsAncestorOrSelf(ankle, foot))
                {
                    if (toes < 0) toes = foot;
                    foot = ankle;
                }
                if (foot < 0) foot = EndSiteOf(skeleton, lowLeg);
                Put(left ? HumanoidBone.LeftUpperLeg : HumanoidBone.RightUpperLeg, upLeg);
                Put(left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg, lowLeg);
                Put(left ? HumanoidBone.LeftFoot : HumanoidBone.RightFoot, foot);
                if (toes >= 0 && !skeleton.IsEndSite(toes)) Put(left ? HumanoidBone.LeftToes : HumanoidBone.RightToes, toes);

                // Arms: is "shoulder" the clavicle or the upper arm on this side?
                bool hasArm = FindAnywhere(cores, sides, side, UpperArmKeys) >= 0;
                int clavicle = hasArm
                    ? Find(skeleton, cores, sides, side, hips, "shoulder", "clavicle", "collar", "shoulder1")
                    : Find(skeleton, cores, sides, side, hips, "clavicle", "collar");
                int upArm = hasArm
                    ? Find(skeleton, cores, sides, side, clavicle >= 0 ? clavicle : hips, UpperArmKeys)
                    : Find(skeleton, cores, sides, side, clavicle >= 0 ? clavicle : hips, "shoulder", "humerus", "shldr");
                int foreArm = Find(skeleton, cores, sides, side, upArm, "forearm", "lowerarm", "elbow", "radius", "armlower", "farm");
                // A "wrist" above a "hand" (SMPL: L_Wrist, then L_Hand at the knuckles) is the hand bone.
                int hand = Find(skeleton, cores, sides, side, foreArm, "hand", "wrist", "handwrist");
                int wrist = Find(skeleton, cores, sides, side, foreArm, "wrist");
                if (wrist >= 0 && hand >= 0 && hand != wrist && skeleton.IsAncestorOrSelf(wrist, hand)) hand = wrist;
                if (hand < 0) hand = EndSiteOf(skeleton, foreArm);
                Put(left ? HumanoidBone.LeftShoulder : HumanoidBone.RightShoulder, clavicle);
                Put(left ? HumanoidBone.LeftUpperArm : HumanoidBone.RightUpperArm, upArm);
                Put(left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm, foreArm);
                Put(left ? HumanoidBone.LeftHand : HumanoidBone.RightHand, hand);

                // Fingers: three phalanges per finger, below the hand.
                if (hand >= 0 && !skeleton.IsEndSite(hand))
                {
                    BodySide bodySide = left ? BodySide.Left : BodySide.Right;
                    FingerNumbering numbering = NumberingOf(skeleton, cores, sides, side, hand);
                    for (int f = 0; f < 5; f++)
                    {
                        int parent = hand;
                        for (int phalanx = 0; phalanx < 3; phalanx++)
                        {
                            int joint = FindPhalanx(skeleton, cores, sides, side, hand, parent, numbering, f, phalanx);
                            if (joint < 0) break;
                            Put(HumanoidBones.Finger(bodySide, (Finger)f, (Phalanx)phalanx), joint);
                            parent = joint;
                        }
                    }
                }

                int eye = Find(skeleton, cores, sides, side, hips, "eye");
                if (eye >= 0 && !skeleton.IsEndSite(eye)) Put(left ? HumanoidBone.LeftEye : HumanoidBone.RightEye, eye);
            }

            // Neck and head.
            int neck = Find(skeleton, cores, sides, Side.None, hips, "neck", "neck1", "neck01", "necklower", "necktwist01", "lowerneck");
            int head = Find(skeleton, cores, sides, Side.None, neck >= 0 ? neck : hips, "head");
            if (head < 0) head = Find(skeleton, cores, sides, Side.None, neck >= 0 ? neck : hips, "face");
            if (head < 0 && neck >= 0) head = EndSiteOf(skeleton, neck);
            if (neck < 0 && head < 0) SpineAboveTheArms(skeleton, cores, sides, used, ArmCarrier(skeleton, bones), out neck, out head);
            Put(HumanoidBone.Neck, neck);
            Put(HumanoidBone.Head, head);
            int jaw = Find(skeleton, cores, sides, Side.None, head, "jaw");
            if (jaw >= 0 && !skeleton.IsEndSite(jaw)) Put(HumanoidBone.Jaw, jaw);

            // Spine chain: unsided joints strictly between the hips and the neck (or the arms' attachment).
            int top = neck >= 0 ? skeleton.GetParent(neck)
                : bones.TryGetValue(HumanoidBone.LeftUpperArm, out int la) ? skeleton.GetParent(la)
                : head >= 0 ? skeleton.GetParent(head) : -1;
            if (bones.TryGetValue(HumanoidBone.LeftShoulder, out int ls)) top = CommonAncestor(skeleton, top, skeleton.GetParent(ls));
            var chain = new List<int>();
            for (int j = top; j >= 0 && j != hips; j = skeleton.GetParent(j))
                if (!used.Contains(j) && sides[j] == Side.None && !skeleton.IsEndSite(j)) chain.Add(j);
            chain.Reverse(); // hips-first (built by Add, then reversed: Insert(0, …) was quadratic on deep chains)
            if (chain.Count > 0 && skeleton.IsAncestorOrSelf(hips, chain[0]))
            {
                Put(HumanoidBone.Spine, chain[0]);
                if (chain.Count > 1) Put(HumanoidBone.Chest, chain[1]);
                if (chain.Count > 2) Put(HumanoidBone.UpperChest, chain[chain.Count - 1]);
            }

            var pairs = new List<KeyValuePair<HumanoidBone, string>>();
            foreach (var pair in bones) pairs.Add(new KeyValuePair<HumanoidBone, string>(pair.Key, skeleton.GetName(pair.Value)));
            return new HumanoidMap(skeleton, pairs);
        }

        // The joint both arms hang from (the parent of the clavicles, else of the upper arms), or -1.
        private static int ArmCarrier(Skeleton s, Dictionary<HumanoidBone, int> bones)
        {
            int Parent(HumanoidBone clavicle, HumanoidBone upperArm) =>
                bones.TryGetValue(clavicle, out int c) ? s.GetParent(c) : bones.TryGetValue(upperArm, out int a) ? s.GetParent(a) : -1;
            int left = Parent(HumanoidBone.LeftShoulder, HumanoidBone.LeftUpperArm), right = Parent(HumanoidBone.RightShoulder, HumanoidBone.RightUpperArm);
            return left >= 0 && right >= 0 ? CommonAncestor(s, left, right, required: true) : -1;
        }

        // A spine named without a neck or a head (Rigify's DEF-spine.004 to .006, any numbered chain): it goes on above the
        // joint that carries the arms through the unsided joints named like that joint (the same letters, other digits); the
        // first is the neck and the last the head, a chain of one joint the head alone. Joints named otherwise are not
        // followed: a jaw, a hair strand or a prop under an unnamed head would make a wrong head, where a missing one is a
        // clear error.
        private static void SpineAboveTheArms(Skeleton s, string[] cores, Side[] sides, HashSet<int> used, int carrier, out int neck, out int head)
        {
            neck = head = -1;
            if (carrier < 0) return;
            string stem = Stem(cores[carrier]);
            if (stem.Length == 0) return;
            var chain = new List<int>();
            for (int next = SpineChildNamed(s, cores, sides, used, carrier, stem); next >= 0; next = SpineChildNamed(s, cores, sides, used, next, stem))
                chain.Add(next);
            if (chain.Count == 0) return;
            head = chain[chain.Count - 1];
            if (chain.Count > 1) neck = chain[0];
        }

        // The one unsided, unused child of `at` (not an End Site) whose name has the letters `stem`; -1 when there is none or
        // more than one.
        private static int SpineChildNamed(Skeleton s, string[] cores, Side[] sides, HashSet<int> used, int at, string stem)
        {
            int found = -1, count = 0;
            for (int j = at + 1; j < s.JointCount; j++)
            {
                if (s.GetParent(j) != at || s.IsEndSite(j) || sides[j] != Side.None || used.Contains(j) || Stem(cores[j]) != stem) continue;
                found = j;
                count++;
            }
            return count == 1 ? found : -1;
        }

        // A core name without its digits ("spine004" → "spine").
        private static string Stem(string core) => core.TrimEnd('0', '1', '2', '3', '4', '5', '6', '7', '8', '9');

        private static int CommonAncestor(Skeleton s, int a, int b, bool required = false)
        {
            if (required && (a < 0 || b < 0)) return -1;
            if (a < 0) return b;
            if (b < 0) return a;
            for (int x = a; x >= 0; x = s.GetParent(x))
                if (s.IsAncestorOrSelf(x, b)) return x;
            return -1;
        }

        private static int EndSiteOf(Skeleton s, int joint)
        {
            if (joint < 0) return -1;
            for (int j = joint + 1; j < s.JointCount; j++)
                if (s.GetParent(j) == joint && s.IsEndSite(j)) return j;
            return -1;
        }

        // The first joint (in hierarchy order) below `under` (any depth; anywhere when under is -1) on the
        // given side whose core name equals one of the keys, trying keys in order of preference.
        // A name missing that way is tried again as the first of numbered segments (MakeHuman's upperarm01, lowerleg01).
        private static int Find(Skeleton s, string[] cores, Side[] sides, Side side, int under, params string[] keys)
        {
            foreach (string suffix in SegmentSuffixes)
                foreach (string key in keys)
                    for (int j = 0; j < cores.Length; j++)
                        if (sides[j] == side && IsNamed(cores[j], key, suffix) && !s.IsEndSite(j) && (under < 0 || (j != under && s.IsAncestorOrSelf(under, j))))
                            return j;
            return -1;
        }

        // The exact name first, then the first of numbered segments.
        private static readonly string[] SegmentSuffixes = { "", "01", "001" };

        private static readonly string[] UpperLegKeys = { "upleg", "upperleg", "thigh", "hip", "femur", "legupper" };

        private static readonly string[] UpperArmKeys = { "arm", "upperarm", "uparm", "armupper", "uarm" };

        // The unsided joint whose core name is one of the keys with the fewest ancestors (the first in hierarchy order among
        // equals), or -1.
        private static int Shallowest(Skeleton s, string[] cores, Side[] sides, params string[] keys)
        {
            int best = -1, bestDepth = int.MaxValue;
            for (int j = 0; j < cores.Length; j++)
            {
                if (sides[j] != Side.None || s.IsEndSite(j) || Array.IndexOf(keys, cores[j]) < 0) continue;
                int depth = 0;
                for (int p = s.GetParent(j); p >= 0; p = s.GetParent(p)) depth++;
                if (depth < bestDepth) { best = j; bestDepth = depth; }
            }
            return best;
        }

        private static int FindAnywhere(string[] cores, Side[] sides, Side side, params string[] keys)
        {
            foreach (string suffix in SegmentSuffixes)
                foreach (string key in keys)
                    for (int j = 0; j < cores.Length; j++)
                        if (sides[j] == side && IsNamed(cores[j], key, suffix)) return j;
            return -1;
        }

        // core == key + suffix, without building the string.
        private static bool IsNamed(string core, string key, string suffix) =>
            core.Length == key.Length + suffix.Length && core.StartsWith(key, StringComparison.Ordinal) && core.EndsWith(suffix, StringComparison.Ordinal);

        // How a rig names its fingers' phalanges. By finger: a finger word and the phalanx's number or name (Mixamo's
        // LeftHandIndex1, Unreal's index_01_l, Rigify's f_index.01.L, Unity's and VRM's LeftIndexProximal); 3ds Max Biped's
        // Finger0 (thumb) to Finger4, their phalanges Finger0, Finger01, Finger02; MakeHuman's finger1-1 (thumb) to finger5-3.
        private enum FingerNumbering { ByFinger, Biped, MakeHuman }

        // The finger words, thumb to little finger (Daz and Character Creator call the middle finger "Mid"; Xsens MVN's
        // gloves count them, LeftFirstMC to LeftFifthDP).
        private static readonly string[][] FingerWords =
        {
            new[] { "thumb", "first" }, new[] { "index", "second" }, new[] { "middle", "mid", "third" }, new[] { "ring", "fourth" },
            new[] { "pinky", "little", "fifth" },
        };

        // Xsens MVN's segments: the thumb's metacarpal, proximal and distal phalanges (MC, PP, DP), the other fingers'
        // proximal, middle and distal ones (PP, MP, DP; their metacarpals are not humanoid bones).
        private static readonly string[] XsensThumb = { "mc", "pp", "dp" };
        private static readonly string[] XsensFinger = { "pp", "mp", "dp" };

        // Phalanges by name, proximal first. A thumb with a metacarpal (VRM 1.0, OpenXR, Meta) has a proximal and a distal
        // after it, and its metacarpal is the humanoid thumb's first bone, as Unity maps it; the other fingers' metacarpals
        // are not humanoid bones.
        private static readonly string[] PhalanxWords = { "proximal", "intermediate", "distal" };
        private static readonly string[] ThumbWithMetacarpal = { "metacarpal", "proximal", "distal" };

        // Biped when a Finger0 is under the hand, or a Finger1 with its Finger11 (a Biped hand exported without its thumb);
        // MakeHuman when a finger1-1 is without either (MakeHuman has no plain finger1; Biped's Finger11 is the index finger's
        // second phalanx), else by finger.
        private static FingerNumbering NumberingOf(Skeleton s, string[] cores, Side[] sides, Side side, int hand)
        {
            if (FindUnderHand(s, cores, sides, side, hand, hand, "finger0") >= 0) return FingerNumbering.Biped;
            if (FindUnderHand(s, cores, sides, side, hand, hand, "finger1") >= 0 && FindUnderHand(s, cores, sides, side, hand, hand, "finger11") >= 0)
                return FingerNumbering.Biped;
            if (FindUnderHand(s, cores, sides, side, hand, hand, "finger11") >= 0) return FingerNumbering.MakeHuman;
            return FingerNumbering.ByFinger;
        }

        // Phalanx `phalanx` (0 proximal to 2 distal) of finger `finger` (0 thumb to 4 little), below `under` (the hand or the
        // previous phalanx).
        private static int FindPhalanx(Skeleton s, string[] cores, Side[] sides, Side side, int hand, int under, FingerNumbering numbering, int finger, int phalanx)
        {
            string number = (phalanx + 1).ToString(CultureInfo.InvariantCulture);
            switch (numbering)
            {
                case FingerNumbering.Biped:
                    return FindUnderHand(s, cores, sides, side, hand, under, "finger" + finger.ToString(CultureInfo.InvariantCulture) + (phalanx == 0 ? "" : phalanx.ToString(CultureInfo.InvariantCulture)));
                case FingerNumbering.MakeHuman:
                    return FindUnderHand(s, cores, sides, side, hand, under, "finger" + (finger + 1).ToString(CultureInfo.InvariantCulture) + number);
            }
            foreach (string word in FingerWords[finger])
            {
                string[] named = finger == 0 && FindUnderHand(s, cores, sides, side, hand, hand, word + "metacarpal") >= 0 ? ThumbWithMetacarpal : PhalanxWords;
                int joint = FindUnderHand(s, cores, sides, side, hand, under, word + number, word + "0" + number, word + named[phalanx],
                    word + (finger == 0 ? XsensThumb : XsensFinger)[phalanx]);
                if (joint >= 0) return joint;
            }
            return -1;
        }

        // The first joint below `under` on the side whose core name, after the hand's own prefix (Mixamo's LeftHandIndex1,
        // Meta's LeftHandIndexProximal) or Rigify's f_ (f_index.01.L), is one of the keys.
        private static int FindUnderHand(Skeleton s, string[] cores, Side[] sides, Side side, int hand, int under, params string[] keys)
        {
            foreach (string key in keys)
                for (int j = 0; j < cores.Length; j++)
                {
                    if (sides[j] != side || s.IsEndSite(j) || j == under || !s.IsAncestorOrSelf(under, j) || !s.IsAncestorOrSelf(hand, j)) continue;
                    string c = cores[j];
                    if (c.StartsWith("hand", StringComparison.Ordinal)) c = c.Substring(4);
                    if (c == key) return j;
                    // Rigify's f_index.01.L: the f is not part of the finger's name (Xsens's FirstMC and FifthDP are).
                    if (c.Length == key.Length + 1 && c[0] == 'f' && string.CompareOrdinal(c, 1, key, 0, key.Length) == 0) return j;
                }
            return -1;
        }

        // Every joint's side and core name. The sides of OptiTrack Motive (LUArm) and Kinect (ShoulderLeft) names are read
        // only when they side more joints than every other rule does: on a rig named otherwise a facial EyeLeft or a helper
        // HandRight must not take a bone from LeftEye or RightHand.
        private static void ReadNames(Skeleton skeleton, Side[] sides, string[] cores)
        {
            int n = skeleton.JointCount, strong = 0, weak = 0;
            var weakSides = new Side[n];
            var weakCores = new string[n];
            for (int j = 0; j < n; j++)
            {
                Normalise(skeleton.GetName(j), false, out sides[j], out cores[j]);
                if (sides[j] != Side.None) strong++;
                Normalise(skeleton.GetName(j), true, out weakSides[j], out weakCores[j]);
                if (weakSides[j] != sides[j]) weak++;
            }
            if (weak <= strong) return;
            Array.Copy(weakSides, sides, n);
            Array.Copy(weakCores, cores, n);
        }

        // Strips a namespace ("mixamorig:"), finds the side (Left/Right prefix, L_/R_ prefix, .L/_L/.R/_R suffix, Daz's
        // lowercase l/r before a capital, or an L/R/C token after a rig prefix: VRoid's J_Bip_L_UpperArm, 3ds Max Biped's
        // Bip01_L_Thigh; with `motionCapture`, also OptiTrack Motive's capital L/R before a capitalised segment and Kinect's
        // side as a last word), drops a Biped "Bip01" prefix and Daz's "Bend" suffix, and reduces the rest to lower-case
        // letters and digits.
        private static void Normalise(string name, bool motionCapture, out Side side, out string core)
        {
            int colon = name.LastIndexOf(':');
            string s = colon >= 0 ? name.Substring(colon + 1) : name;
            s = StripRigAffixes(s);
            string lower = s.ToLowerInvariant();
            side = Side.None;
            // Daz: a lowercase l or r before a capitalised word (lShldrBend, rThighBend); CMU's ASF names: l or r before a bone
            // (lhumerus, rfemur).
            if (s.Length >= 3 && (s[0] == 'l' || s[0] == 'r') && char.IsUpper(s[1]) && char.IsLower(s[2])) { side = s[0] == 'l' ? Side.Left : Side.Right; lower = lower.Substring(1); }
            else if (lower.Length > 1 && (lower[0] == 'l' || lower[0] == 'r') && Array.IndexOf(AsfBones, lower.Substring(1)) >= 0) { side = lower[0] == 'l' ? Side.Left : Side.Right; lower = lower.Substring(1); }
            else if (SideToken(lower, out Side tokenSide, out string rest)) { side = tokenSide; lower = rest; }
            else if (lower.StartsWith("left", StringComparison.Ordinal)) { side = Side.Left; lower = lower.Substring(4); }
            else if (lower.StartsWith("right", StringComparison.Ordinal)) { side = Side.Right; lower = lower.Substring(5); }
            else if (lower.StartsWith("l_", StringComparison.Ordinal) || lower.StartsWith("l.", StringComparison.Ordinal)) { side = Side.Left; lower = lower.Substring(2); }
            else if (lower.StartsWith("r_", StringComparison.Ordinal) || lower.StartsWith("r.", StringComparison.Ordinal)) { side = Side.Right; lower = lower.Substring(2); }
            else if (lower.EndsWith(".l", StringComparison.Ordinal) || lower.EndsWith("_l", StringComparison.Ordinal)) { side = Side.Left; lower = lower.Substring(0, lower.Length - 2); }
            else if (lower.EndsWith(".r", StringComparison.Ordinal) || lower.EndsWith("_r", StringComparison.Ordinal)) { side = Side.Right; lower = lower.Substring(0, lower.Length - 2); }
            else if (motionCapture && CapitalSideFirst(s)) { side = s[0] == 'L' ? Side.Left : Side.Right; lower = lower.Substring(1); }
            else if (motionCapture && SideWordLast(s, lower, "left", out string before)) { side = Side.Left; lower = before; }
            else if (motionCapture && SideWordLast(s, lower, "right", out before)) { side = Side.Right; lower = before; }
            var chars = new System.Text.StringBuilder(lower.Length);
            foreach (char c in lower)
                if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) chars.Append(c);
            core = chars.ToString();
            if (core.Length > 4 && core.EndsWith("bend", StringComparison.Ordinal)) core = core.Substring(0, core.Length - 4);
        }

        // OptiTrack Motive: a capital L or R before a capitalised segment (LShoulder, LUArm, LFArm, RThigh), not a word in
        // capitals (LUMBAR, LOD0, RIGHTARM).
        private static bool CapitalSideFirst(string s) =>
            s.Length >= 3 && (s[0] == 'L' || s[0] == 'R') && char.IsUpper(s[1])
            && (char.IsLower(s[2]) || (s.Length >= 4 && char.IsUpper(s[2]) && char.IsLower(s[3])));

        private static readonly char[] Separators = { '_', ' ', '.', '-' };

        // Kinect: true when `name` ends in the word after something, capitalised after a lower-case letter or a digit
        // (ShoulderLeft) or after a separator (SHOULDER_LEFT, hand.left), not a word ending in it (Upright, UPRIGHT): the
        // name before it.
        private static bool SideWordLast(string name, string lower, string word, out string before)
        {
            before = null;
            int at = lower.Length - word.Length;
            if (at < 1 || !lower.EndsWith(word, StringComparison.Ordinal)) return false;
            bool separated = Array.IndexOf(Separators, lower[at - 1]) >= 0;
            bool capitalised = char.IsUpper(name[at]) && char.IsLower(name[at + 1]) && (char.IsLower(name[at - 1]) || char.IsDigit(name[at - 1]));
            if (!separated && !capitalised) return false;
            before = lower.Substring(0, separated ? at - 1 : at);
            return before.Length > 0;
        }

        // The sided bones of the CMU database's ASF skeleton, named after the bone (lhumerus, rtibia).
        private static readonly string[] AsfBones = { "clavicle", "humerus", "radius", "wrist", "hand", "fingers", "thumb", "hipjoint", "femur", "tibia", "foot", "toes" };

        // Rigify's DEF- prefix, a namespace written with an underscore (HumanIK's Character1_, Meta's FullBody_, OptiTrack
        // Motive's Skeleton1_, SMPL's m_avg_) and ARKit's _joint suffix, which carry no side and no bone.
        private static string StripRigAffixes(string name)
        {
            string lower = name.ToLowerInvariant();
            if (lower.StartsWith("def-", StringComparison.Ordinal) && name.Length > 4) { name = name.Substring(4); lower = lower.Substring(4); } // Rigify's deform bones
            if (lower.EndsWith("_joint", StringComparison.Ordinal) && name.Length > 6) { name = name.Substring(0, name.Length - 6); lower = lower.Substring(0, lower.Length - 6); }
            int underscore = lower.IndexOf('_');
            if (underscore > 0 && underscore < lower.Length - 1)
            {
                string prefix = lower.Substring(0, underscore);
                if (IsNumbered(prefix, "character") || IsNumbered(prefix, "skeleton") || prefix == "fullbody") name = name.Substring(underscore + 1);
                else if ((prefix == "m" || prefix == "f") && lower.StartsWith(prefix + "_avg_", StringComparison.Ordinal) && lower.Length > 6)
                    name = name.Substring(6); // SMPL's FBX: m_avg_L_Hip, f_avg_Neck
            }
            return name;
        }

        // "character", "character1", "skeleton002": a word followed by digits only.
        private static bool IsNumbered(string token, string word)
        {
            if (!token.StartsWith(word, StringComparison.Ordinal)) return false;
            for (int i = word.Length; i < token.Length; i++)
                if (token[i] < '0' || token[i] > '9') return false;
            return true;
        }

        // A side token after a rig prefix ("j_bip_l_upperarm", "bip01_l_thigh", "cc_base_l_thigh"; "c" marks the centre), or a
        // Biped or Character Creator prefix alone ("bip01_pelvis", "cc_base_hip"): true with the side and the name after the token. A first token "l"/"r" is left to the
        // L_/R_ rule, a last one to the _L/_R rule.
        private static bool SideToken(string lower, out Side side, out string rest)
        {
            side = Side.None;
            rest = lower;
            string[] tokens = lower.Split(Separators, StringSplitOptions.RemoveEmptyEntries);
            for (int i = 1; i < tokens.Length - 1; i++)
            {
                string t = tokens[i];
                if (t != "l" && t != "r" && t != "c") continue;
                side = t == "l" ? Side.Left : t == "r" ? Side.Right : Side.None;
                rest = string.Join("_", tokens, i + 1, tokens.Length - i - 1);
                return true;
            }
            if (tokens.Length > 1 && IsBipedPrefix(tokens[0]))
            {
                rest = string.Join("_", tokens, 1, tokens.Length - 1);
                return true;
            }
            if (tokens.Length > 2 && tokens[0] == "cc" && tokens[1] == "base") // Character Creator / iClone: CC_Base_Hip
            {
                rest = string.Join("_", tokens, 2, tokens.Length - 2);
                return true;
            }
            return false;
        }

        // "bip", "bip01", "bip001": 3ds Max Biped's root name, which its bones' names start with.
        private static bool IsBipedPrefix(string token)
        {
            if (!token.StartsWith("bip", StringComparison.Ordinal)) return false;
            for (int i = 3; i < token.Length; i++)
                if (token[i] < '0' || token[i] > '9') return false;
            return true;
        }
    }
}
