namespace AvatarGo.Core
{
    /// <summary>The three joints of a finger, from the hand outward (Unity's Proximal, Intermediate, Distal bones).</summary>
    public enum Phalanx
    {
        /// <summary>The joint at the knuckle (the thumb's at its base).</summary>
        Proximal = 0,

        /// <summary>The middle joint.</summary>
        Intermediate = 1,

        /// <summary>The joint nearest the tip.</summary>
        Distal = 2,
    }
}
