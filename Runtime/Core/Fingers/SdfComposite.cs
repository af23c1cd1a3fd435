using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>The union of <see cref="SdfShape"/>s: the distance is the smallest of theirs, the gradient that shape's.</summary>
    public sealed class SdfComposite
    {
        private readonly SdfShape[] _shapes;

        /// <summary>Creates the union of at least one shape.</summary>
        public SdfComposite(IReadOnlyList<SdfShape> shapes)
        {
            if (shapes == null || shapes.Count == 0) throw new ArgumentException("A composite needs at least one shape.", nameof(shapes));
            _shapes = new SdfShape[shapes.Count];
            for (int i = 0; i < _shapes.Length; i++) _shapes[i] = shapes[i];
        }

        /// <summary>The shapes.</summary>
        public IReadOnlyList<SdfShape> Shapes => _shapes;

        /// <summary>The signed distance from <paramref name="p"/> (in the object's frame).</summary>
        public float Distance(Vector3 p) => Evaluate(p, out _);

        /// <summary>The signed distance and its gradient. Allocation-free.</summary>
        public float Evaluate(Vector3 p, out Vector3 gradient)
        {
            float best = _shapes[0].Evaluate(p, out gradient);
            for (int i = 1; i < _shapes.Length; i++)
            {
                float d = _shapes[i].Evaluate(p, out Vector3 g);
                if (d < best)
                {
                    best = d;
                    gradient = g;
                }
            }
            return best;
        }
    }
}
