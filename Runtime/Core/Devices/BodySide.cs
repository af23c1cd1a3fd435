namespace AvatarGo.Core
{
    /// <summary>A side of the body: which hand, foot, arm or leg.</summary>
    public enum BodySide
    {
        /// <summary>The wearer's left.</summary>
        Left = 0,

        /// <summary>The wearer's right.</summary>
        Right = 1,
    }
}
