namespace AvatarGo.Core
{
    /// <summary>
    /// What an XR device is, from the characteristics bits Unity's <c>UnityEngine.XR.InputDevice</c> reports (the values of
    /// <c>InputDeviceCharacteristics</c>, and the tracker-role bits the OpenXR VIVE tracker profiles add above them).
    /// Engine-free, so which device plays which class and runtime role is decided and tested here.
    /// </summary>
    public static class XrDeviceKind
    {
        /// <summary><c>InputDeviceCharacteristics.HeadMounted</c>.</summary>
        public const uint HeadMounted = 1u << 0;
        /// <summary><c>InputDeviceCharacteristics.Camera</c>.</summary>
        public const uint Camera = 1u << 1;
        /// <summary><c>InputDeviceCharacteristics.HeldInHand</c>.</summary>
        public const uint HeldInHand = 1u << 2;
        /// <summary><c>InputDeviceCharacteristics.HandTracking</c>.</summary>
        public const uint HandTracking = 1u << 3;
        /// <summary><c>InputDeviceCharacteristics.EyeTracking</c>.</summary>
        public const uint EyeTracking = 1u << 4;
        /// <summary><c>InputDeviceCharacteristics.TrackedDevice</c>.</summary>
        public const uint TrackedDevice = 1u << 5;
        /// <summary><c>InputDeviceCharacteristics.Controller</c>.</summary>
        public const uint Controller = 1u << 6;
        /// <summary><c>InputDeviceCharacteristics.TrackingReference</c> (a base station).</summary>
        public const uint TrackingReference = 1u << 7;
        /// <summary><c>InputDeviceCharacteristics.Left</c>.</summary>
        public const uint Left = 1u << 8;
        /// <summary><c>InputDeviceCharacteristics.Right</c>.</summary>
        public const uint Right = 1u << 9;

        /// <summary>The VIVE tracker profiles' left-foot role bit (<c>/user/vive_tracker_htcx/role/left_foot</c>).</summary>
        public const uint TrackerLeftFoot = 0x1000;
        /// <summary>The right-foot role bit.</summary>
        public const uint TrackerRightFoot = 0x2000;
        /// <summary>The waist role bit.</summary>
        public const uint TrackerWaist = 0x100000;
        /// <summary>Every other role bit of the profiles (shoulders, elbows, knees, chest, camera, keyboard): trackers the body does not use.</summary>
        public const uint TrackerOtherRoles = 0x4000 | 0x8000 | 0x10000 | 0x20000 | 0x40000 | 0x80000 | 0x200000 | 0x400000 | 0x800000;

        /// <summary>
        /// The class and runtime role of a device with these characteristics, or false for a device the body does not use
        /// (base stations, hand- or eye-tracking devices, cameras, trackers the runtime gave another body role). Controllers
        /// get no runtime role: which hand holds which comes from the T-pose (two wands look the same to the runtime).
        /// </summary>
        public static bool TryClassify(uint characteristics, out DeviceClass deviceClass, out DeviceRole runtimeRole)
        {
            deviceClass = DeviceClass.Tracker;
            runtimeRole = DeviceRole.None;
            bool has(uint bit) => (characteristics & bit) != 0;
            if (has(TrackingReference) || has(TrackerOtherRoles)) return false;
            // Before the head test: Unity's OpenXR eye-gaze device is HeadMounted | EyeTracking | TrackedDevice
            // (com.unity.xr.openxr EyeGazeInteraction), and it is no HMD.
            if (has(EyeTracking)) return false;
            if (has(HeadMounted))
            {
                deviceClass = DeviceClass.Hmd;
                return true;
            }
            // Before the controller test: Unity OpenXR's hand interaction profiles (Microsoft Hand Interaction, Palm Pose,
            // Hand Common Poses) report tracked hands as HandTracking | HeldInHand | Controller | TrackedDevice: no
            // controllers (a wearer who put the controllers down would have had four).
            if (has(HandTracking)) return false;
            if (has(HeldInHand) && has(Controller))
            {
                deviceClass = DeviceClass.Controller;
                return true;
            }
            if (has(Camera) || !has(TrackedDevice)) return false;
            runtimeRole = has(TrackerWaist) ? DeviceRole.Pelvis : has(TrackerLeftFoot) ? DeviceRole.LeftFoot : has(TrackerRightFoot) ? DeviceRole.RightFoot : DeviceRole.None;
            return true;
        }
    }
}
