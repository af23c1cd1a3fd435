namespace AvatarGo.Core
{
    /// <summary>A device's state in one frame: its pose and whether the runtime is tracking it.</summary>
    public readonly struct DeviceSample
    {
        /// <summary>The device pose in tracking space (Unity's frame). Meaningful only when <see cref="IsTracked"/>.</summary>
        public readonly RigidPose Pose;

        /// <summary>True when the runtime reports the pose as tracked.</summary>
        public readonly bool IsTracked;

        /// <summary>Creates a sample.</summary>
        public DeviceSample(RigidPose pose, bool isTracked)
        {
            Pose = pose;
            IsTracked = isTracked;
        }

        /// <summary>A tracked sample whose pose is finite and whose rotation is a unit quaternion.</summary>
        public bool IsUsable => IsTracked && Pose.IsValid;

        /// <summary>An untracked sample.</summary>
        public static DeviceSample Lost => new DeviceSample(RigidPose.Identity, false);
    }
}
