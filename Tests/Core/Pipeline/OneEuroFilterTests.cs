using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The One Euro filter: steadies a still device, follows a moving one, and does not depend on the frame rate.</summary>
    public class OneEuroFilterTests
    {
        private static DeviceSample At(Vector3 p) => new DeviceSample(new RigidPose(p, Quaternion.Identity), true);

        [Test]
        public void AStillNoisyDeviceBecomesSteady()
        {
            var rng = new Random(5);
            var filter = new OneEuroFilter(1, 2f, 30f);
            var one = new DeviceSample[1];
            double rawSum = 0, filteredSum = 0;
            for (int i = 0; i < 900; i++)
            {
                var noise = new Vector3((float)(rng.NextDouble() - 0.5), (float)(rng.NextDouble() - 0.5), (float)(rng.NextDouble() - 0.5)) * 0.004f;
                one[0] = At(new Vector3(0, 1, 0) + noise);
                filter.Apply(i / 90.0, one);
                if (i < 90) continue;
                rawSum += noise.LengthSquared();
                filteredSum += (one[0].Pose.Position - new Vector3(0, 1, 0)).LengthSquared();
            }
            Assert.That(Math.Sqrt(filteredSum / rawSum), Is.LessThan(0.5), "RMS deviation at most half the raw one");
        }

        [Test]
        public void AMovingDeviceIsFollowedWithLittleLag()
        {
            var filter = new OneEuroFilter(1, 2f, 30f);
            var one = new DeviceSample[1];
            float worst = 0f;
            for (int i = 0; i < 180; i++)
            {
                var p = new Vector3(1.5f * i / 90f, 1, 0); // 1.5 m/s, a brisk hand
                one[0] = At(p);
                filter.Apply(i / 90.0, one);
                if (i > 30) worst = Math.Max(worst, Vector3.Distance(one[0].Pose.Position, p));
            }
            Assert.That(worst, Is.LessThan(0.01f), "behind by less than 1 cm at 1.5 m/s (m)");
        }

        /// <summary>
        /// A frame in which no time passed, or the clock went back, keeps the filtered pose where it was; the next frames go
        /// on from it (found in review: such a frame seeded the filter again from the raw sample, a jump by the whole lag,
        /// centimetres on a moving hand, and its speed estimate started from zero).
        /// </summary>
        [TestCase(0.0)]
        [TestCase(-5.0)]
        public void ARepeatedOrBackwardFrameDoesNotJump(double back)
        {
            var filter = new OneEuroFilter(1, 1f, 0.5f);
            var one = new DeviceSample[1];
            Vector3 Path(int i) => new Vector3(1.5f * i / 90f, 1, 0);
            double t = 0;
            Vector3 previous = default;
            for (int i = 0; i < 90; i++)
            {
                one[0] = At(Path(i));
                filter.Apply(t = i / 90.0, one);
                previous = one[0].Pose.Position;
            }
            float lag = Vector3.Distance(previous, Path(89));
            one[0] = At(Path(90));
            filter.Apply(t += back, one);
            Assert.That(Vector3.Distance(one[0].Pose.Position, previous), Is.LessThan(1e-6f), "the filtered pose stays (m)");
            float largestStep = 0f;
            for (int i = 91; i < 120; i++)
            {
                one[0] = At(Path(i));
                filter.Apply(t += 1 / 90.0, one);
                largestStep = Math.Max(largestStep, Vector3.Distance(one[0].Pose.Position, previous));
                previous = one[0].Pose.Position;
            }
            TestContext.WriteLine($"lag {lag * 1000:F1} mm, largest step after the frame {largestStep * 1000:F1} mm (the path moves {1.5f / 90 * 1000:F1} mm a frame)");
            Assert.That(lag, Is.GreaterThan(0.01f), "the filter lags enough for a re-seed to show (m)");
            Assert.That(largestStep, Is.LessThan(lag), "no step as large as the lag afterwards");
        }

        [Test]
        public void TheResultDoesNotDependOnTheFrameRate()
        {
            // The same motion (a 1 Hz sway) at 72 and 144 Hz: the filtered positions agree where the rates share times.
            Vector3 Sway(double t) => new Vector3(0.2f * (float)Math.Sin(2 * Math.PI * t), 1, 0);
            var slow = new OneEuroFilter(1, 2f, 30f);
            var fast = new OneEuroFilter(1, 2f, 30f);
            var a = new DeviceSample[1];
            var b = new DeviceSample[1];
            float largest = 0f;
            for (int i = 0; i < 144 * 3; i++)
            {
                double t = i / 144.0;
                b[0] = At(Sway(t));
                fast.Apply(t, b);
                if (i % 2 != 0) continue;
                a[0] = At(Sway(t));
                slow.Apply(t, a);
                if (i > 144) largest = Math.Max(largest, Vector3.Distance(a[0].Pose.Position, b[0].Pose.Position));
            }
            Assert.That(largest, Is.LessThan(0.002f), "m");
        }

        [Test]
        public void ALostDeviceStartsAgainFromItsNextSample()
        {
            var filter = new OneEuroFilter(1, 2f, 30f);
            var one = new DeviceSample[1];
            one[0] = At(Vector3.Zero);
            filter.Apply(0, one);
            one[0] = DeviceSample.Lost;
            filter.Apply(1 / 90.0, one);
            one[0] = At(new Vector3(2, 0, 0));
            filter.Apply(2 / 90.0, one);
            Assert.That(one[0].Pose.Position.X, Is.EqualTo(2f), "not dragged from before the loss");
        }
    }
}
