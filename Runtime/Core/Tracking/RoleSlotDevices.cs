using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The device list of a source that reads one device per body role (Input System actions, SteamVR input sources, plain
    /// transforms): six devices in <see cref="BodyRoles.All"/> order, id = index, the HMD and the controllers without a
    /// runtime role (which hand holds which is the T-pose's to say), the trackers with the role their binding gives (the
    /// calibration checks it against the plane fit). A serial learned later (SteamVR reports one once a device is bound)
    /// gives a new header; nothing else changes it.
    /// </summary>
    public sealed class RoleSlotDevices
    {
        private readonly float _rate;
        private readonly string[] _serials = new string[BodyRoles.Count];

        /// <summary>Creates the list, every serial empty.</summary>
        public RoleSlotDevices(float rate = 90f)
        {
            if (!(rate > 0f) || float.IsInfinity(rate)) throw new ArgumentOutOfRangeException(nameof(rate), rate, "The rate must be positive.");
            _rate = rate;
            for (int i = 0; i < _serials.Length; i++) _serials[i] = string.Empty;
            Header = Build();
        }

        /// <summary>The six devices.</summary>
        public SessionHeader Header { get; private set; }

        /// <summary>Incremented whenever <see cref="Header"/> is replaced.</summary>
        public int Version { get; private set; }

        /// <summary>The device of a role.</summary>
        public static DeviceInfo Create(DeviceRole role, string serial)
        {
            int index = BodyRoles.IndexOf(role);
            switch (role)
            {
                case DeviceRole.Head: return new DeviceInfo(index, DeviceClass.Hmd, serial);
                case DeviceRole.LeftHand:
                case DeviceRole.RightHand:
                    return new DeviceInfo(index, DeviceClass.Controller, serial);
                default: return new DeviceInfo(index, DeviceClass.Tracker, serial, role);
            }
        }

        /// <summary>Sets a role's serial (null: none); true, with a new <see cref="Header"/>, when it changed.</summary>
        public bool SetSerial(DeviceRole role, string serial)
        {
            serial ??= string.Empty;
            int i = BodyRoles.IndexOf(role);
            if (_serials[i] == serial) return false;
            _serials[i] = serial;
            Header = Build();
            Version++;
            return true;
        }

        private SessionHeader Build()
        {
            var devices = new DeviceInfo[BodyRoles.Count];
            for (int i = 0; i < devices.Length; i++) devices[i] = Create(BodyRoles.All[i], _serials[i]);
            return new SessionHeader(_rate, devices);
        }
    }
}
