namespace AvatarGo.Simulation
{
    /// <summary>What <see cref="SessionDisturber"/> does to a session: bursty device losses, extra noise, teleports.</summary>
    public sealed class DisturbanceOptions
    {
        /// <summary>The share of frames each device is lost, 0 to 0.9 (0.05: 5 %).</summary>
        public float DropoutRate { get; set; }

        /// <summary>The longest burst of lost frames, in seconds (1); each burst lasts a uniform 1 frame to this long.</summary>
        public float DropoutMaxSeconds { get; set; } = 1f;

        /// <summary>Extra position noise, standard deviation per coordinate, in millimetres (0).</summary>
        public float NoiseMm { get; set; }

        /// <summary>How far a teleport moves a device, in metres (0: no teleports).</summary>
        public float TeleportMetres { get; set; }

        /// <summary>Teleports per device per minute (1).</summary>
        public float TeleportsPerMinute { get; set; } = 1f;

        /// <summary>How long a teleported device stays away, in seconds (0.1): a tracking glitch.</summary>
        public float TeleportSeconds { get; set; } = 0.1f;

        /// <summary>The random seed (1).</summary>
        public int Seed { get; set; } = 1;

        /// <summary>True when the options change anything.</summary>
        public bool IsActive => DropoutRate > 0f || NoiseMm > 0f || TeleportMetres > 0f;
    }
}
