namespace AvatarGo.Core
{
    /// <summary>
    /// What an XR runtime says about one device when it connects, engine-free: the characteristics bits of Unity's
    /// <c>UnityEngine.XR.InputDevice.characteristics</c> (with any tracker-role bits above them), its <c>name</c> and its
    /// <c>serialNumber</c> (empty under OpenXR, which reports none).
    /// </summary>
    public readonly struct XrDeviceReport
    {
        /// <summary>The characteristics bits (<see cref="XrDeviceKind"/>).</summary>
        public readonly uint Characteristics;

        /// <summary>The device's name as the runtime gives it (never null).</summary>
        public readonly string Name;

        /// <summary>The hardware serial number, or empty when the runtime gives none (never null).</summary>
        public readonly string Serial;

        /// <summary>Creates a report; null strings become empty.</summary>
        public XrDeviceReport(uint characteristics, string name, string serial)
        {
            Characteristics = characteristics;
            Name = name ?? string.Empty;
            Serial = serial ?? string.Empty;
        }

        /// <inheritdoc/>
        public override string ToString() => $"{Name} (0x{Characteristics:x}{(Serial.Length > 0 ? ", " + Serial : "")})";
    }
}
