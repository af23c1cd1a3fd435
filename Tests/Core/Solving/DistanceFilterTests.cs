using System;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The One Euro filter on one distance that the straight limbs and the back's chord use: a still distance settles with
    /// the cutoff's time constant at any frame rate, a moving one lags less the faster it moves, and a distance that is not
    /// finite, or a repeated frame, leaves it as it was.
    /// </summary>
    public class DistanceFilterTests
    {
        // The filtered value `seconds` after a step from 0.5 to 0.501 m (1 mm), at `rate` frames a second.
        private static float AfterStep(int rate, double seconds, float cutoffHz)
        {
            var filter = new DistanceFilter();
            filter.Filter(0.5f, 1f / rate, cutoffHz);
            float value = 0.5f;
            for (int f = 0; f < (int)Math.Round(seconds * rate); f++) value = filter.Filter(0.501f, 1f / rate, cutoffHz);
            return value;
        }

        [Test]
        public void AStillDistanceSettlesWithTheCutoffsTimeConstantAtAnyRate()
        {
            // 1 Hz: time constant 1/(2π) s. A 1 mm step is slow enough that the speed term adds little (20 Hz per m/s).
            double tau = 1.0 / (2.0 * Math.PI);
            foreach (int rate in new[] { 45, 90, 180 })
            {
                float left = (0.501f - AfterStep(rate, tau, 1f)) * 1000f; // mm of the step still to go
                TestContext.WriteLine($"{rate} Hz: {left:F3} mm of 1 mm left after one time constant");
                Assert.That(left, Is.InRange(0.2f, 0.45f), $"{rate} Hz: about e^-1 of the step left after one time constant (mm)");
            }
            Assert.That(Math.Abs(AfterStep(45, tau, 1f) - AfterStep(180, tau, 1f)) * 1000f, Is.LessThan(0.08f), "the same at 45 and 180 Hz (mm)");
        }

        [Test]
        public void AFasterMoveLagsLess()
        {
            // A ramp at 0.02 and at 0.5 m/s for half a second: the lag behind the ramp, relative to how far it went.
            float RelativeLag(float speed)
            {
                var filter = new DistanceFilter();
                float d = 0.5f, value = 0f;
                for (int f = 0; f <= 45; f++, d += speed / 90f) value = filter.Filter(d, 1f / 90f, 1f);
                return (d - speed / 90f - value) / (speed * 0.5f);
            }
            float slow = RelativeLag(0.02f), fast = RelativeLag(0.5f);
            TestContext.WriteLine($"lag as a share of the move: {slow:F3} at 0.02 m/s, {fast:F3} at 0.5 m/s");
            Assert.That(fast, Is.LessThan(0.5f * slow), "the cutoff rises with the speed");
        }

        [Test]
        public void ANonFiniteDistanceOrARepeatedFrameLeavesItAsItWas()
        {
            var filter = new DistanceFilter();
            filter.Filter(0.5f, 1f / 90f, 1f);
            float before = filter.Filter(0.51f, 1f / 90f, 1f);
            Assert.That(filter.Filter(float.NaN, 1f / 90f, 1f), Is.NaN, "returned as it is");
            Assert.That(filter.Filter(float.PositiveInfinity, 1f / 90f, 1f), Is.EqualTo(float.PositiveInfinity));
            Assert.That(filter.Filter(-1f, 1f / 90f, 1f), Is.EqualTo(-1f), "a negative distance is no distance");
            Assert.That(filter.Filter(0.51f, 0f, 1f), Is.EqualTo(before), "a repeated frame filters nothing");
            var clean = new DistanceFilter();
            clean.Filter(0.5f, 1f / 90f, 1f);
            clean.Filter(0.51f, 1f / 90f, 1f);
            Assert.That(filter.Filter(0.52f, 1f / 90f, 1f), Is.EqualTo(clean.Filter(0.52f, 1f / 90f, 1f)), "the next frame as if the bad ones had not come");
            filter.Reset();
            Assert.That(filter.Filter(0.7f, 1f / 90f, 1f), Is.EqualTo(0.7f), "after a reset the first distance is taken as it is");
        }
    }
}
