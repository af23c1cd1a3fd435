using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// One signed-distance primitive, in the frame of the object it belongs to (a controller): negative inside,
    /// zero on the surface, positive outside, in metres, with its analytic gradient. A plain struct evaluated by
    /// a switch (no virtual calls, no allocation).
    /// </summary>
    public readonly struct SdfShape
    {
        /// <summary>The primitive.</summary>
        public readonly SdfShapeKind Kind;

        /// <summary>Capsule: start point. Sphere: centre. Box, rounded box: centre.</summary>
        public readonly Vector3 A;

        /// <summary>Capsule: end point. Box, rounded box: half extents (before rounding). Unused otherwise.</summary>
        public readonly Vector3 B;

        /// <summary>Capsule, sphere, rounded box: radius. Unused for a box.</summary>
        public readonly float Radius;

        /// <summary>Box, rounded box: orientation of the box in the object frame.</summary>
        public readonly Quaternion Rotation;

        // A box whose rotation is the identity (every shipped profile's): its frame is the controller's, and the two
        // rotations per evaluation are skipped (turning by the identity changes no bit, so the result is the same).
        private readonly bool _axisAligned;

        private SdfShape(SdfShapeKind kind, Vector3 a, Vector3 b, float radius, Quaternion rotation)
        {
            Kind = kind;
            A = a;
            B = b;
            Radius = radius;
            Rotation = rotation;
            _axisAligned = rotation == Quaternion.Identity;
        }

        /// <summary>A capsule around the segment <paramref name="start"/>–<paramref name="end"/>.</summary>
        public static SdfShape Capsule(Vector3 start, Vector3 end, float radius) => new SdfShape(SdfShapeKind.Capsule, start, end, Check(radius), Quaternion.Identity);

        /// <summary>A sphere.</summary>
        public static SdfShape Sphere(Vector3 centre, float radius) => new SdfShape(SdfShapeKind.Sphere, centre, Vector3.Zero, Check(radius), Quaternion.Identity);

        /// <summary>A box with the given centre, half extents and orientation.</summary>
        public static SdfShape Box(Vector3 centre, Vector3 halfExtents, Quaternion rotation) =>
            new SdfShape(SdfShapeKind.Box, centre, Vector3.Max(halfExtents, Vector3.Zero), 0f, Quaternion.Normalize(rotation));

        /// <summary>A box whose edges are rounded by <paramref name="radius"/> (its outer half extents stay <paramref name="halfExtents"/>).</summary>
        public static SdfShape RoundedBox(Vector3 centre, Vector3 halfExtents, float radius, Quaternion rotation) =>
            new SdfShape(SdfShapeKind.RoundedBox, centre, Vector3.Max(halfExtents - new Vector3(Check(radius)), Vector3.Zero), radius, Quaternion.Normalize(rotation));

        /// <summary>The signed distance from <paramref name="p"/> to the surface.</summary>
        public float Distance(Vector3 p) => Evaluate(p, out _);

        /// <summary>The signed distance and its gradient (the unit outward direction of steepest increase).</summary>
        public float Evaluate(Vector3 p, out Vector3 gradient)
        {
            switch (Kind)
            {
                case SdfShapeKind.Capsule:
                {
                    // The paper's formula: h = clamp(v1·v2 / v2·v2, 0, 1), d = |v1 − v2 h| − r.
                    Vector3 v1 = p - A, v2 = B - A;
                    float vv = Vector3.Dot(v2, v2);
                    float h = vv > 1e-12f ? Math.Max(0f, Math.Min(1f, Vector3.Dot(v1, v2) / vv)) : 0f;
                    Vector3 d = v1 - v2 * h;
                    float len = d.Length();
                    gradient = len > 1e-9f ? d / len : Vector3.UnitY;
                    return len - Radius;
                }
                case SdfShapeKind.Sphere:
                {
                    Vector3 d = p - A;
                    float len = d.Length();
                    gradient = len > 1e-9f ? d / len : Vector3.UnitY;
                    return len - Radius;
                }
                default:
                {
                    Vector3 q = _axisAligned ? p - A : Vector3.Transform(p - A, Quaternion.Conjugate(Rotation));
                    Vector3 e = Vector3.Abs(q) - B;
                    Vector3 outside = Vector3.Max(e, Vector3.Zero);
                    float outsideLength = outside.Length();
                    float inside = Math.Min(Math.Max(e.X, Math.Max(e.Y, e.Z)), 0f);
                    Vector3 local;
                    if (outsideLength > 1e-9f) local = outside / outsideLength;
                    else if (e.X >= e.Y && e.X >= e.Z) local = Vector3.UnitX;
                    else if (e.Y >= e.Z) local = Vector3.UnitY;
                    else local = Vector3.UnitZ;
                    local = new Vector3(q.X < 0 ? -local.X : local.X, q.Y < 0 ? -local.Y : local.Y, q.Z < 0 ? -local.Z : local.Z);
                    gradient = _axisAligned ? local : Vector3.Transform(local, Rotation);
                    float radius = Kind == SdfShapeKind.RoundedBox ? Radius : 0f;
                    return outsideLength + inside - radius;
                }
            }
        }

        private static float Check(float radius)
        {
            if (!(radius >= 0f) || float.IsInfinity(radius)) throw new ArgumentOutOfRangeException(nameof(radius), radius, "A radius must be finite and non-negative.");
            return radius;
        }
    }
}
