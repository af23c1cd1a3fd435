namespace AvatarGo.Core
{
    /// <summary>Why a calibration step was refused. Each has a message a wearer understands (<see cref="CalibrationMessages"/>).</summary>
    public enum CalibrationError
    {
        /// <summary>No error.</summary>
        None = 0,

        /// <summary>Fewer devices than one HMD, two controllers and three trackers are connected.</summary>
        DeviceMissing,

        /// <summary>A required device is connected but not tracked.</summary>
        DeviceNotTracked,

        /// <summary>A device moved during the averaging window.</summary>
        DevicesMoving,

        /// <summary>The controllers are not at shoulder height, or not at the same height.</summary>
        ArmsNotLevel,

        /// <summary>The controllers are too close together for a T-pose.</summary>
        ArmsNotSpread,

        /// <summary>The HMD is tilted: the head is not upright.</summary>
        HeadNotUpright,

        /// <summary>The devices do not lie in a vertical plane facing the way the HMD looks.</summary>
        NotFacingPlane,

        /// <summary>Two devices claim one role (both controllers on one side, both feet on one side, a runtime role twice).</summary>
        RoleConflict,

        /// <summary>The foot trackers are not near the floor.</summary>
        FeetNotOnFloor,

        /// <summary>The pelvis tracker is not between the head and the feet.</summary>
        PelvisNotBetweenHeadAndFeet,

        /// <summary>A runtime-assigned role disagrees with where the device is on the body.</summary>
        RuntimeRoleMismatch,

        /// <summary>The step was asked for in the wrong state (for example offsets before identification).</summary>
        WrongState,

        /// <summary>At the walk-in, the HMD is not where the avatar's eyes are: the wearer has not walked into the avatar.</summary>
        NotInsideAvatar,

        /// <summary>
        /// The avatar's size against the wearer's is beyond what a profile holds (<see cref="CalibrationProfileStore.MinAvatarScale"/>
        /// … <see cref="CalibrationProfileStore.MaxAvatarScale"/>): its units are not a person's (an avatar modelled in
        /// micrometres), or its eye height is wrong.
        /// </summary>
        AvatarScaleOutOfRange,
    }
}
