namespace AvatarGo.Core
{
    /// <summary>How much a <see cref="SetupFinding"/> matters.</summary>
    public enum SetupSeverity
    {
        /// <summary>Worth knowing; everything works.</summary>
        Info,
        /// <summary>It works, but not as well as it could (no finger IK on a hand, an odd scale).</summary>
        Warning,
        /// <summary>It cannot work until this is fixed; the components disable themselves.</summary>
        Error,
    }
}
