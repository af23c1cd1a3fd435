using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>Eigen-decomposition of a symmetric 3×3 matrix by cyclic Jacobi rotations (double precision).</summary>
    public static class SymmetricEigen3
    {
        /// <summary>
        /// Decomposes the symmetric matrix <paramref name="m"/> (row-major, only the upper triangle is read).
        /// Eigenvalues come out in ascending order, <paramref name="vectors"/>[i] being the unit eigenvector of
        /// <paramref name="values"/>[i].
        /// </summary>
        public static void Decompose(double[,] m, double[] values, Vector3[] vectors)
        {
            if (m == null || m.GetLength(0) != 3 || m.GetLength(1) != 3) throw new ArgumentException("A 3×3 matrix is expected.", nameof(m));
            var a = new double[3, 3];
            var v = new double[3, 3] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            for (int i = 0; i < 3; i++)
                for (int j = i; j < 3; j++) a[i, j] = a[j, i] = m[i, j];
            for (int sweep = 0; sweep < 50; sweep++)
            {
                double off = a[0, 1] * a[0, 1] + a[0, 2] * a[0, 2] + a[1, 2] * a[1, 2];
                if (off < 1e-30) break;
                for (int p = 0; p < 2; p++)
                    for (int q = p + 1; q < 3; q++)
                    {
                        if (Math.Abs(a[p, q]) < 1e-300) continue;
                        double theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                        double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                        if (theta == 0) t = 1;
                        double c = 1 / Math.Sqrt(t * t + 1), s = t * c;
                        for (int k = 0; k < 3; k++)
                        {
                            double akp = a[k, p], akq = a[k, q];
                            a[k, p] = c * akp - s * akq;
                            a[k, q] = s * akp + c * akq;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double apk = a[p, k], aqk = a[q, k];
                            a[p, k] = c * apk - s * aqk;
                            a[q, k] = s * apk + c * aqk;
                        }
                        for (int k = 0; k < 3; k++)
                        {
                            double vkp = v[k, p], vkq = v[k, q];
                            v[k, p] = c * vkp - s * vkq;
                            v[k, q] = s * vkp + c * vkq;
                        }
                    }
            }
            int[] order = { 0, 1, 2 };
            Array.Sort(new[] { a[0, 0], a[1, 1], a[2, 2] }, order);
            for (int i = 0; i < 3; i++)
            {
                int k = order[i];
                values[i] = a[k, k];
                vectors[i] = Vector3.Normalize(new Vector3((float)v[0, k], (float)v[1, k], (float)v[2, k]));
            }
        }
    }
}
