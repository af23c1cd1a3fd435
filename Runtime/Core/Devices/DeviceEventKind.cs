namespace AvatarGo.Core
{
    /// <summary>A discrete input event from a device.</summary>
    public enum DeviceEventKind
    {
        /// <summary>The trigger crossed its press threshold.</summary>
        TriggerPressed = 0,

        /// <summary>The trigger was let go.</summary>
        TriggerReleased = 1,
    }
}
