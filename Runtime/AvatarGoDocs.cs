namespace AvatarGo
{
    /// <summary>Where the package's manual lives online: the components' <c>HelpURL</c>s point at their pages under it.</summary>
    internal static class AvatarGoDocs
    {
        /// <summary>The manual's folder (the package's Documentation~ in its repository).</summary>
        public const string Manual = "https://github.com/avatargo/com.avatargo.selfavatar/blob/main/Documentation~/";
    }
}
