using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    public class ErrorSeriesTests
    {
        [Test]
        public void PercentilesInterpolateBetweenRanks()
        {
            var s = new ErrorSeries();
            // 101 samples 0..100 added in reverse: the p-th percentile is exactly p.
            for (int i = 100; i >= 0; i--) s.Add(i);
            Assert.That(s.Median, Is.EqualTo(50.0).Within(1e-12));
            Assert.That(s.P95, Is.EqualTo(95.0).Within(1e-12));
            Assert.That(s.Max, Is.EqualTo(100.0).Within(1e-12));
            Assert.That(s.Mean, Is.EqualTo(50.0).Within(1e-12));
            Assert.That(s.Percentile(12.5), Is.EqualTo(12.5).Within(1e-12));
        }

        [Test]
        public void EvenCountMedianIsMidpointAndInvalidSamplesAreCountedApart()
        {
            var s = new ErrorSeries();
            s.Add(4); s.Add(1); s.Add(double.NaN); s.Add(3); s.Add(2); s.Add(double.PositiveInfinity);
            Assert.That(s.Count, Is.EqualTo(4));
            Assert.That(s.InvalidCount, Is.EqualTo(2));
            Assert.That(s.Median, Is.EqualTo(2.5).Within(1e-12));
            Assert.That(new ErrorSeries().Median, Is.NaN);
        }
    }
}
