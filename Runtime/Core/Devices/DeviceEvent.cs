namespace AvatarGo.Core
{
    /// <summary>A discrete input event (a trigger press or release) from one device.</summary>
    public readonly struct DeviceEvent
    {
        /// <summary>The id of the device the event came from (<see cref="DeviceInfo.Id"/>).</summary>
        public readonly int DeviceId;

        /// <summary>What happened.</summary>
        public readonly DeviceEventKind Kind;

        /// <summary>Creates an event.</summary>
        public DeviceEvent(int deviceId, DeviceEventKind kind)
        {
            DeviceId = deviceId;
            Kind = kind;
        }

        /// <inheritdoc/>
        public override string ToString() => $"{Kind} on device {DeviceId}";
    }
}
