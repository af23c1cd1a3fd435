using System;

namespace AvatarGo.Core
{
    /// <summary>One tracked device: a stable id, its class, its serial and the role the runtime assigned, if any.</summary>
    public sealed class DeviceInfo
    {
        /// <summary>Creates a device description.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="id"/> is negative.</exception>
        public DeviceInfo(int id, DeviceClass deviceClass, string serial, DeviceRole runtimeRole = DeviceRole.None)
        {
            if (id < 0) throw new ArgumentOutOfRangeException(nameof(id), id, "Device ids are non-negative.");
            Id = id;
            Class = deviceClass;
            Serial = serial ?? string.Empty;
            RuntimeRole = runtimeRole;
        }

        /// <summary>
        /// A stable id, unique within a session: what trigger events (<see cref="DeviceEvent.DeviceId"/>) and the session
        /// format name the device by. Not necessarily its index in the device list, which per-frame arrays follow
        /// (<see cref="SessionHeader.IndexOf"/> finds it).
        /// </summary>
        public int Id { get; }

        /// <summary>HMD, controller or tracker.</summary>
        public DeviceClass Class { get; }

        /// <summary>The hardware serial number, used to recognise the same devices in a later session.</summary>
        public string Serial { get; }

        /// <summary>The role the XR runtime assigned (for example an OpenXR VIVE tracker role), or <see cref="DeviceRole.None"/>.</summary>
        public DeviceRole RuntimeRole { get; }

        /// <inheritdoc/>
        public override string ToString() => $"{Class} #{Id} ({Serial}{(RuntimeRole != DeviceRole.None ? ", runtime role " + RuntimeRole : "")})";
    }
}
