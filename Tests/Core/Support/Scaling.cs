using System;
using System.Diagnostics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Asserts that work grows linearly with input size without a flaky absolute timing: the same work is timed at
    /// size n and 4n (best of three runs each, which drops the scheduler's and the collector's outliers), and 4n must
    /// cost less than 8 times n, plus 50 ms of slack for timer noise on small inputs. Linear work costs about 4 times
    /// as much, quadratic work 16 times. A first run beyond a hard limit fails at once (a quadratic regression at the
    /// larger size would otherwise take minutes).
    /// </summary>
    public static class Scaling
    {
        /// <summary>Times <paramref name="work"/> on the input made for n and for 4n, and asserts linear growth.</summary>
        /// <param name="make">Makes the input for a size (not timed).</param>
        /// <param name="work">The work to time.</param>
        /// <param name="n">The smaller size.</param>
        /// <param name="what">Names the work in failure messages.</param>
        /// <param name="hardLimitMs">The most a single run of the larger size may take.</param>
        public static void AssertLinear<T>(Func<int, T> make, Action<T> work, int n, string what, double hardLimitMs = 5000)
        {
            T small = make(n), large = make(4 * n);
            work(small); // warm up (JIT)
            double ts = 0, tl = double.MaxValue;
            // A machine starved by other work can slow one size's three runs alike (a CI run beside other jobs measured
            // 73 ms against 2.4 for a linear reader once): the pair is timed up to three times; quadratic work fails each.
            for (int attempt = 0; attempt < 3 && !(tl < 8 * ts + 50); attempt++)
            {
                ts = BestOf(3, () => work(small), hardLimitMs, what);
                tl = BestOf(3, () => work(large), hardLimitMs, what);
            }
            Assert.That(tl, Is.LessThan(8 * ts + 50),
                $"{what}: {tl:0.0} ms at {4 * n} against {ts:0.0} ms at {n}: grows faster than linearly (linear: about 4x, quadratic: 16x)");
        }

        /// <summary>The shortest of <paramref name="runs"/> timings of <paramref name="work"/>, in milliseconds.</summary>
        public static double BestOf(int runs, Action work, double hardLimitMs, string what)
        {
            double best = double.MaxValue;
            for (int r = 0; r < runs; r++)
            {
                var clock = Stopwatch.StartNew();
                work();
                double ms = clock.Elapsed.TotalMilliseconds;
                Assert.That(ms, Is.LessThan(hardLimitMs), $"{what}: one run took {ms:0} ms");
                best = Math.Min(best, ms);
            }
            return best;
        }
    }
}
