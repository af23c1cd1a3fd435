namespace AvatarGo.Core
{
    /// <summary>The points of a finger that the finger IK keeps on the controller's surface.</summary>
    public enum FingerPoint
    {
        /// <summary>The intermediate joint.</summary>
        IntermediateJoint = 0,

        /// <summary>The distal joint.</summary>
        DistalJoint = 1,

        /// <summary>The fingertip (the finger's end point).</summary>
        Tip = 2,
    }
}
