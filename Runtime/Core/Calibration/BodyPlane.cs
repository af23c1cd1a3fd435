using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The plane of the body in T-pose, fitted through the device positions by orthogonal least squares
    /// (the eigenvector of the smallest eigenvalue of their covariance is the normal), so it works for any
    /// facing direction and anywhere in the play area. The normal is oriented along the wearer's facing.
    /// </summary>
    public readonly struct BodyPlane
    {
        /// <summary>The centroid of the points.</summary>
        public readonly Vector3 Centroid;

        /// <summary>The unit normal, pointing the way the wearer faces.</summary>
        public readonly Vector3 Normal;

        /// <summary>Root-mean-square distance of the points from the plane, in metres.</summary>
        public readonly float RmsDistance;

        private BodyPlane(Vector3 centroid, Vector3 normal, float rms)
        {
            Centroid = centroid;
            Normal = normal;
            RmsDistance = rms;
        }

        /// <summary>
        /// Fits the plane through <paramref name="points"/> (at least 3) and orients its normal to agree with
        /// <paramref name="facingHint"/> (the HMD's forward).
        /// </summary>
        public static BodyPlane Fit(ReadOnlySpan<Vector3> points, Vector3 facingHint)
        {
            if (points.Length < 3) throw new ArgumentException("A plane needs at least three points.", nameof(points));
            Vector3 c = Vector3.Zero;
            foreach (Vector3 p in points) c += p;
            c /= points.Length;
            var m = new double[3, 3];
            foreach (Vector3 p in points)
            {
                Vector3 d = p - c;
                m[0, 0] += d.X * d.X; m[0, 1] += d.X * d.Y; m[0, 2] += d.X * d.Z;
                m[1, 1] += d.Y * d.Y; m[1, 2] += d.Y * d.Z; m[2, 2] += d.Z * d.Z;
            }
            var values = new double[3];
            var vectors = new Vector3[3];
            SymmetricEigen3.Decompose(m, values, vectors);
            Vector3 n = vectors[0];
            if (Vector3.Dot(n, facingHint) < 0f) n = -n;
            return new BodyPlane(c, n, (float)Math.Sqrt(Math.Max(0, values[0]) / points.Length));
        }
    }
}
