namespace AvatarGo.Core
{
    /// <summary>Options for <see cref="BvhReader"/>.</summary>
    public sealed class BvhReadOptions
    {
        /// <summary>
        /// Factor applied to every length in the file (offsets and position channels) when poses are produced:
        /// 0.01 turns a centimetre file into metres. Default 1 (the file's own units).
        /// See <see cref="BvhClip.GuessMetresPerUnit"/>.
        /// </summary>
        public float Scale { get; set; } = 1f;

        /// <summary>
        /// When true, <see cref="Scale"/> is ignored and chosen by
        /// <see cref="BvhClip.GuessMetresPerUnit"/> so that poses come out in metres.
        /// </summary>
        public bool ToMetres { get; set; }
    }
}
