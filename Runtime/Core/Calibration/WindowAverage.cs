namespace AvatarGo.Core
{
    /// <summary>One device averaged over the calibration window (<see cref="SampleWindow.Average"/>).</summary>
    public readonly struct WindowAverage
    {
        /// <summary>The mean pose of the tracked samples (position mean, sign-aligned quaternion mean); identity without samples.</summary>
        public readonly RigidPose Mean;

        /// <summary>The share of the window's frames in which the device was tracked with a valid pose, 0 to 1.</summary>
        public readonly float TrackedFraction;

        /// <summary>True when every tracked sample lies within the stillness bounds of <see cref="Mean"/>.</summary>
        public readonly bool IsStill;

        /// <summary>Creates an average.</summary>
        public WindowAverage(RigidPose mean, float trackedFraction, bool isStill)
        {
            Mean = mean;
            TrackedFraction = trackedFraction;
            IsStill = isStill;
        }

        /// <summary>True when the device was tracked in at least <see cref="SampleWindow.MinTrackedFraction"/> of the window.</summary>
        public bool IsTracked => TrackedFraction >= SampleWindow.MinTrackedFraction;

        /// <summary>The mean position.</summary>
        public System.Numerics.Vector3 Position => Mean.Position;
    }
}
