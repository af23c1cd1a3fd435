using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// An immutable joint hierarchy: names, parents and rest (bind) local transforms, in Unity's frame.
    /// Joints are ordered so that every parent comes before its children, which lets forward kinematics
    /// run as one pass. End points (a BVH <c>End Site</c>, a finger tip) are joints flagged as end sites.
    /// </summary>
    public sealed class Skeleton
    {
        private readonly string[] _names;
        private readonly int[] _parents;
        private readonly RigidPose[] _restLocal;
        private readonly bool[] _isEndSite;
        private readonly Dictionary<string, int> _indexByName;
        // Each joint's place in a depth-first order and the size of its subtree: joint j lies under a when
        // _order[a] <= _order[j] < _order[a] + _subtree[a], an O(1) test however deep the hierarchy.
        private readonly int[] _order;
        private readonly int[] _subtree;

        /// <summary>
        /// Creates a skeleton. <paramref name="parents"/>[i] is the index of joint i's parent, or -1 for a root,
        /// and must be smaller than i.
        /// </summary>
        /// <exception cref="ArgumentException">The arrays differ in length, a parent does not precede its child,
        /// a name is empty or used twice, or a rest pose is not finite.</exception>
        public Skeleton(IReadOnlyList<string> names, IReadOnlyList<int> parents, IReadOnlyList<RigidPose> restLocal,
            IReadOnlyList<bool> isEndSite = null)
        {
            if (names == null) throw new ArgumentNullException(nameof(names));
            if (parents == null) throw new ArgumentNullException(nameof(parents));
            if (restLocal == null) throw new ArgumentNullException(nameof(restLocal));
            int n = names.Count;
            if (n == 0) throw new ArgumentException("A skeleton needs at least one joint.", nameof(names));
            if (parents.Count != n || restLocal.Count != n || (isEndSite != null && isEndSite.Count != n))
                throw new ArgumentException("names, parents, rest poses and end-site flags must have the same length.");

            _names = new string[n];
            _parents = new int[n];
            _restLocal = new RigidPose[n];
            _isEndSite = new bool[n];
            _indexByName = new Dictionary<string, int>(n, StringComparer.Ordinal);
            for (int i = 0; i < n; i++)
            {
                string name = names[i];
                if (string.IsNullOrEmpty(name)) throw new ArgumentException($"Joint {i} has no name.", nameof(names));
                if (_indexByName.ContainsKey(name)) throw new ArgumentException($"Joint name '{name}' is used twice.", nameof(names));
                int parent = parents[i];
                if (parent < -1 || parent >= i)
                    throw new ArgumentException($"Joint '{name}' (index {i}) has parent {parent}; a parent must come before its child.", nameof(parents));
                if (!Vectors.IsFinite(restLocal[i].Position) || !Rotations.IsFinite(restLocal[i].Rotation))
                    throw new ArgumentException($"Joint '{name}' has a non-finite rest pose.", nameof(restLocal));
                _names[i] = name;
                _parents[i] = parent;
                _restLocal[i] = new RigidPose(restLocal[i].Position, Rotations.NormalizeOr(restLocal[i].Rotation, Quaternion.Identity));
                _isEndSite[i] = isEndSite != null && isEndSite[i];
                _indexByName.Add(name, i);
            }

            // Subtree sizes from the leaves up, then depth-first places from the roots down (children after their
            // parent, in index order); both are single passes since every parent comes before its children.
            _subtree = new int[n];
            _order = new int[n];
            for (int i = n - 1; i >= 0; i--)
            {
                _subtree[i]++;
                if (_parents[i] >= 0) _subtree[_parents[i]] += _subtree[i];
            }
            var next = new int[n];
            int nextRoot = 0;
            for (int i = 0; i < n; i++)
            {
                int parent = _parents[i];
                if (parent < 0) { _order[i] = nextRoot; nextRoot += _subtree[i]; }
                else { _order[i] = next[parent]; next[parent] += _subtree[i]; }
                next[i] = _order[i] + 1;
            }
        }

        /// <summary>The number of joints, end sites included.</summary>
        public int JointCount => _names.Length;

        /// <summary>The joint names, in hierarchy order.</summary>
        public IReadOnlyList<string> Names => _names;

        /// <summary>The name of joint <paramref name="joint"/>.</summary>
        public string GetName(int joint) => _names[joint];

        /// <summary>The parent index of joint <paramref name="joint"/>, or -1 for a root.</summary>
        public int GetParent(int joint) => _parents[joint];

        /// <summary>The rest (bind) transform of joint <paramref name="joint"/> relative to its parent.</summary>
        public RigidPose GetRestLocal(int joint) => _restLocal[joint];

        /// <summary>True when the joint is an end point with no rotation of its own (a BVH End Site).</summary>
        public bool IsEndSite(int joint) => _isEndSite[joint];

        /// <summary>The index of the joint with this exact name, or -1.</summary>
        public int IndexOf(string name) => name != null && _indexByName.TryGetValue(name, out int i) ? i : -1;

        /// <summary>True when <paramref name="ancestor"/> is <paramref name="joint"/> or one of its ancestors.</summary>
        public bool IsAncestorOrSelf(int ancestor, int joint)
        {
            if ((uint)ancestor >= (uint)_order.Length || joint < 0) return false;
            int place = _order[joint];
            return place >= _order[ancestor] && place < _order[ancestor] + _subtree[ancestor];
        }

        /// <summary>Copies the rest local transforms into <paramref name="local"/>.</summary>
        public void GetRestLocal(Span<RigidPose> local)
        {
            CheckLength(local.Length);
            _restLocal.AsSpan().CopyTo(local);
        }

        /// <summary>
        /// Forward kinematics: world transforms from local ones, the roots placed under <paramref name="origin"/>.
        /// Allocation-free.
        /// </summary>
        public void ComputeWorld(ReadOnlySpan<RigidPose> local, Span<RigidPose> world, RigidPose origin)
        {
            CheckLength(local.Length);
            CheckLength(world.Length);
            for (int i = 0; i < _parents.Length; i++)
            {
                int parent = _parents[i];
                world[i] = (parent < 0 ? origin : world[parent]) * local[i];
            }
        }

        /// <summary>Forward kinematics with the roots at the world origin.</summary>
        public void ComputeWorld(ReadOnlySpan<RigidPose> local, Span<RigidPose> world) => ComputeWorld(local, world, RigidPose.Identity);

        /// <summary>
        /// Inverse of <see cref="ComputeWorld(ReadOnlySpan{RigidPose}, Span{RigidPose}, RigidPose)"/>: local transforms from world ones.
        /// </summary>
        public void ComputeLocal(ReadOnlySpan<RigidPose> world, Span<RigidPose> local, RigidPose origin)
        {
            CheckLength(local.Length);
            CheckLength(world.Length);
            for (int i = 0; i < _parents.Length; i++)
            {
                int parent = _parents[i];
                local[i] = world[i].RelativeTo(parent < 0 ? origin : world[parent]);
            }
        }

        /// <summary>A copy of this skeleton with every rest translation multiplied by <paramref name="scale"/>.</summary>
        public Skeleton Scaled(float scale)
        {
            if (!(scale > 0f) || !Vectors.IsFinite(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "Scale must be positive and finite.");
            var rest = new RigidPose[_restLocal.Length];
            for (int i = 0; i < rest.Length; i++) rest[i] = _restLocal[i].Scaled(scale);
            return new Skeleton(_names, _parents, rest, _isEndSite);
        }

        /// <summary>A copy of this skeleton with other rest local transforms (same names and hierarchy).</summary>
        public Skeleton WithRestLocal(IReadOnlyList<RigidPose> restLocal) => new Skeleton(_names, _parents, restLocal, _isEndSite);

        private void CheckLength(int length)
        {
            if (length != _names.Length)
                throw new ArgumentException($"Expected a buffer of {_names.Length} joints, got {length}.");
        }
    }
}
