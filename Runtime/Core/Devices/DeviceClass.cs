namespace AvatarGo.Core
{
    /// <summary>The kind of a tracked device, as the XR runtime reports it.</summary>
    public enum DeviceClass
    {
        /// <summary>The head-mounted display.</summary>
        Hmd = 0,

        /// <summary>A hand-held controller.</summary>
        Controller = 1,

        /// <summary>A body-worn tracker (VIVE Tracker or similar).</summary>
        Tracker = 2,
    }
}
