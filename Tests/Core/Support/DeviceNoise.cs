using System;
using System.Numerics;

namespace AvatarGo.Core.Tests
{
    /// <summary>Seeded Gaussian noise for a device's position, and percentiles of per-frame figures, for the solver's steadiness tests.</summary>
    internal static class DeviceNoise
    {
        /// <summary>A source of 3D offsets, each coordinate Gaussian with <paramref name="sigmaMetres"/> (1 mm by default), reproducible from <paramref name="seed"/>.</summary>
        public static Func<Vector3> Source(int seed, float sigmaMetres = 0.001f)
        {
            var random = new Random(seed);
            float Gaussian() => (float)(Math.Sqrt(-2.0 * Math.Log(1.0 - random.NextDouble())) * Math.Cos(2.0 * Math.PI * random.NextDouble()));
            return () => sigmaMetres * new Vector3(Gaussian(), Gaussian(), Gaussian());
        }

        /// <summary>The value below which a share <paramref name="q"/> of <paramref name="values"/> lies (1: the largest); the array is left as it was.</summary>
        public static float Percentile(float[] values, double q)
        {
            var sorted = (float[])values.Clone();
            Array.Sort(sorted);
            return sorted[Math.Min(sorted.Length - 1, (int)(q * sorted.Length))];
        }
    }
}
