using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Quaternion helpers with Unity's semantics (LookRotation, FromToRotation, angles in degrees),
    /// built on System.Numerics. <c>Vector3.Transform(v, q)</c> is Unity's <c>q * v</c> and
    /// <c>a * b</c> applies <c>b</c> first, as in Unity.
    /// </summary>
    public static class Rotations
    {
        /// <summary>Degrees per radian.</summary>
        public const float Rad2Deg = 180f / MathF.PI;

        /// <summary>Radians per degree.</summary>
        public const float Deg2Rad = MathF.PI / 180f;

        /// <summary>True when every component is finite.</summary>
        public static bool IsFinite(Quaternion q) =>
            Vectors.IsFinite(q.X) && Vectors.IsFinite(q.Y) && Vectors.IsFinite(q.Z) && Vectors.IsFinite(q.W);

        /// <summary>True when the quaternion is finite and of unit length within 1e-3.</summary>
        public static bool IsUnit(Quaternion q) => IsFinite(q) && MathF.Abs(q.LengthSquared() - 1f) < 2e-3f;

        /// <summary>
        /// The normalised quaternion, or <paramref name="fallback"/> when <paramref name="q"/> is
        /// not finite or (nearly) zero-length.
        /// </summary>
        public static Quaternion NormalizeOr(Quaternion q, Quaternion fallback)
        {
            float lengthSquared = q.LengthSquared();
            if (!(lengthSquared > 1e-12f) || !Vectors.IsFinite(lengthSquared)) return fallback;
            return Quaternion.Multiply(q, 1f / MathF.Sqrt(lengthSquared));
        }

        /// <summary>A rotation of <paramref name="degrees"/> about <paramref name="axis"/> (Unity's <c>Quaternion.AngleAxis</c>).</summary>
        public static Quaternion AngleAxis(float degrees, Vector3 axis) =>
            Quaternion.CreateFromAxisAngle(Vectors.NormalizeOr(axis, Vector3.UnitY), degrees * Deg2Rad);

        /// <summary>The angle of the rotation between two orientations, in degrees [0, 180].</summary>
        public static float AngleDegrees(Quaternion a, Quaternion b)
        {
            // atan2 of the relative rotation's vector and scalar parts: exact near 0°, where acos(dot) is not.
            Quaternion d = Quaternion.Conjugate(a) * b;
            double vector = Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y + (double)d.Z * d.Z);
            return (float)(2.0 * Math.Atan2(vector, Math.Abs((double)d.W)) * (180.0 / Math.PI));
        }

        /// <summary>
        /// The shortest rotation taking direction <paramref name="from"/> to direction <paramref name="to"/>
        /// (Unity's <c>Quaternion.FromToRotation</c>), computed in double precision: near-opposite directions (a limb
        /// swung through almost 180°) lose a millimetre in single precision. Opposite directions give half a turn about
        /// an axis perpendicular to <paramref name="from"/>; a zero or non-finite direction gives the identity.
        /// </summary>
        public static Quaternion FromTo(Vector3 from, Vector3 to)
        {
            double fx = from.X, fy = from.Y, fz = from.Z, tx = to.X, ty = to.Y, tz = to.Z;
            double fl = Math.Sqrt(fx * fx + fy * fy + fz * fz), tl = Math.Sqrt(tx * tx + ty * ty + tz * tz);
            if (!(fl > 1e-12) || !(tl > 1e-12) || double.IsInfinity(fl) || double.IsInfinity(tl)) return Quaternion.Identity;
            fx /= fl; fy /= fl; fz /= fl; tx /= tl; ty /= tl; tz /= tl;
            double cx = fy * tz - fz * ty, cy = fz * tx - fx * tz, cz = fx * ty - fy * tx;
            double w = 1.0 + fx * tx + fy * ty + fz * tz;
            if (w < 1e-12)
            {
                // Opposite: half a turn about any axis perpendicular to from.
                if (Math.Abs(fx) < 0.9) { cx = 0; cy = -fz; cz = fy; } else { cx = fz; cy = 0; cz = -fx; }
                w = 0;
            }
            double n = Math.Sqrt(cx * cx + cy * cy + cz * cz + w * w);
            return new Quaternion((float)(cx / n), (float)(cy / n), (float)(cz / n), (float)(w / n));
        }

        /// <summary>
        /// The rotation whose +Z axis points along <paramref name="forward"/> and whose +Y axis is as
        /// close as possible to <paramref name="up"/> (Unity's <c>Quaternion.LookRotation</c>).
        /// Degenerate input (zero forward, forward parallel to up) still gives a valid rotation.
        /// </summary>
        public static Quaternion LookRotation(Vector3 forward, Vector3 up)
        {
            Vector3 f = Vectors.NormalizeOr(forward, Vector3.UnitZ);
            Vector3 r = Vector3.Cross(up, f);
            if (r.LengthSquared() < 1e-10f)
            {
                // up is parallel to forward: pick any perpendicular right axis.
                r = Vector3.Cross(MathF.Abs(f.Y) < 0.9f ? Vector3.UnitY : Vector3.UnitZ, f);
            }
            r = Vector3.Normalize(r);
            Vector3 u = Vector3.Cross(f, r);
            return FromBasis(r, u, f);
        }

        /// <summary>
        /// The rotation that maps +X, +Y, +Z onto the given orthonormal axes.
        /// </summary>
        public static Quaternion FromBasis(Vector3 right, Vector3 up, Vector3 forward)
        {
            // System.Numerics matrices are row-vector: row i is the image of basis axis i.
            var m = new Matrix4x4(
                right.X, right.Y, right.Z, 0f,
                up.X, up.Y, up.Z, 0f,
                forward.X, forward.Y, forward.Z, 0f,
                0f, 0f, 0f, 1f);
            return Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(m));
        }

        /// <summary>
        /// The average of rotations that are close to each other (a stillness window): signs are aligned
        /// with the first sample, components summed, the result normalised. For spreads of a few degrees
        /// this equals the eigenvector (Markley) average to well under 0.01°.
        /// </summary>
        public static Quaternion Average(ReadOnlySpan<Quaternion> rotations)
        {
            if (rotations.Length == 0) return Quaternion.Identity;
            Quaternion reference = rotations[0];
            Vector4 sum = Vector4.Zero;
            for (int i = 0; i < rotations.Length; i++)
            {
                Quaternion q = rotations[i];
                if (Quaternion.Dot(q, reference) < 0f) q = new Quaternion(-q.X, -q.Y, -q.Z, -q.W);
                sum += new Vector4(q.X, q.Y, q.Z, q.W);
            }
            return NormalizeOr(new Quaternion(sum.X, sum.Y, sum.Z, sum.W), reference);
        }

        /// <summary>
        /// Splits <paramref name="rotation"/> into a twist about the unit <paramref name="axis"/> and the
        /// remaining swing, such that <c>rotation == swing * twist</c>.
        /// </summary>
        public static void SwingTwist(Quaternion rotation, Vector3 axis, out Quaternion swing, out Quaternion twist)
        {
            Vector3 r = new Vector3(rotation.X, rotation.Y, rotation.Z);
            Vector3 p = Vector3.Dot(r, axis) * axis;
            twist = NormalizeOr(new Quaternion(p.X, p.Y, p.Z, rotation.W), Quaternion.Identity);
            swing = rotation * Quaternion.Conjugate(twist);
        }

        /// <summary>The same orientation with a non-negative w, for stable comparison and output.</summary>
        public static Quaternion Canonical(Quaternion q) => q.W < 0f ? new Quaternion(-q.X, -q.Y, -q.Z, -q.W) : q;
    }
}
