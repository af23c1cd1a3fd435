using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The One Euro filter (Casiez, Roussel and Vogel, CHI 2012) for device poses: an exponential smoothing whose cutoff
    /// rises with the device's speed, so a still device is steady and a moving one lags little. Positions are filtered
    /// per coordinate with the speed's magnitude driving the cutoff; rotations by spherical interpolation with the angular
    /// speed driving it. One state per device; time-based (frame-rate independent); allocation-free.
    /// </summary>
    public sealed class OneEuroFilter
    {
        private readonly float _minCutoff, _beta, _derivativeCutoff;
        private readonly bool[] _has;
        private readonly RigidPose[] _value;
        private readonly RigidPose[] _raw;          // the last sample as it came: the speeds are measured from it
        private readonly float[] _speed, _angularSpeed;
        private readonly double[] _time;

        /// <summary>
        /// Creates the filter for <paramref name="devices"/> devices: <paramref name="minCutoff"/> (Hz) is the cutoff of a
        /// still device, <paramref name="beta"/> how fast it rises with speed (Hz per m/s, and per rad/s for rotations),
        /// <paramref name="derivativeCutoff"/> (Hz) the cutoff of the speed estimate.
        /// </summary>
        public OneEuroFilter(int devices, float minCutoff, float beta, float derivativeCutoff = 1f)
        {
            if (!(minCutoff > 0f) || float.IsInfinity(minCutoff)) throw new ArgumentOutOfRangeException(nameof(minCutoff), minCutoff, "The cutoff must be a finite number of Hz more than 0.");
            if (!(beta >= 0f) || float.IsInfinity(beta)) throw new ArgumentOutOfRangeException(nameof(beta), beta, "Beta must be a finite number, 0 or more.");
            if (!(derivativeCutoff > 0f) || float.IsInfinity(derivativeCutoff)) throw new ArgumentOutOfRangeException(nameof(derivativeCutoff), derivativeCutoff, "The derivative's cutoff must be a finite number of Hz more than 0.");
            _minCutoff = minCutoff;
            _beta = beta;
            _derivativeCutoff = derivativeCutoff;
            _has = new bool[devices];
            _value = new RigidPose[devices];
            _raw = new RigidPose[devices];
            _speed = new float[devices];
            _angularSpeed = new float[devices];
            _time = new double[devices];
        }

        /// <summary>Forgets a device's history (it was lost: start again from its next sample).</summary>
        public void Reset(int device) => _has[device] = false;

        /// <summary>Filters the tracked samples in place; lost ones reset their device's filter. Allocation-free.</summary>
        public void Apply(double time, Span<DeviceSample> samples)
        {
            for (int d = 0; d < samples.Length; d++)
            {
                if (!samples[d].IsTracked) { _has[d] = false; continue; }
                RigidPose x = samples[d].Pose;
                if (_has[d] && !(time > _time[d]))
                {
                    // No time passed (a repeated frame) or the clock went back (a replay restarted): the filtered pose stays
                    // as it is, and the clock restarts from here. Seeded again from the raw sample, it jumped by the whole lag.
                    _time[d] = time;
                    _raw[d] = x;
                    samples[d] = new DeviceSample(_value[d], true);
                    continue;
                }
                if (!_has[d])
                {
                    _has[d] = true;
                    _value[d] = _raw[d] = x;
                    _speed[d] = _angularSpeed[d] = 0f;
                    _time[d] = time;
                    continue;
                }
                float dt = (float)Math.Min(time - _time[d], 0.25);
                _time[d] = time;
                RigidPose previous = _value[d];
                // The device's speed from its own samples: measured from the filtered pose, it included the filter's lag over
                // one frame, v (1 + tau / dt), so the cutoff, and the lag, changed with the frame rate.
                float speed = Vector3.Distance(x.Position, _raw[d].Position) / dt;
                float angularSpeed = Rotations.AngleDegrees(_raw[d].Rotation, x.Rotation) * Rotations.Deg2Rad / dt;
                _raw[d] = x;
                _speed[d] += Alpha(_derivativeCutoff, dt) * (speed - _speed[d]);
                _angularSpeed[d] += Alpha(_derivativeCutoff, dt) * (angularSpeed - _angularSpeed[d]);
                Vector3 p = Vector3.Lerp(previous.Position, x.Position, Alpha(_minCutoff + _beta * _speed[d], dt));
                Quaternion q = Quaternion.Slerp(previous.Rotation, x.Rotation, Alpha(_minCutoff + _beta * _angularSpeed[d], dt));
                _value[d] = new RigidPose(p, Quaternion.Normalize(q));
                samples[d] = new DeviceSample(_value[d], true);
            }
        }

        // The smoothing factor of an exponential filter with this cutoff over dt: 1 / (1 + tau / dt), tau = 1 / (2 pi cutoff).
        internal static float Alpha(float cutoff, float dt) => 1f / (1f + 1f / (2f * MathF.PI * cutoff * dt));
    }
}
