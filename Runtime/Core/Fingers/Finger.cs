namespace AvatarGo.Core
{
    /// <summary>The five fingers of a hand, thumb first (the order of Unity's humanoid finger bones).</summary>
    public enum Finger
    {
        /// <summary>The thumb.</summary>
        Thumb = 0,

        /// <summary>The index finger.</summary>
        Index = 1,

        /// <summary>The middle finger.</summary>
        Middle = 2,

        /// <summary>The ring finger.</summary>
        Ring = 3,

        /// <summary>The little finger.</summary>
        Little = 4,
    }
}
