namespace AvatarGo.Core
{
    /// <summary>The four bend hints of a humanoid IK pass, with the same values as Unity's <c>AvatarIKHint</c>.</summary>
    public enum IkHint
    {
        /// <summary>The left knee.</summary>
        LeftKnee = 0,

        /// <summary>The right knee.</summary>
        RightKnee = 1,

        /// <summary>The left elbow.</summary>
        LeftElbow = 2,

        /// <summary>The right elbow.</summary>
        RightElbow = 3,
    }
}
