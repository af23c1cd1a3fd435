using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The pipeline's gate for device samples: per device and frame, a sample is accepted only when it is tracked, finite,
    /// has a unit quaternion, moved no faster than a human can move it since the device's last accepted sample, and (for
    /// the body's devices other than the HMD) lies within reach of the HMD. Anything else is treated as lost tracking. A
    /// device rejected for a jump is taken back once its samples agree with each other at the new place for
    /// <see cref="TrackingSettings.ReacquireSeconds"/>. Allocation-free per frame.
    /// </summary>
    public sealed class SampleSanitizer
    {
        private readonly TrackingSettings _settings;
        private readonly int _hmd;
        private readonly float[] _reach;            // per device: the largest plausible distance from the HMD, or +∞
        private readonly bool[] _hasLast;
        private readonly RigidPose[] _last;
        private readonly double[] _lastTime;
        private readonly bool[] _hasCandidate;
        private readonly RigidPose[] _candidate;
        private readonly double[] _candidateTime, _candidateSince;
        private double _minimumInterval;            // this frame's: the shortest interval a device's motion is measured over

        /// <summary>
        /// Creates the gate for <paramref name="deviceCount"/> devices. <paramref name="hmd"/> is the HMD's device index; a
        /// device's reach from it is <paramref name="reachAtCalibration"/>[device] (the distance at the walk-in; NaN or
        /// negative: not checked) times <see cref="TrackingSettings.BodyReachFactor"/> plus the margin.
        /// </summary>
        public SampleSanitizer(int deviceCount, int hmd, ReadOnlySpan<float> reachAtCalibration, TrackingSettings settings)
        {
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            if (reachAtCalibration.Length != deviceCount) throw new ArgumentException("One reach per device.", nameof(reachAtCalibration));
            _hmd = hmd;
            _reach = new float[deviceCount];
            for (int d = 0; d < deviceCount; d++)
                _reach[d] = d != hmd && reachAtCalibration[d] >= 0f ? reachAtCalibration[d] * settings.BodyReachFactor + settings.BodyReachMargin : float.PositiveInfinity;
            _hasLast = new bool[deviceCount];
            _last = new RigidPose[deviceCount];
            _lastTime = new double[deviceCount];
            _hasCandidate = new bool[deviceCount];
            _candidate = new RigidPose[deviceCount];
            _candidateTime = new double[deviceCount];
            _candidateSince = new double[deviceCount];
        }

        /// <summary>Forgets every device's history (after a calibration or a reset of the tracking space).</summary>
        public void Clear()
        {
            Array.Clear(_hasLast, 0, _hasLast.Length);
            Array.Clear(_hasCandidate, 0, _hasCandidate.Length);
        }

        /// <summary>
        /// Writes every sample of <paramref name="samples"/> to <paramref name="accepted"/>, replaced by a lost one where it
        /// is rejected. Returns the number of samples rejected that claimed to be tracked. Allocation-free.
        /// <paramref name="time"/> (seconds) must not go back and should advance by frame-sized steps: the speeds and
        /// durations are measured between calls. <see cref="SelfAvatarPipeline"/> passes its own clock, which does that
        /// whatever the frames' times do.
        /// </summary>
        public int Filter(double time, ReadOnlySpan<DeviceSample> samples, Span<DeviceSample> accepted) => Filter(time, 0.0, samples, accepted);

        /// <summary>
        /// As <see cref="Filter(double, ReadOnlySpan{DeviceSample}, Span{DeviceSample})"/>, with every interval since a device's
        /// last accepted sample counted as at least <paramref name="frameSeconds"/> (the frames' regular step): a frame whose
        /// time did not advance (a repeated or slightly early timestamp) still carries one frame's motion, which a wearer
        /// walking at 2.5 m/s makes 2.8 cm long at 90 Hz (found in review: without it such frames froze the avatar).
        /// </summary>
        public int Filter(double time, double frameSeconds, ReadOnlySpan<DeviceSample> samples, Span<DeviceSample> accepted)
        {
            _minimumInterval = frameSeconds > 0.0 && frameSeconds < double.PositiveInfinity ? frameSeconds : 0.0;
            if (samples.Length != _reach.Length || accepted.Length != _reach.Length) throw new ArgumentException($"Expected {_reach.Length} samples.");
            int rejected = 0;
            // The HMD first: the others' reach is measured from it.
            bool hmdOk = _hmd >= 0 && Gate(_hmd, time, samples[_hmd]);
            for (int d = 0; d < samples.Length; d++)
            {
                bool ok = d == _hmd ? hmdOk : Gate(d, time, samples[d]);
                if (ok && d != _hmd && !float.IsPositiveInfinity(_reach[d]))
                    ok = hmdOk && Vector3.Distance(samples[d].Pose.Position, samples[_hmd].Pose.Position) <= _reach[d];
                if (ok)
                {
                    _hasLast[d] = true;
                    _last[d] = samples[d].Pose;
                    _lastTime[d] = time;
                    _hasCandidate[d] = false;
                    accepted[d] = samples[d];
                }
                else
                {
                    if (samples[d].IsTracked) rejected++;
                    accepted[d] = new DeviceSample(_hasLast[d] ? _last[d] : RigidPose.Identity, false);
                }
            }
            return rejected;
        }

        // Valid, and not faster than a human since the last accepted sample (or agreeing long enough at a new place).
        private bool Gate(int d, double time, DeviceSample s)
        {
            if (!s.IsUsable) return false;
            if (!_hasLast[d] || !IsJump(_last[d], _lastTime[d], s.Pose, time)) return true;
            // A jump: a glitch, unless the device stays at the new place.
            if (_hasCandidate[d] && !IsJump(_candidate[d], _candidateTime[d], s.Pose, time))
            {
                _candidate[d] = s.Pose;
                _candidateTime[d] = time;
                return time - _candidateSince[d] >= _settings.ReacquireSeconds;
            }
            _hasCandidate[d] = true;
            _candidate[d] = s.Pose;
            _candidateTime[d] = _candidateSince[d] = time;
            return false;
        }

        // What a sample may move beyond the speed limits, whatever the time since the last one: the devices' noise (about a
        // millimetre and a tenth of a degree) many times over, so that a sample with the same timestamp is no jump for it.
        // A fixed allowance, not a time: a frame's worth of time (1/90 s) raised the limits by half at 90 Hz and by 160 % at 144 Hz.
        private const float PositionSlackMetres = 0.02f;
        private const float AngleSlackDegrees = 3f;

        private bool IsJump(RigidPose from, double fromTime, RigidPose to, double toTime)
        {
            double elapsed = Math.Max(toTime - fromTime, _minimumInterval);
            return Vector3.Distance(from.Position, to.Position) > _settings.MaxSpeed * elapsed + PositionSlackMetres
                || Rotations.AngleDegrees(from.Rotation, to.Rotation) > _settings.MaxAngularSpeedDegrees * elapsed + AngleSlackDegrees;
        }
    }
}
