using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Damages a session's frames as a headset in a real room would: each device lost in bursts (a Markov process whose
    /// bursts last a uniform 1 frame to <see cref="DisturbanceOptions.DropoutMaxSeconds"/>, started so that the device is lost
    /// <see cref="DisturbanceOptions.DropoutRate"/> of the time), extra Gaussian noise, and teleports (a tracked pose suddenly
    /// metres away for a moment). Reproducible from its seed; knows which devices it disturbed in the current frame.
    /// </summary>
    public sealed class SessionDisturber
    {
        private readonly DisturbanceOptions _options;
        private readonly Random _rng;
        private readonly int[] _lostFrames;
        private readonly int[] _teleportFrames;
        private readonly Vector3[] _teleport;
        private readonly bool[] _disturbed, _lostNow;
        private readonly int _maxBurst, _teleportLength;
        private readonly double _burstStart, _teleportStart;

        /// <summary>Creates a disturber for sessions of <paramref name="devices"/> devices at <paramref name="rate"/> Hz.</summary>
        public SessionDisturber(int devices, float rate, DisturbanceOptions options)
        {
            _options = options ?? throw new ArgumentNullException(nameof(options));
            if (!(options.DropoutRate >= 0f && options.DropoutRate <= 0.9f)) throw new ArgumentOutOfRangeException(nameof(options), options.DropoutRate, "The dropout rate must be between 0 and 0.9.");
            if (!(rate > 0f)) throw new ArgumentOutOfRangeException(nameof(rate));
            _rng = new Random(options.Seed);
            _lostFrames = new int[devices];
            _teleportFrames = new int[devices];
            _teleport = new Vector3[devices];
            _disturbed = new bool[devices];
            _lostNow = new bool[devices];
            _maxBurst = Math.Max(1, (int)Math.Round(options.DropoutMaxSeconds * rate));
            // Lost a fraction r of the time with bursts of mean length L (the frame a burst starts on among them): a burst
            // starts, on a frame not already lost, with probability p = r / (L (1 - r) + r), so that the share lost,
            // p L / (p L + 1 - p), is r. (r / (L (1 - r)) left out the start frame: with one-frame bursts at r = 0.5, p was 1
            // and the device was lost on every frame.)
            double meanBurst = (1 + _maxBurst) / 2.0;
            _burstStart = options.DropoutRate / (meanBurst * (1 - options.DropoutRate) + options.DropoutRate);
            _teleportLength = Math.Max(1, (int)Math.Round(options.TeleportSeconds * rate));
            _teleportStart = options.TeleportMetres > 0f ? options.TeleportsPerMinute / (60.0 * rate) : 0;
        }

        /// <summary>True when device <paramref name="device"/> was lost or teleported in the last frame <see cref="Apply"/> changed.</summary>
        public bool IsDisturbed(int device) => _disturbed[device];

        /// <summary>True when device <paramref name="device"/> was lost (not tracked) in the last frame <see cref="Apply"/> changed.</summary>
        public bool IsLost(int device) => _lostNow[device];

        /// <summary>Disturbs one frame's samples in place.</summary>
        public void Apply(SessionFrame frame)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (frame.Samples.Length != _lostNow.Length) throw new ArgumentException($"Expected a frame of {_lostNow.Length} devices.", nameof(frame));
            for (int d = 0; d < frame.Samples.Length; d++)
            {
                _disturbed[d] = false;
                _lostNow[d] = false;
                if (_lostFrames[d] == 0 && _rng.NextDouble() < _burstStart) _lostFrames[d] = 1 + _rng.Next(_maxBurst);
                if (_teleportFrames[d] == 0 && _rng.NextDouble() < _teleportStart)
                {
                    double angle = _rng.NextDouble() * 2 * Math.PI;
                    _teleport[d] = new Vector3((float)Math.Cos(angle), 0f, (float)Math.Sin(angle)) * _options.TeleportMetres;
                    _teleportFrames[d] = _teleportLength;
                }
                DeviceSample s = frame.Samples[d];
                if (_lostFrames[d] > 0)
                {
                    _lostFrames[d]--;
                    frame.Samples[d] = new DeviceSample(s.Pose, false);
                    _disturbed[d] = _lostNow[d] = true;
                    continue;
                }
                if (!s.IsTracked) continue;
                Vector3 p = s.Pose.Position;
                if (_options.NoiseMm > 0f) p += new Vector3(Gaussian(), Gaussian(), Gaussian()) * (_options.NoiseMm / 1000f);
                if (_teleportFrames[d] > 0)
                {
                    _teleportFrames[d]--;
                    p += _teleport[d];
                    _disturbed[d] = true;
                }
                frame.Samples[d] = new DeviceSample(new RigidPose(p, s.Pose.Rotation), true);
            }
        }

        private float Gaussian()
        {
            double u1 = 1.0 - _rng.NextDouble(), u2 = _rng.NextDouble();
            return (float)(Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2.0 * Math.PI * u2));
        }
    }
}
