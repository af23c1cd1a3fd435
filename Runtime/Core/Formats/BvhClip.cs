using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A BVH motion: the joint hierarchy with its channels and the raw channel values of every frame, as read
    /// from a file (right-handed, file units) or created from poses. Poses come out in Unity's frame:
    /// positions (x, y, z) → (-x, y, z) times <see cref="Scale"/>, rotations (x, y, z, w) → (x, -y, -z, w).
    /// </summary>
    /// <remarks>
    /// Channel semantics: rotation channels compose in the order listed, <c>R = R(c1) R(c2) R(c3)</c>
    /// (intrinsic), about BVH's right-handed axes, in degrees. A joint with position channels takes those
    /// values as its translation from the parent, component by component, in place of its OFFSET (the usual
    /// reading, and the one Blender's exporter relies on); a joint without them is translated by its OFFSET.
    /// End Sites are joints with no channels, named <c>&lt;parent&gt;_End</c> (made unique if needed).
    /// </remarks>
    public sealed class BvhClip
    {
        private readonly Vector3[] _fileOffsets;
        private readonly BvhChannel[][] _channels;
        private readonly int[] _channelStart;
        private readonly float[] _values;

        /// <summary>Creates a clip from its parts (used by <see cref="BvhReader"/> and <c>FromPoses</c>).</summary>
        /// <param name="names">Joint names in file order (End Sites included).</param>
        /// <param name="parents">Parent index of each joint (-1 for the root), parents first.</param>
        /// <param name="isEndSite">True for End Site joints.</param>
        /// <param name="fileOffsets">OFFSET of each joint, in the file's frame and units.</param>
        /// <param name="channels">Channels of each joint (empty for End Sites).</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="frameTime">Seconds per frame, positive.</param>
        /// <param name="values">frameCount × total channels values, frame-major.</param>
        /// <param name="scale">Length factor applied when poses are produced.</param>
        public BvhClip(IReadOnlyList<string> names, IReadOnlyList<int> parents, IReadOnlyList<bool> isEndSite,
            IReadOnlyList<Vector3> fileOffsets, IReadOnlyList<BvhChannel[]> channels, int frameCount, float frameTime,
            float[] values, float scale)
        {
            if (names == null) throw new ArgumentNullException(nameof(names));
            int n = names.Count;
            if (fileOffsets == null || fileOffsets.Count != n || channels == null || channels.Count != n)
                throw new ArgumentException("Offsets and channels must be given for every joint.");
            if (!(frameTime > 0f) || float.IsInfinity(frameTime)) throw new ArgumentOutOfRangeException(nameof(frameTime), frameTime, "Frame time must be positive.");
            if (!(scale > 0f) || float.IsInfinity(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "Scale must be positive.");
            if (frameCount < 0) throw new ArgumentOutOfRangeException(nameof(frameCount));

            _fileOffsets = new Vector3[n];
            _channels = new BvhChannel[n][];
            _channelStart = new int[n];
            int total = 0;
            for (int i = 0; i < n; i++)
            {
                _fileOffsets[i] = fileOffsets[i];
                _channels[i] = channels[i] ?? Array.Empty<BvhChannel>();
                _channelStart[i] = total;
                total += _channels[i].Length;
            }
            ChannelCount = total;
            if (values == null || values.Length != (long)frameCount * total)
                throw new ArgumentException($"Expected {(long)frameCount * total} channel values, got {values?.Length ?? 0}.", nameof(values));
            _values = values;
            FrameCount = frameCount;
            FrameTime = frameTime;
            Scale = scale;

            var rest = new RigidPose[n];
            for (int i = 0; i < n; i++) rest[i] = new RigidPose(ToUnity(_fileOffsets[i]) * scale, Quaternion.Identity);
            Skeleton = new Skeleton(names, parents, rest, isEndSite);
        }

        /// <summary>The joint hierarchy in Unity's frame, scaled; rest pose = the OFFSETs with no rotation.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>The number of frames.</summary>
        public int FrameCount { get; }

        /// <summary>Seconds per frame.</summary>
        public float FrameTime { get; }

        /// <summary>Frames per second (1 / <see cref="FrameTime"/>).</summary>
        public float FrameRate => 1f / FrameTime;

        /// <summary>The length factor applied to the file's lengths when poses are produced.</summary>
        public float Scale { get; }

        /// <summary>The number of channels per frame.</summary>
        public int ChannelCount { get; }

        /// <summary>The channels of a joint, in file order (empty for End Sites).</summary>
        public IReadOnlyList<BvhChannel> GetChannels(int joint) => _channels[joint];

        /// <summary>The joint's OFFSET as written in the file (BVH frame, file units).</summary>
        public Vector3 GetFileOffset(int joint) => _fileOffsets[joint];

        /// <summary>The raw value of channel <paramref name="channel"/> (0 … <see cref="ChannelCount"/>-1) in a frame.</summary>
        public float GetValue(int frame, int channel) => _values[(long)frame * ChannelCount + channel];

        /// <summary>The same clip with another length factor (values are shared, not copied).</summary>
        public BvhClip WithScale(float scale)
        {
            var channels = new BvhChannel[_channels.Length][];
            Array.Copy(_channels, channels, channels.Length);
            Hierarchy(out int[] parents, out bool[] endSites);
            return new BvhClip(Skeleton.Names, parents, endSites, _fileOffsets, channels, FrameCount, FrameTime, _values, scale);
        }

        // The skeleton's parents and End Site flags, as the constructor takes them.
        private void Hierarchy(out int[] parents, out bool[] endSites)
        {
            parents = new int[Skeleton.JointCount];
            endSites = new bool[Skeleton.JointCount];
            for (int i = 0; i < parents.Length; i++)
            {
                parents[i] = Skeleton.GetParent(i);
                endSites[i] = Skeleton.IsEndSite(i);
            }
        }

        /// <summary>
        /// The clip reflected left to right (through the file's YZ plane): every X offset and X translation negated, every Y
        /// and Z rotation angle negated (a reflection turns a rotation about X the same way and one about Y or Z the other
        /// way, whatever the order the channels compose in). Each joint's world position in every frame is the original's
        /// with X negated, to float precision; names are kept, so a joint named Left ends on the other side. For a clip
        /// written in a left-handed frame, or one whose sides are named the wrong way round, this is the clip as it was meant.
        /// </summary>
        public BvhClip Mirrored()
        {
            int n = Skeleton.JointCount;
            var offsets = new Vector3[n];
            var negate = new bool[ChannelCount];
            Hierarchy(out int[] parents, out bool[] endSites);
            for (int j = 0; j < n; j++)
            {
                offsets[j] = new Vector3(-_fileOffsets[j].X, _fileOffsets[j].Y, _fileOffsets[j].Z);
                for (int c = 0; c < _channels[j].Length; c++)
                {
                    BvhChannel channel = _channels[j][c];
                    negate[_channelStart[j] + c] = channel == BvhChannel.Xposition || channel == BvhChannel.Yrotation || channel == BvhChannel.Zrotation;
                }
            }
            var values = new float[_values.Length];
            for (long i = 0; i < values.LongLength; i++)
                values[i] = negate[i % ChannelCount] ? -_values[i] : _values[i];
            return new BvhClip(Skeleton.Names, parents, endSites, offsets, _channels, FrameCount, FrameTime, values, Scale);
        }

        /// <summary>
        /// The local pose of every joint in a frame, in Unity's frame and scaled. Allocation-free.
        /// </summary>
        public void GetLocalPoses(int frame, Span<RigidPose> local)
        {
            if ((uint)frame >= (uint)FrameCount) throw new ArgumentOutOfRangeException(nameof(frame), frame, $"The clip has {FrameCount} frames.");
            if (local.Length != _channels.Length) throw new ArgumentException($"Expected {_channels.Length} poses, got {local.Length}.", nameof(local));
            int row = frame * ChannelCount;
            for (int j = 0; j < _channels.Length; j++)
            {
                Vector3 t = _fileOffsets[j];
                Quaternion q = Quaternion.Identity;
                BvhChannel[] channels = _channels[j];
                int start = row + _channelStart[j];
                for (int c = 0; c < channels.Length; c++)
                {
                    float v = _values[start + c];
                    switch (channels[c])
                    {
                        case BvhChannel.Xposition: t.X = v; break;
                        case BvhChannel.Yposition: t.Y = v; break;
                        case BvhChannel.Zposition: t.Z = v; break;
                        case BvhChannel.Xrotation: q *= AxisRotation(0, v); break;
                        case BvhChannel.Yrotation: q *= AxisRotation(1, v); break;
                        default: q *= AxisRotation(2, v); break;
                    }
                }
                local[j] = new RigidPose(ToUnity(t) * Scale, ToUnity(Quaternion.Normalize(q)));
            }
        }

        /// <summary>The world pose of every joint in a frame (Unity's frame, scaled). Allocation-free.</summary>
        public void GetWorldPoses(int frame, Span<RigidPose> local, Span<RigidPose> world)
        {
            GetLocalPoses(frame, local);
            Skeleton.ComputeWorld(local, world);
        }

        /// <summary>
        /// The length of the skeleton's longest chain of bones from a root (the sum of the OFFSET lengths along it, End
        /// Sites included), in file units, and from it the guessed metres per file unit: under 3 units → metres (1), under
        /// 300 → centimetres (0.01), otherwise millimetres (0.001). For a human that chain (hips to a fingertip or the head)
        /// is 0.7–1.6 m whatever the rest pose: it depends on the bones' lengths only, not on how the rest bends them (a rest
        /// with every bone along one axis, or crumpled, guesses the same unit as a T-pose). When that unit makes the chain
        /// implausible for a person (outside <see cref="PlausibleChainMinMetres"/>…<see cref="PlausibleChainMaxMetres"/>), the unit among metres, centimetres,
        /// millimetres, inches (0.0254) and the CMU database's BVH unit (0.0254 / 0.45 m: the CMU clips converted to BVH are
        /// in it, a 24-unit chain) that makes it plausible and brings it nearest 1.2 m is taken instead (those clips read as
        /// 20 cm people before); when none does, the first guess stays. A chain near the lower limit can change unit across
        /// it (a 0.59 m chain in centimetres reads as inches): the limit is where a person's chain ends (a small child's).
        /// </summary>
        public float GuessMetresPerUnit()
        {
            var chain = new float[Skeleton.JointCount];
            float longest = 0f;
            for (int j = 0; j < chain.Length; j++)
            {
                int parent = Skeleton.GetParent(j);
                chain[j] = (parent < 0 ? 0f : chain[parent]) + (parent < 0 ? 0f : _fileOffsets[j].Length());
                longest = Math.Max(longest, chain[j]);
            }
            float unit = longest < 3f ? 1f : longest < 300f ? 0.01f : 0.001f;
            float metres = longest * unit;
            if (!(longest > 0f) || (metres >= PlausibleChainMinMetres && metres <= PlausibleChainMaxMetres)) return unit;
            float best = unit, bestDistance = float.MaxValue;
            foreach (float candidate in CandidateUnits)
            {
                float candidateMetres = longest * candidate;
                if (!(candidateMetres >= PlausibleChainMinMetres && candidateMetres <= PlausibleChainMaxMetres)) continue;
                float distance = Math.Abs((float)Math.Log(candidateMetres / 1.2f));
                if (distance < bestDistance) { best = candidate; bestDistance = distance; }
            }
            return best; // the first guess when no unit makes a plausible person either
        }

        /// <summary>
        /// The shortest longest-chain (metres) <see cref="GuessMetresPerUnit"/> accepts for the unit it guesses first: 0.6 m,
        /// a small child's (the shared clips' are 1.10–1.38 m).
        /// </summary>
        public const float PlausibleChainMinMetres = 0.6f;

        /// <summary>The longest longest-chain (metres) <see cref="GuessMetresPerUnit"/> accepts for the unit it guesses first: 2.4 m, twice an adult's.</summary>
        public const float PlausibleChainMaxMetres = 2.4f;

        private static readonly float[] CandidateUnits = { 1f, 0.01f, 0.001f, 0.0254f, 0.0254f / 0.45f };

        /// <summary>
        /// Creates a clip from local poses of <paramref name="skeleton"/> (Unity's frame, metres), for writing:
        /// roots, and joints whose translation leaves their rest offset in some frame (hips placed under a floor-level root),
        /// get 6 channels (Xposition Yposition Zposition Zrotation Xrotation Yrotation), other joints 3 rotation channels,
        /// End Sites none. Lengths are divided by <paramref name="metresPerUnit"/>.
        /// </summary>
        public static BvhClip FromPoses(Skeleton skeleton, IReadOnlyList<RigidPose[]> localFrames, float frameTime, float metresPerUnit = 1f)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (localFrames == null) throw new ArgumentNullException(nameof(localFrames));
            var channels = new BvhChannel[skeleton.JointCount][];
            for (int j = 0; j < channels.Length; j++)
                channels[j] = skeleton.IsEndSite(j) ? Array.Empty<BvhChannel>()
                    : skeleton.GetParent(j) < 0 || Translates(skeleton, localFrames, j, metresPerUnit) ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation }
                    : new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            return FromPoses(skeleton, localFrames, frameTime, metresPerUnit, channels);
        }

        // Whether a joint's local translation leaves its rest offset in some frame: the solved avatar's hips under a
        // floor-level root are placed in the world, so their translation moves (with only rotation channels, writing such
        // a solve threw).
        // (In file units, with half the tolerance the writer allows a joint without position channels.)
        private static bool Translates(Skeleton skeleton, IReadOnlyList<RigidPose[]> localFrames, int joint, float metresPerUnit)
        {
            if (!(metresPerUnit > 0f)) return false; // refused by the writer
            Vector3 rest = skeleton.GetRestLocal(joint).Position;
            float tolerance = 0.5e-5f * Math.Max(1f, rest.Length() / metresPerUnit);
            for (int f = 0; f < localFrames.Count; f++)
            {
                RigidPose[] frame = localFrames[f];
                if (frame != null && joint < frame.Length && Vector3.Distance(frame[joint].Position, rest) / metresPerUnit > tolerance) return true;
            }
            return false;
        }

        /// <summary>
        /// Creates a clip from local poses of <paramref name="skeleton"/> (Unity's frame, metres) with the channels
        /// given for each joint: End Sites none; every other joint its three rotation channels (one per axis, in the
        /// order they compose) and, when its translation moves, the three position channels. The OFFSETs are the
        /// skeleton's rest translations. Lengths are divided by <paramref name="metresPerUnit"/>.
        /// </summary>
        /// <exception cref="ArgumentException">A joint's channels are not as described, a frame has the wrong number of
        /// poses, or a joint without position channels is translated away from its rest offset in some frame.</exception>
        public static BvhClip FromPoses(Skeleton skeleton, IReadOnlyList<RigidPose[]> localFrames, float frameTime, float metresPerUnit,
            IReadOnlyList<BvhChannel[]> channels)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (localFrames == null) throw new ArgumentNullException(nameof(localFrames));
            if (channels == null) throw new ArgumentNullException(nameof(channels));
            if (!(metresPerUnit > 0f) || float.IsInfinity(metresPerUnit)) throw new ArgumentOutOfRangeException(nameof(metresPerUnit), metresPerUnit, "Must be positive.");
            int n = skeleton.JointCount;
            if (channels.Count != n) throw new ArgumentException($"Expected channels for {n} joints, got {channels.Count}.", nameof(channels));
            var parents = new int[n];
            var endSites = new bool[n];
            var offsets = new Vector3[n];
            var copied = new BvhChannel[n][];
            var positionAt = new int[n];   // index of Xposition among the joint's channels, or -1
            var rotationAxes = new int[n][];
            int total = 0;
            for (int j = 0; j < n; j++)
            {
                parents[j] = skeleton.GetParent(j);
                endSites[j] = skeleton.IsEndSite(j);
                offsets[j] = ToUnity(skeleton.GetRestLocal(j).Position) / metresPerUnit;
                copied[j] = (BvhChannel[])(channels[j] ?? Array.Empty<BvhChannel>()).Clone();
                positionAt[j] = -1;
                CheckChannels(skeleton, j, copied[j], out positionAt[j], out rotationAxes[j]);
                total += copied[j].Length;
            }
            var values = new float[localFrames.Count * total];
            int k = 0;
            for (int f = 0; f < localFrames.Count; f++)
            {
                RigidPose[] frame = localFrames[f];
                if (frame == null || frame.Length != n) throw new ArgumentException($"Frame {f} does not have {n} poses.", nameof(localFrames));
                for (int j = 0; j < n; j++)
                {
                    if (endSites[j]) continue;
                    Vector3 p = ToUnity(frame[j].Position) / metresPerUnit; // the mirror is its own inverse
                    if (positionAt[j] < 0 && Vector3.Distance(p, offsets[j]) > 1e-5f * Math.Max(1f, offsets[j].Length()))
                        throw new ArgumentException($"Joint '{skeleton.GetName(j)}' moves away from its OFFSET in frame {f} but has no position channels.", nameof(channels));
                    int[] axes = rotationAxes[j];
                    Vector3 euler = EulerDegrees(ToUnity(frame[j].Rotation), axes[0], axes[1], axes[2]);
                    BvhChannel[] list = copied[j];
                    int rotation = 0; // rotation channels take the angles in the order they compose
                    for (int c = 0; c < list.Length; c++)
                    {
                        switch (list[c])
                        {
                            case BvhChannel.Xposition: values[k++] = p.X; break;
                            case BvhChannel.Yposition: values[k++] = p.Y; break;
                            case BvhChannel.Zposition: values[k++] = p.Z; break;
                            default:
                                values[k++] = rotation == 0 ? euler.X : rotation == 1 ? euler.Y : euler.Z;
                                rotation++;
                                break;
                        }
                    }
                }
            }
            return new BvhClip(skeleton.Names, parents, endSites, offsets, copied, localFrames.Count, frameTime, values, metresPerUnit);
        }

        // End Sites have no channels; other joints exactly one rotation channel per axis and no or all three position channels.
        private static void CheckChannels(Skeleton skeleton, int joint, BvhChannel[] list, out int positionAt, out int[] rotationAxes)
        {
            positionAt = -1;
            rotationAxes = null;
            string name = skeleton.GetName(joint);
            if (skeleton.IsEndSite(joint))
            {
                if (list.Length != 0) throw new ArgumentException($"End Site '{name}' cannot have channels.", "channels");
                return;
            }
            var axes = new List<int>(3);
            int positions = 0, seen = 0;
            for (int c = 0; c < list.Length; c++)
            {
                int bit = 1 << (int)list[c];
                if ((seen & bit) != 0) throw new ArgumentException($"Joint '{name}' lists {list[c]} twice.", "channels");
                seen |= bit;
                if (list[c] <= BvhChannel.Zposition)
                {
                    if (positions == 0) positionAt = c;
                    positions++;
                }
                else axes.Add(list[c] - BvhChannel.Xrotation);
            }
            if (axes.Count != 3 || (positions != 0 && positions != 3))
                throw new ArgumentException($"Joint '{name}' needs three rotation channels and none or three position channels.", "channels");
            rotationAxes = axes.ToArray();
        }

        /// <summary>
        /// Decomposes a right-handed rotation into Euler angles (degrees) for axes i, j, k (0 = X, 1 = Y, 2 = Z,
        /// all different) such that <c>q = R_i(a) R_j(b) R_k(c)</c>; returns (a, b, c).
        /// </summary>
        internal static Vector3 EulerDegrees(Quaternion q, int i, int j, int k)
        {
            double[,] m = Matrix(q);
            // +1 when (i, j, k) is an even permutation of (X, Y, Z).
            double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
            double sb = Math.Max(-1.0, Math.Min(1.0, s * m[i, k]));
            // atan2 rather than asin: asin loses half the digits near ±90°.
            double cb = Math.Sqrt(m[i, i] * m[i, i] + m[i, j] * m[i, j]);
            double a, b = Math.Atan2(sb, cb), c;
            if (cb > 1e-6)
            {
                a = Math.Atan2(-s * m[j, k], m[k, k]);
                c = Math.Atan2(-s * m[i, j], m[i, i]);
            }
            else
            {
                // Gimbal lock: only a + c (or a - c) is defined; put it all in a.
                c = 0.0;
                a = Math.Atan2(s * m[k, j], m[j, j]);
            }
            const double toDeg = 180.0 / Math.PI;
            return new Vector3((float)(a * toDeg), (float)(b * toDeg), (float)(c * toDeg));
        }

        // The rotation matrix of q, normalised in double (s = 2 / |q|²): a float quaternion's norm is off by up to ~1e-7, which
        // the 1 - 2(y² + z²) form adds to the diagonal, and near gimbal lock the Euler angles read from entries of size
        // cos(b) would magnify it (found in review; a rebased joint could then move by more than 0.01 mm on a metre).
        private static double[,] Matrix(Quaternion q)
        {
            double x = q.X, y = q.Y, z = q.Z, w = q.W;
            double n = x * x + y * y + z * z + w * w;
            double s = n > 0 ? 2.0 / n : 0.0;
            return new double[,]
            {
                { 1 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w) },
                { s * (x * y + z * w), 1 - s * (x * x + z * z), s * (y * z - x * w) },
                { s * (x * z - y * w), s * (y * z + x * w), 1 - s * (x * x + y * y) },
            };
        }

        private static Quaternion AxisRotation(int axis, float degrees)
        {
            double half = degrees * (Math.PI / 360.0);
            float s = (float)Math.Sin(half), c = (float)Math.Cos(half);
            return axis == 0 ? new Quaternion(s, 0, 0, c) : axis == 1 ? new Quaternion(0, s, 0, c) : new Quaternion(0, 0, s, c);
        }

        /// <summary>BVH (right-handed) ↔ Unity (left-handed): mirror X. Its own inverse.</summary>
        internal static Vector3 ToUnity(Vector3 v) => new Vector3(-v.X, v.Y, v.Z);

        /// <summary>BVH (right-handed) ↔ Unity (left-handed) rotation under the X mirror. Its own inverse.</summary>
        internal static Quaternion ToUnity(Quaternion q) => new Quaternion(q.X, -q.Y, -q.Z, q.W);
    }
}
