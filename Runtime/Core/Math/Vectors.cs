using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>Small vector helpers the core needs and System.Numerics lacks.</summary>
    public static class Vectors
    {
        /// <summary>Unity's up axis (+Y).</summary>
        public static readonly Vector3 Up = Vector3.UnitY;

        /// <summary>Unity's forward axis (+Z).</summary>
        public static readonly Vector3 Forward = Vector3.UnitZ;

        /// <summary>Unity's right axis (+X).</summary>
        public static readonly Vector3 Right = Vector3.UnitX;

        /// <summary>True when every component is finite (no NaN, no infinity).</summary>
        public static bool IsFinite(Vector3 v) => IsFinite(v.X) && IsFinite(v.Y) && IsFinite(v.Z);

        /// <summary>True when the value is neither NaN nor infinite.</summary>
        public static bool IsFinite(float f) => !float.IsNaN(f) && !float.IsInfinity(f);

        /// <summary>
        /// The unit vector along <paramref name="v"/>, or <paramref name="fallback"/> when
        /// <paramref name="v"/> is shorter than 1e-8 or not finite.
        /// </summary>
        public static Vector3 NormalizeOr(Vector3 v, Vector3 fallback)
        {
            float lengthSquared = v.LengthSquared();
            if (!(lengthSquared > 1e-16f) || !IsFinite(lengthSquared)) return fallback;
            return v / System.MathF.Sqrt(lengthSquared);
        }

        /// <summary><paramref name="v"/> with its component along the unit vector <paramref name="normal"/> removed.</summary>
        public static Vector3 ProjectOnPlane(Vector3 v, Vector3 normal) => v - Vector3.Dot(v, normal) * normal;

        /// <summary>The distance between <paramref name="a"/> and <paramref name="b"/> on the floor plane (y up ignored).</summary>
        public static float HorizontalDistance(Vector3 a, Vector3 b) => new Vector2(a.X - b.X, a.Z - b.Z).Length();

        /// <summary>The unsigned angle between two vectors, in degrees (0 for a zero vector).</summary>
        public static float AngleDegrees(Vector3 a, Vector3 b)
        {
            float denominator = System.MathF.Sqrt(a.LengthSquared() * b.LengthSquared());
            if (denominator < 1e-12f) return 0f;
            float cos = System.Math.Clamp(Vector3.Dot(a, b) / denominator, -1f, 1f);
            return System.MathF.Acos(cos) * Rotations.Rad2Deg;
        }

        /// <summary>
        /// The angle from <paramref name="from"/> to <paramref name="to"/> about <paramref name="axis"/>,
        /// in degrees, signed like Unity's <c>Vector3.SignedAngle</c>: positive when <c>Cross(from, to)</c> points along <paramref name="axis"/>.
        /// </summary>
        public static float SignedAngleDegrees(Vector3 from, Vector3 to, Vector3 axis)
        {
            float angle = AngleDegrees(from, to);
            return Vector3.Dot(axis, Vector3.Cross(from, to)) < 0f ? -angle : angle;
        }
    }
}
