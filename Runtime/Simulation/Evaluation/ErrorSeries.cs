using System;
using System.Collections.Generic;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Collects one error measure (millimetres, degrees) over many frames and summarises it:
    /// median, mean, 95th percentile, maximum. Storage grows with the number of samples; meant for
    /// evaluation and tests, not for per-frame code in an application.
    /// </summary>
    public sealed class ErrorSeries
    {
        private readonly List<double> _values = new List<double>();
        private bool _sorted = true;
        private double _sum;

        /// <summary>The number of samples added.</summary>
        public int Count => _values.Count;

        /// <summary>Adds one sample; NaN or infinite samples are counted in <see cref="InvalidCount"/> instead.</summary>
        public void Add(double value)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
            {
                InvalidCount++;
                return;
            }
            if (_values.Count > 0 && value < _values[_values.Count - 1]) _sorted = false;
            _values.Add(value);
            _sum += value;
        }

        /// <summary>Samples that were NaN or infinite (a solver bug if ever non-zero).</summary>
        public int InvalidCount { get; private set; }

        /// <summary>The arithmetic mean, or NaN with no samples.</summary>
        public double Mean => _values.Count == 0 ? double.NaN : _sum / _values.Count;

        /// <summary>The median (50th percentile).</summary>
        public double Median => Percentile(50);

        /// <summary>The 95th percentile.</summary>
        public double P95 => Percentile(95);

        /// <summary>The largest sample, or NaN with no samples.</summary>
        public double Max => Percentile(100);

        /// <summary>
        /// The <paramref name="percent"/>th percentile with linear interpolation between closest ranks
        /// (the definition of numpy's default), or NaN with no samples.
        /// </summary>
        public double Percentile(double percent)
        {
            if (_values.Count == 0) return double.NaN;
            if (!_sorted)
            {
                _values.Sort();
                _sorted = true;
            }
            double p = Math.Max(0, Math.Min(100, percent)) / 100.0 * (_values.Count - 1);
            int lo = (int)Math.Floor(p);
            int hi = Math.Min(lo + 1, _values.Count - 1);
            return _values[lo] + (_values[hi] - _values[lo]) * (p - lo);
        }

        /// <summary>The share (0…1) of the samples above <paramref name="threshold"/>, or NaN with no samples.</summary>
        public double ShareAbove(double threshold)
        {
            if (_values.Count == 0) return double.NaN;
            int above = 0;
            foreach (double v in _values) if (v > threshold) above++;
            return (double)above / _values.Count;
        }

        /// <summary>Adds every sample of another series.</summary>
        public void AddAll(ErrorSeries other)
        {
            if (other == null) throw new ArgumentNullException(nameof(other));
            foreach (double v in other._values) Add(v);
            InvalidCount += other.InvalidCount;
        }
    }
}
