using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The last samples of every device, for averaging over the <see cref="CalibrationSettings.WindowSeconds"/> before a
    /// trigger press: calibration never measures a single frame. A preallocated ring per device; <see cref="Add"/>
    /// allocates nothing.
    /// </summary>
    public sealed class SampleWindow
    {
        /// <summary>A device counts as tracked through the window when it was tracked in this share of its frames (80 %).</summary>
        public const float MinTrackedFraction = 0.8f;

        /// <summary>
        /// A device counts as still only when the window's frames span at least this share of it (80 %): a press in the first
        /// frames after the calibrator was made or reset, with a frame or two to average, is refused as not yet still.
        /// </summary>
        public const float MinCoveredFraction = 0.8f;

        private readonly CalibrationSettings _settings;
        private readonly int _capacity;
        private readonly double[] _times;
        private readonly RigidPose[,] _poses;
        private readonly bool[,] _tracked;
        private readonly Vector3[] _positions;
        private readonly Quaternion[] _rotations;
        private int _head = -1, _count;

        /// <summary>
        /// Creates the rings for <paramref name="deviceCount"/> devices. <paramref name="capacity"/> frames are kept
        /// (512 covers the default 0.5 s window up to 1 kHz).
        /// </summary>
        public SampleWindow(int deviceCount, CalibrationSettings settings, int capacity = 512)
        {
            if (deviceCount < 0) throw new ArgumentOutOfRangeException(nameof(deviceCount));
            if (capacity < 2) throw new ArgumentOutOfRangeException(nameof(capacity));
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            _capacity = capacity;
            _times = new double[capacity];
            _poses = new RigidPose[deviceCount, capacity];
            _tracked = new bool[deviceCount, capacity];
            _positions = new Vector3[capacity];
            _rotations = new Quaternion[capacity];
            DeviceCount = deviceCount;
        }

        /// <summary>The number of devices.</summary>
        public int DeviceCount { get; }

        /// <summary>Records one frame: the samples of every device, in device order. Allocation-free.</summary>
        public void Add(double time, ReadOnlySpan<DeviceSample> samples)
        {
            if (samples.Length != DeviceCount) throw new ArgumentException($"Expected {DeviceCount} samples, got {samples.Length}.", nameof(samples));
            _head = (_head + 1) % _capacity;
            _times[_head] = time;
            for (int d = 0; d < DeviceCount; d++)
            {
                bool usable = samples[d].IsUsable;
                _tracked[d, _head] = usable;
                _poses[d, _head] = usable ? samples[d].Pose : RigidPose.Identity;
            }
            if (_count < _capacity) _count++;
        }

        /// <summary>Forgets every frame.</summary>
        public void Clear()
        {
            _head = -1;
            _count = 0;
        }

        /// <summary>
        /// Device <paramref name="device"/> averaged over the window that ends at <paramref name="now"/>: mean pose, share
        /// of frames tracked, and whether every tracked sample is within <see cref="CalibrationSettings.StillPosition"/>
        /// and <see cref="CalibrationSettings.StillRotationDegrees"/> of the mean. Allocation-free.
        /// </summary>
        public WindowAverage Average(int device, double now)
        {
            if ((uint)device >= (uint)DeviceCount) throw new ArgumentOutOfRangeException(nameof(device));
            int n = 0, total = 0;
            double oldest = now;
            for (int k = 0; k < _count; k++)
            {
                int i = (_head - k + _capacity) % _capacity;
                if (now - _times[i] > _settings.WindowSeconds + 1e-9) break;
                total++;
                oldest = _times[i];
                if (!_tracked[device, i]) continue;
                _positions[n] = _poses[device, i].Position;
                _rotations[n] = _poses[device, i].Rotation;
                n++;
            }
            if (n == 0) return new WindowAverage(RigidPose.Identity, 0f, false);
            Vector3 p = Vector3.Zero;
            for (int i = 0; i < n; i++) p += _positions[i];
            p /= n;
            Quaternion q = Rotations.Average(new ReadOnlySpan<Quaternion>(_rotations, 0, n));
            // A window its frames do not yet cover (a press in the first frames after the calibrator was made or reset)
            // measures too little to count as still: one frame is always still. A full ring covers what it can hold.
            bool still = now - oldest >= MinCoveredFraction * _settings.WindowSeconds - 1e-6 || total == _capacity;
            for (int i = 0; i < n && still; i++)
                still = Vector3.Distance(_positions[i], p) <= _settings.StillPosition && Rotations.AngleDegrees(_rotations[i], q) <= _settings.StillRotationDegrees;
            return new WindowAverage(new RigidPose(p, q), n / (float)total, still);
        }
    }
}
