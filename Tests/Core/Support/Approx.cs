using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>Assertions on vectors, quaternions and poses with explicit tolerances.</summary>
    public static class Approx
    {
        /// <summary>Asserts that two points are within <paramref name="metres"/> of each other.</summary>
        public static void Near(Vector3 expected, Vector3 actual, float metres, string what = null)
        {
            float d = Vector3.Distance(expected, actual);
            Assert.That(d, Is.LessThanOrEqualTo(metres), $"{what ?? "position"}: expected {expected}, got {actual} ({d * 1000f:F3} mm apart)");
        }

        /// <summary>Asserts that two rotations differ by at most <paramref name="degrees"/>.</summary>
        public static void Near(Quaternion expected, Quaternion actual, float degrees, string what = null)
        {
            float a = Rotations.AngleDegrees(expected, actual);
            Assert.That(a, Is.LessThanOrEqualTo(degrees), $"{what ?? "rotation"}: expected {expected}, got {actual} ({a:F4}° apart)");
        }

        /// <summary>Asserts both parts of two poses.</summary>
        public static void Near(RigidPose expected, RigidPose actual, float metres, float degrees, string what = null)
        {
            Near(expected.Position, actual.Position, metres, what);
            Near(expected.Rotation, actual.Rotation, degrees, what);
        }
    }
}
