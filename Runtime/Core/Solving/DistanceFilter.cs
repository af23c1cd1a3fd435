using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// A One Euro filter (Casiez et al. 2012) on one distance: an exponential filter whose cutoff rises with the distance's
    /// speed (<see cref="SpeedGain"/> Hz per m/s), so a still distance is steadied and a changing one lags little. The
    /// solver's straight limbs (<see cref="LimbReachFilter"/>) and the back's hips-to-head chord use it. Time-based
    /// (frame-rate independent); allocation-free.
    /// </summary>
    internal sealed class DistanceFilter
    {
        /// <summary>How fast the cutoff rises with the distance's speed: Hz per m/s (the One Euro filter's beta).</summary>
        private const float SpeedGain = 20f;

        /// <summary>The cutoff of the speed estimate (Hz).</summary>
        private const float SpeedCutoffHz = 1f;

        /// <summary>The longest time one step filters over (s): a longer pause is filtered as if it were that long.</summary>
        private const float MaxStepSeconds = 0.25f;

        private bool _has;
        private float _value, _raw, _speed;

        /// <summary>Forgets the history (the distance's end was lost, or the solve starts over): the next distance is taken as it is.</summary>
        public void Reset() => _has = false;

        /// <summary>
        /// The filtered distance, this frame <paramref name="deltaSeconds"/> after the previous one (0: a repeated frame,
        /// which filters nothing) with cutoff <paramref name="cutoffHz"/> for a still distance. A distance that is not finite
        /// and 0 or more is returned as it is and leaves the history alone.
        /// </summary>
        public float Filter(float distance, float deltaSeconds, float cutoffHz)
        {
            if (!(distance >= 0f && distance < float.PositiveInfinity)) return distance;
            if (!_has)
            {
                _has = true;
                _value = _raw = distance;
                _speed = 0f;
                return distance;
            }
            if (deltaSeconds > 0f && deltaSeconds < float.PositiveInfinity)
            {
                float dt = Math.Min(deltaSeconds, MaxStepSeconds);
                float speed = Math.Abs(distance - _raw) / dt;
                _speed += OneEuroFilter.Alpha(SpeedCutoffHz, dt) * (speed - _speed);
                _value += OneEuroFilter.Alpha(cutoffHz + SpeedGain * _speed, dt) * (distance - _value);
            }
            _raw = distance;
            return _value;
        }
    }
}
