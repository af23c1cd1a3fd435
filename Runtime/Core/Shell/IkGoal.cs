namespace AvatarGo.Core
{
    /// <summary>The four limb goals of a humanoid IK pass, with the same values as Unity's <c>AvatarIKGoal</c>.</summary>
    public enum IkGoal
    {
        /// <summary>The left ankle.</summary>
        LeftFoot = 0,

        /// <summary>The right ankle.</summary>
        RightFoot = 1,

        /// <summary>The left wrist.</summary>
        LeftHand = 2,

        /// <summary>The right wrist.</summary>
        RightHand = 3,
    }
}
