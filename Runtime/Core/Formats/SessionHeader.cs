using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// The header of a session (format v1, see Documentation~/session-format.md): nominal rate, devices and,
    /// for synthetic sessions, the ground truth that does not change over time (each device's true role and
    /// the wearer's skeleton with its humanoid map).
    /// </summary>
    public sealed class SessionHeader
    {
        private readonly DeviceInfo[] _devices;
        private readonly DeviceRole[] _trueRoles;
        private readonly Dictionary<int, int> _indexById = new Dictionary<int, int>();

        /// <summary>Creates a header.</summary>
        /// <param name="rate">Nominal frame rate in Hz (<see cref="SessionLimits.MinRate"/> to <see cref="SessionLimits.MaxRate"/>).</param>
        /// <param name="devices">The devices, ids unique and non-negative, at most <see cref="SessionLimits.MaxDevices"/>.</param>
        /// <param name="trueRoles">Synthetic sessions: the true role of each device, in device order; or null.</param>
        /// <param name="truthHumanoid">Synthetic sessions: the wearer's skeleton (at most <see cref="SessionLimits.MaxTruthJoints"/> joints) and humanoid map; or null.</param>
        /// <exception cref="ArgumentException">Ids repeat or are negative, counts differ or exceed the format's limits, or the rate is out of range.</exception>
        public SessionHeader(float rate, IReadOnlyList<DeviceInfo> devices, IReadOnlyList<DeviceRole> trueRoles = null, HumanoidMap truthHumanoid = null)
        {
            if (!(rate >= SessionLimits.MinRate && rate <= SessionLimits.MaxRate))
                throw new ArgumentOutOfRangeException(nameof(rate), rate, $"The rate must be from {SessionLimits.MinRate} to {SessionLimits.MaxRate} Hz.");
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            if (devices.Count > SessionLimits.MaxDevices) throw new ArgumentException($"{devices.Count} devices; a session has at most {SessionLimits.MaxDevices}.", nameof(devices));
            if (truthHumanoid != null && truthHumanoid.Skeleton.JointCount > SessionLimits.MaxTruthJoints)
                throw new ArgumentException($"The ground-truth skeleton has {truthHumanoid.Skeleton.JointCount} joints; a session holds at most {SessionLimits.MaxTruthJoints}.", nameof(truthHumanoid));
            if (trueRoles != null && trueRoles.Count != devices.Count) throw new ArgumentException("One true role per device.", nameof(trueRoles));
            Rate = rate;
            _devices = new DeviceInfo[devices.Count];
            for (int i = 0; i < _devices.Length; i++)
            {
                _devices[i] = devices[i] ?? throw new ArgumentException($"Device {i} is null.", nameof(devices));
                if (_devices[i].Id < 0) throw new ArgumentException($"Device id {_devices[i].Id} is negative.", nameof(devices));
                if (_indexById.ContainsKey(_devices[i].Id)) throw new ArgumentException($"Device id {_devices[i].Id} is used twice.", nameof(devices));
                _indexById.Add(_devices[i].Id, i);
            }
            if (trueRoles != null)
            {
                _trueRoles = new DeviceRole[trueRoles.Count];
                for (int i = 0; i < _trueRoles.Length; i++) _trueRoles[i] = trueRoles[i];
            }
            TruthHumanoid = truthHumanoid;
        }

        /// <summary>The format version this library writes.</summary>
        public static readonly Version FormatVersion = new Version(1, 0);

        /// <summary>The nominal frame rate, in Hz.</summary>
        public float Rate { get; }

        /// <summary>The devices, in file order; frames index device samples in this order.</summary>
        public IReadOnlyList<DeviceInfo> Devices => _devices;

        /// <summary>True for a synthetic session that records each device's true role.</summary>
        public bool HasTrueRoles => _trueRoles != null;

        /// <summary>The true role of the device at <paramref name="deviceIndex"/> (synthetic sessions), else <see cref="DeviceRole.None"/>.</summary>
        public DeviceRole TrueRole(int deviceIndex) => _trueRoles == null ? DeviceRole.None : _trueRoles[deviceIndex];

        /// <summary>Synthetic sessions: the wearer's skeleton (rest pose = the wearer's proportions) and humanoid map; else null.</summary>
        public HumanoidMap TruthHumanoid { get; }

        /// <summary>The position of the device with this id in <see cref="Devices"/>, or -1.</summary>
        public int IndexOf(int deviceId) => _indexById.TryGetValue(deviceId, out int i) ? i : -1;
    }
}
