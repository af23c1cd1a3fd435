using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Finds the humanoid bones of a skeleton from its hierarchy and how its joints move, not from their names: the
    /// fallback for rigs whose names <see cref="HumanoidNaming"/> cannot read (numbered joints, names in another language).
    /// It reads nothing that the rest pose or the bones' local axes decide: bone lengths and angles are measured on the
    /// joints' world positions in the frames given (lengths as medians over the frames, and a joint bends when it does in
    /// one frame in fifty and in two at least, so a glitch in one frame changes nothing).
    /// </summary>
    /// <remarks>
    /// The rules, in order (a person's proportions, not any rig's):
    /// <list type="number">
    /// <item>The two <b>hubs</b> are the joints where three or more long branches meet (each at least a fifth of the
    /// skeleton's longest path, hand to foot): the pelvis (two legs and the spine) and the chest (two arms and the spine).
    /// The chest is the hub with a further, shorter branch, the head; if both or neither have one, the hub whose limbs have
    /// the longer bones carries the legs. The hips are the lowest common ancestor of the two hubs.</item>
    /// <item>Each <b>limb</b> follows, from its hub, the child with the longest reach at every joint. Joints the limb passes
    /// straight through (within 3° but in fewer than two frames, or one in fifty: twist joints) or that sit on their parent
    /// are not articulations (of joints in one place, the first is). Of the segments between articulations, the two
    /// consecutive ones with the greatest total length, within a factor of 1.67 of each other and longer than every
    /// segment before them, are the upper and lower limb (thigh and shin, upper arm and forearm); the articulation they
    /// end at is the foot or hand, which must have a joint or an End Site beyond it; the joint after a foot is the toes,
    /// the first joint of an arm before its upper arm the clavicle.</item>
    /// <item>The <b>head</b> branch is the chest's longest other branch, at least 4 % of the longest path (8 cm) long; it
    /// is followed while it goes on through a single child turning less than 60°, and the head is its last joint there
    /// (not counting End Sites and a joint that only marks the end, Mixamo's <c>HeadTop_End</c>), so eyes, a jaw or a
    /// ponytail end it; the branch's first joint, when it is not the head, is the neck. The joints between the hips and
    /// the neck are the spine: Spine, Chest, UpperChest, as <see cref="HumanoidNaming"/> counts them.</item>
    /// <item><b>Sides</b>: each arm goes with the leg whose hip is nearer its shoulder; left is the side whose knees then bend
    /// forward (<see cref="KneeBend.Direction"/>); with no bent knee in the frames, the side the body's
    /// left is on when the toes point forward (in Unity's left-handed frame, in which <see cref="BvhClip"/> gives the joints).</item>
    /// </list>
    /// Fingers and eyes are not looked for: a hand found this way takes the walk-in offset, without finger IK.
    /// </remarks>
    public static class HumanoidStructure
    {
        /// <summary>A long branch is at least this share of the skeleton's longest path (hand to foot, ~2 m: 40 cm).</summary>
        public const float LongBranchShare = 0.2f;

        /// <summary>The head branch is at least this share of the longest path long (~8 cm).</summary>
        public const float HeadHeightShare = 0.04f;

        /// <summary>
        /// A joint whose bones in and out stay within this angle (degrees) in all frames but fewer than two (or than one in
        /// fifty) is not an articulation.
        /// </summary>
        public const float StraightDegrees = 3f;

        /// <summary>The head branch goes on through a joint whose bone turns less than this (degrees) from the bone before.</summary>
        public const float HeadTurnDegrees = 60f;

        /// <summary>The upper and lower limb are within this factor of each other's length.</summary>
        public const float LimbPairRatio = 1.67f;

        /// <summary>The two legs (arms) are within this factor of each other's length, or the structure is refused.</summary>
        public const float SidesRatio = 1.25f;

        private const int MaximumFrames = 120;

        /// <summary>
        /// The humanoid map of <paramref name="clip"/>'s skeleton from its structure and up to 120 of its frames spread
        /// over the clip, or null with the reason in <paramref name="failure"/>.
        /// </summary>
        public static HumanoidMap Detect(BvhClip clip, out string failure)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            Skeleton s = clip.Skeleton;
            var frames = new List<Vector3[]>();
            var local = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            int count = Math.Max(1, clip.FrameCount);
            int samples = Math.Min(MaximumFrames, count);
            for (int k = 0; k < samples; k++)
            {
                if (clip.FrameCount > 0) clip.GetWorldPoses((int)((long)k * count / samples), local, world);
                else
                {
                    s.GetRestLocal(local);
                    s.ComputeWorld(local, world);
                }
                frames.Add(Positions(world));
            }
            return Detect(s, frames, out failure);
        }

        /// <summary>
        /// The humanoid map of <paramref name="skeleton"/> from its structure and the world positions of its joints in
        /// <paramref name="frames"/> (one array per frame, indexed by joint), or null with the reason in
        /// <paramref name="failure"/>.
        /// </summary>
        public static HumanoidMap Detect(Skeleton skeleton, IReadOnlyList<Vector3[]> frames, out string failure)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (frames == null) throw new ArgumentNullException(nameof(frames));
            if (frames.Count == 0) throw new ArgumentException("At least one frame is needed.", nameof(frames));
            foreach (Vector3[] frame in frames)
                if (frame == null || frame.Length != skeleton.JointCount)
                    throw new ArgumentException("Every frame needs one position per joint.", nameof(frames));
            return new Reading(skeleton, frames).Run(out failure);
        }

        private static Vector3[] Positions(RigidPose[] world)
        {
            var positions = new Vector3[world.Length];
            for (int j = 0; j < world.Length; j++) positions[j] = world[j].Position;
            return positions;
        }

        /// <summary>One reading of one skeleton: the measured lengths and reaches, then the rules above.</summary>
        private sealed class Reading
        {
            private readonly Skeleton _s;
            private readonly IReadOnlyList<Vector3[]> _frames;
            private readonly int _n;
            private readonly float[] _length;  // mean distance to the parent
            private readonly float[] _reach;   // longest path down from the joint
            private readonly float[] _up;      // longest path that leaves the joint through its parent
            private readonly List<int>[] _children;
            private readonly float[] _scratch;
            private float _longest;

            public Reading(Skeleton skeleton, IReadOnlyList<Vector3[]> frames)
            {
                _s = skeleton;
                _frames = frames;
                _n = skeleton.JointCount;
                _length = new float[_n];
                _reach = new float[_n];
                _up = new float[_n];
                _children = new List<int>[_n];
                _scratch = new float[frames.Count];
                for (int j = 0; j < _n; j++) _children[j] = new List<int>();
                for (int j = 0; j < _n; j++)
                {
                    int p = skeleton.GetParent(j);
                    if (p < 0) continue;
                    _children[p].Add(j);
                    _length[j] = Distance(j, p);
                }
                // Parents come before their children: reaches from the leaves up, the way up from the roots down.
                for (int j = _n - 1; j >= 0; j--)
                    foreach (int c in _children[j]) _reach[j] = Math.Max(_reach[j], _length[c] + _reach[c]);
                // The longest way on from a parent other than back down to j: its own way up, or its longest other child
                // (the best two children kept per parent, so a joint with thousands of children costs no more than one).
                var first = new int[_n];
                var second = new int[_n];
                for (int j = 0; j < _n; j++) first[j] = second[j] = -1;
                for (int j = 0; j < _n; j++)
                {
                    int p = skeleton.GetParent(j);
                    if (p < 0) continue;
                    if (first[p] < 0 || Branch(j) > Branch(first[p])) { second[p] = first[p]; first[p] = j; }
                    else if (second[p] < 0 || Branch(j) > Branch(second[p])) second[p] = j;
                }
                for (int j = 0; j < _n; j++)
                {
                    int p = skeleton.GetParent(j);
                    if (p < 0) continue;
                    int sibling = first[p] == j ? second[p] : first[p];
                    _up[j] = _length[j] + Math.Max(_up[p], sibling >= 0 ? Branch(sibling) : 0f);
                }
                for (int j = 0; j < _n; j++) _longest = Math.Max(_longest, _reach[j] + _up[j]);
            }

            /// <summary>The longest path down from a joint's parent through the joint.</summary>
            private float Branch(int joint) => _length[joint] + _reach[joint];

            public HumanoidMap Run(out string failure)
            {
                failure = null;
                if (!(_longest > 0f) || !float.IsFinite(_longest)) return Fail("its joints do not move apart: the bones have no length", out failure);
                float longBranch = LongBranchShare * _longest;

                var hubs = new List<int>();
                for (int j = 0; j < _n; j++)
                    if (LongBranches(j, longBranch).Count >= 3) hubs.Add(j);
                if (hubs.Count != 2)
                    return Fail($"{hubs.Count} joint(s) where three long branches meet, where a humanoid has two (the pelvis and the chest)", out failure);

                // The two side limbs of each hub: its long branches other than the one toward the other hub.
                var limbs = new Limb[2][];
                for (int h = 0; h < 2; h++)
                {
                    int hub = hubs[h], other = hubs[1 - h];
                    var sides = new List<int>();
                    foreach (int branch in LongBranches(hub, longBranch))
                        if (branch >= 0 && !_s.IsAncestorOrSelf(branch, other)) sides.Add(branch);
                    if (sides.Count < 2)
                        return Fail($"'{_s.GetName(hub)}' carries {sides.Count} long limb(s) besides the spine, where a pelvis or a chest carries two", out failure);
                    // The two longest (a long neck and head can pass for a branch too).
                    sides.Sort((a, b) => (_length[b] + _reach[b]).CompareTo(_length[a] + _reach[a]));
                    limbs[h] = new Limb[2];
                    for (int k = 0; k < 2; k++)
                    {
                        limbs[h][k] = ReadLimb(hub, sides[k], out string why);
                        if (limbs[h][k] == null) return Fail(why, out failure);
                    }
                }

                int[] heads = { HeadBranch(hubs[0], hubs[1], limbs[0]), HeadBranch(hubs[1], hubs[0], limbs[1]) };
                int chestIndex;
                if ((heads[0] >= 0) != (heads[1] >= 0)) chestIndex = heads[0] >= 0 ? 0 : 1;
                else chestIndex = UpperLength(limbs[0]) < UpperLength(limbs[1]) ? 0 : 1;
                int pelvis = hubs[1 - chestIndex], chest = hubs[chestIndex];
                Limb[] legs = limbs[1 - chestIndex], arms = limbs[chestIndex];
                int headBranch = heads[chestIndex];
                if (headBranch < 0) return Fail($"the chest ('{_s.GetName(chest)}') carries no head", out failure);

                if (!Similar(legs[0].UpperLength + legs[0].LowerLength, legs[1].UpperLength + legs[1].LowerLength))
                    return Fail("its two legs differ in length by more than a quarter", out failure);
                if (!Similar(arms[0].UpperLength + arms[0].LowerLength, arms[1].UpperLength + arms[1].LowerLength))
                    return Fail("its two arms differ in length by more than a quarter", out failure);

                int hips = CommonAncestor(pelvis, chest);
                if (hips < 0) return Fail("the pelvis and the chest are in separate hierarchies", out failure);

                // Each arm with the leg whose hip is nearer its shoulder, then left by the knees (or the toes).
                if (Distance(arms[0].Upper, legs[0].Upper) + Distance(arms[1].Upper, legs[1].Upper) >
                    Distance(arms[0].Upper, legs[1].Upper) + Distance(arms[1].Upper, legs[0].Upper))
                    (arms[0], arms[1]) = (arms[1], arms[0]);
                int leftFirst = FirstIsLeft(legs, hips, chest, Toe(legs[0]), Toe(legs[1]));
                if (leftFirst == 0)
                    return Fail("left cannot be told from right: no knee bends in the frames and the feet have no toes", out failure);
                if (leftFirst < 0)
                {
                    (legs[0], legs[1]) = (legs[1], legs[0]);
                    (arms[0], arms[1]) = (arms[1], arms[0]);
                }

                var bones = new List<KeyValuePair<HumanoidBone, string>>();
                void Add(HumanoidBone bone, int joint)
                {
                    if (joint >= 0) bones.Add(new KeyValuePair<HumanoidBone, string>(bone, _s.GetName(joint)));
                }
                Add(HumanoidBone.Hips, hips);
                ReadHead(chest, headBranch, out int neck, out int head);
                if (head < 0) return Fail($"the head branch from '{_s.GetName(chest)}' has no joint", out failure);
                List<int> spine = PathBetween(hips, neck >= 0 ? neck : head);
                if (spine.Count == 0) return Fail("no joint lies between the hips and the head", out failure);
                HumanoidBone[] spineBones = { HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.UpperChest };
                for (int k = 0; k < spine.Count && k < spineBones.Length; k++) Add(spineBones[k], spine[k]);
                Add(HumanoidBone.Neck, neck);
                Add(HumanoidBone.Head, head);
                for (int side = 0; side < 2; side++)
                {
                    BodySide body = side == 0 ? BodySide.Left : BodySide.Right;
                    Limb leg = legs[side], arm = arms[side];
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, body), leg.Upper);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, body), leg.Lower);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftFoot, body), leg.End);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftToes, body), leg.After);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftShoulder, body), arm.Before);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, body), arm.Upper);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, body), arm.Lower);
                    Add(HumanoidBones.OnSide(HumanoidBone.LeftHand, body), arm.End);
                }
                var map = new HumanoidMap(_s, bones);
                if (!map.IsComplete) return Fail("it lacks " + string.Join(", ", map.MissingRequired()), out failure);
                return map;
            }

            private static HumanoidMap Fail(string reason, out string failure)
            {
                failure = reason;
                return null;
            }

            private static bool Similar(float a, float b) => a > 0f && b > 0f && Math.Max(a, b) <= SidesRatio * Math.Min(a, b);

            private static float UpperLength(Limb[] limbs) => Math.Max(limbs[0].UpperLength, limbs[1].UpperLength);

            /// <summary>The long branches at <paramref name="joint"/>: its children so, and -1 for the way through its parent.</summary>
            private List<int> LongBranches(int joint, float longBranch)
            {
                var branches = new List<int>();
                foreach (int c in _children[joint])
                    if (_length[c] + _reach[c] >= longBranch) branches.Add(c);
                if (_s.GetParent(joint) >= 0 && _up[joint] >= longBranch) branches.Add(-1);
                return branches;
            }

            /// <summary>The distance between two joints: the median over the frames, so that a glitch in one frame does not move it.</summary>
            private float Distance(int a, int b)
            {
                for (int f = 0; f < _frames.Count; f++) _scratch[f] = Vector3.Distance(_frames[f][a], _frames[f][b]);
                Array.Sort(_scratch, 0, _frames.Count);
                int mid = _frames.Count / 2;
                return _frames.Count % 2 == 1 ? _scratch[mid] : 0.5f * (_scratch[mid - 1] + _scratch[mid]);
            }

            /// <summary>From <paramref name="first"/> on, the child with the longest reach at every joint, to a leaf.</summary>
            private List<int> Chain(int first)
            {
                var chain = new List<int> { first };
                for (int j = first; _children[j].Count > 0;)
                {
                    int next = _children[j][0];
                    foreach (int c in _children[j])
                        if (_length[c] + _reach[c] > _length[next] + _reach[next]) next = c;
                    chain.Add(next);
                    j = next;
                }
                return chain;
            }

            /// <summary>A limb from <paramref name="hub"/> through <paramref name="first"/>: its articulations and the pair of
            /// long segments; null, with the reason, without such a pair.</summary>
            private Limb ReadLimb(int hub, int first, out string failure)
            {
                failure = null;
                List<int> chain = Chain(first);
                var path = new List<int> { hub };
                path.AddRange(chain);
                // Articulations: the hub, every joint the limb bends at in some frame, and the chain's end. Of joints in one
                // place (a joint with a zero offset under it: a sword's grip, an inserted joint) the first is the joint;
                // whether it bends is read toward the first joint beyond them.
                var joints = new List<int> { hub };
                float straight = MathF.Cos(StraightDegrees * MathF.PI / 180f);
                int last = path[path.Count - 1];
                for (int k = 1; k < path.Count - 1; k++)
                {
                    int at = path[k], beyond = k + 1;
                    while (beyond < path.Count && Coincide(at, path[beyond])) beyond++;
                    if (beyond == path.Count) { last = at; break; }
                    if (Bends(joints[joints.Count - 1], at, path[beyond], straight)) joints.Add(at);
                    k = beyond - 1;
                }
                joints.Add(last);

                var segment = new float[joints.Count - 1];
                for (int k = 0; k < segment.Length; k++) segment[k] = Distance(joints[k], joints[k + 1]);
                int best = -1;
                float bestLength = 0f, before = 0f; // the longest segment before the pair
                for (int k = 1; k + 1 < segment.Length; k++)
                {
                    before = Math.Max(before, segment[k - 1]);
                    float a = segment[k], b = segment[k + 1];
                    if (!(a > 0f && b > 0f) || Math.Max(a, b) > LimbPairRatio * Math.Min(a, b)) continue;
                    // The upper and lower limb are the limb's longest segments up to its hand or foot: a foot and its toes
                    // after a leg that never bent (hip to ankle one segment) are not a thigh and a shin.
                    if (before > Math.Max(a, b)) continue;
                    if (a + b > bestLength) { bestLength = a + b; best = k; }
                }
                if (best < 0)
                {
                    failure = $"the limb from '{_s.GetName(first)}' has no two long segments of similar length (an upper and a lower limb, which bend at a joint in some frame)";
                    return null;
                }
                int end = joints[best + 2];
                if (!_s.IsEndSite(end) && _children[end].Count == 0)
                {
                    // Nothing beyond the hand or foot: a limb of clavicle, upper arm and forearm reads the same way as one of
                    // upper arm, forearm and hand.
                    failure = $"the limb from '{_s.GetName(first)}' ends at '{_s.GetName(end)}' with nothing beyond it (no End Site): its hand or foot cannot be told from the joint before";
                    return null;
                }
                int endAt = chain.IndexOf(end), afterAt = endAt + 1;
                while (afterAt < chain.Count && Coincide(end, chain[afterAt])) afterAt++;
                int next = afterAt < chain.Count && !_s.IsEndSite(chain[afterAt]) ? chain[afterAt] : -1;
                int upper = joints[best];
                return new Limb
                {
                    Before = chain[0] != upper && !Coincide(chain[0], upper) ? chain[0] : -1,
                    Upper = upper,
                    Lower = joints[best + 1],
                    End = end,
                    After = next,
                    UpperLength = segment[best],
                    LowerLength = segment[best + 1],
                };
            }

            /// <summary>Whether two joints sit in one place (within 0.01 % of the longest path, 0.2 mm; the median over the frames).</summary>
            private bool Coincide(int a, int b) => Distance(a, b) <= 1e-4f * _longest;

            /// <summary>Whether the limb bends at <paramref name="at"/> in some frame (or it sits on the joint before).</summary>
            private bool Bends(int before, int at, int after, float straight)
            {
                // On its neighbour: not a joint of its own.
                if (!(Distance(before, at) > 1e-4f * _longest) || !(Distance(at, after) > 1e-4f * _longest)) return false;
                // Bent in one frame in fifty and in two at least (one, when there is only one): a glitch in a single frame
                // does not make a twist joint a joint.
                int needed = _frames.Count < 2 ? 1 : Math.Max(2, _frames.Count / 50), bent = 0;
                foreach (Vector3[] frame in _frames)
                {
                    Vector3 a = frame[at] - frame[before], b = frame[after] - frame[at];
                    float la = a.Length(), lb = b.Length();
                    if (la > 0f && lb > 0f && Vector3.Dot(a, b) < straight * la * lb && ++bent >= needed) return true;
                }
                return false;
            }

            /// <summary>The chest's branch toward the head: its longest branch that is neither a limb nor toward the other
            /// hub, or -1 when there is none at least a head's height long.</summary>
            private int HeadBranch(int hub, int other, Limb[] limbs)
            {
                int best = -1;
                foreach (int c in _children[hub])
                {
                    if (_s.IsAncestorOrSelf(c, other) || _s.IsAncestorOrSelf(c, limbs[0].Upper) || _s.IsAncestorOrSelf(c, limbs[1].Upper)) continue;
                    if (_length[c] + _reach[c] < HeadHeightShare * _longest) continue;
                    if (best < 0 || _length[c] + _reach[c] > _length[best] + _reach[best]) best = c;
                }
                return best;
            }

            private void ReadHead(int chest, int first, out int neck, out int head)
            {
                // Up the branch while it goes on upward through a single joint: the head is where it splits (eyes, jaw, the
                // head's top, a ponytail) or turns away (hair hanging from a head with no other child), not the longest
                // path's end, which a ponytail would be.
                var chain = new List<int> { first };
                float onward = MathF.Cos(HeadTurnDegrees * MathF.PI / 180f);
                for (int from = chest, at = first; ;)
                {
                    int only = -1, count = 0;
                    foreach (int c in _children[at])
                        if (!_s.IsEndSite(c) || _length[c] > 0.005f * _longest) { only = c; count++; }
                    if (count != 1 || !GoesOn(from, at, only, onward)) break;
                    chain.Add(only);
                    from = at;
                    at = only;
                }
                int last = chain.Count - 1;
                while (last >= 0 && _s.IsEndSite(chain[last])) last--;
                // A joint that only marks where the head ends (Mixamo's HeadTop_End, its End Site on it) is not the head.
                if (last > 0 && IsEndMarker(chain[last])) last--;
                head = last >= 0 ? chain[last] : -1;
                neck = head >= 0 && chain[0] != head ? chain[0] : -1;
            }

            /// <summary>Whether the bone from <paramref name="at"/> to <paramref name="next"/> goes on within the angle whose
            /// cosine is <paramref name="onward"/> of the bone into <paramref name="at"/>, on average over the frames.</summary>
            private bool GoesOn(int from, int at, int next, float onward)
            {
                double sum = 0;
                foreach (Vector3[] frame in _frames)
                {
                    Vector3 a = frame[at] - frame[from], b = frame[next] - frame[at];
                    float la = a.Length(), lb = b.Length();
                    sum += la > 0f && lb > 0f ? Vector3.Dot(a, b) / (la * lb) : 1.0; // a bone of no length turns nothing
                }
                return sum / _frames.Count >= onward;
            }

            /// <summary>A joint with children, all of them End Sites within a centimetre: a marker of where a chain ends.</summary>
            private bool IsEndMarker(int joint)
            {
                if (_children[joint].Count == 0) return false;
                foreach (int c in _children[joint])
                    if (!_s.IsEndSite(c) || _length[c] > 0.005f * _longest) return false;
                return true;
            }

            /// <summary>The joints after <paramref name="from"/> up to and without <paramref name="to"/>, its descendant.</summary>
            private List<int> PathBetween(int from, int to)
            {
                var path = new List<int>();
                for (int j = _s.GetParent(to); j >= 0 && j != from; j = _s.GetParent(j)) path.Add(j);
                path.Reverse();
                return path;
            }

            private int CommonAncestor(int a, int b)
            {
                for (int j = a; j >= 0; j = _s.GetParent(j))
                    if (_s.IsAncestorOrSelf(j, b)) return j;
                return -1;
            }

            /// <summary>+1 when legs[0] is the left leg, -1 when it is the right, 0 when the frames cannot tell.</summary>
            /// <summary>The joint the foot points toward: its toes, else its longest child (an End Site), else -1.</summary>
            private int Toe(Limb leg) => leg.After >= 0 ? leg.After : _children[leg.End].Count > 0 ? Chain(leg.End)[1] : -1;

            private int FirstIsLeft(Limb[] legs, int hips, int chest, int toe0, int toe1)
            {
                int forward = 0, backward = 0;
                float toes = 0f;
                foreach (Vector3[] frame in _frames)
                {
                    Vector3 hipLine = frame[legs[1].Upper] - frame[legs[0].Upper]; // first to second: right if the first is left
                    if (!(hipLine.LengthSquared() > 0f)) continue;
                    hipLine = Vector3.Normalize(hipLine);
                    Vector3 up = frame[chest] - frame[hips];
                    for (int k = 0; k < 2; k++)
                    {
                        Limb leg = legs[k];
                        int bend = KneeBend.Direction(frame[leg.Upper], frame[leg.Lower], frame[leg.End], hipLine);
                        if (bend > 0) forward++;
                        else if (bend < 0) backward++;
                        int toe = k == 0 ? toe0 : toe1;
                        if (toe < 0) continue;
                        Vector3 forwardOfBody = frame[toe] - frame[leg.End];
                        // In Unity's left-handed frame (as BvhClip gives the joints), up × forward points to the body's right.
                        Vector3 right = Vector3.Cross(up, forwardOfBody);
                        if (right.LengthSquared() > 0f) toes += Vector3.Dot(Vector3.Normalize(right), hipLine);
                    }
                }
                if (forward != backward) return forward > backward ? 1 : -1;
                if (toes != 0f && float.IsFinite(toes)) return toes > 0f ? 1 : -1;
                return 0;
            }
        }

        private sealed class Limb
        {
            public int Before = -1, Upper = -1, Lower = -1, End = -1, After = -1;
            public float UpperLength, LowerLength;
        }
    }
}
