using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// A two-bone limb of a skeleton: root (hip, shoulder), middle (knee, elbow) and end (ankle, wrist) joints,
    /// with every joint on the path between them (twist bones, if a rig has any), precomputed once.
    /// </summary>
    public sealed class LimbChain
    {
        /// <summary>The root joint index (upper leg or upper arm).</summary>
        public int Root { get; }

        /// <summary>The middle joint index (lower leg or lower arm).</summary>
        public int Middle { get; }

        /// <summary>The end joint index (foot or hand).</summary>
        public int End { get; }

        /// <summary>The joints from <see cref="Root"/> to <see cref="End"/> inclusive, parents first.</summary>
        public int[] Path { get; }

        /// <summary>Creates the chain; <paramref name="end"/> must descend from <paramref name="middle"/>, which must descend from <paramref name="root"/>.</summary>
        public LimbChain(Skeleton skeleton, int root, int middle, int end)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (root < 0 || middle < 0 || end < 0 || !skeleton.IsAncestorOrSelf(root, middle) || !skeleton.IsAncestorOrSelf(middle, end) || root == middle || middle == end)
                throw new ArgumentException("The limb's joints must form a chain root → middle → end.");
            Root = root;
            Middle = middle;
            End = end;
            var path = new List<int>();
            for (int j = end; j != root; j = skeleton.GetParent(j)) path.Insert(0, j);
            path.Insert(0, root);
            Path = path.ToArray();
        }
    }
}
