namespace AvatarGo.Core
{
    /// <summary>The body part a device follows. Identified by calibration, or assigned by the runtime.</summary>
    public enum DeviceRole
    {
        /// <summary>Not known (yet), or a device the body does not use.</summary>
        None = 0,

        /// <summary>The HMD on the head.</summary>
        Head = 1,

        /// <summary>The controller in the left hand.</summary>
        LeftHand = 2,

        /// <summary>The controller in the right hand.</summary>
        RightHand = 3,

        /// <summary>The tracker on the lower back (the avatar's root).</summary>
        Pelvis = 4,

        /// <summary>The tracker on the left foot.</summary>
        LeftFoot = 5,

        /// <summary>The tracker on the right foot.</summary>
        RightFoot = 6,
    }
}
