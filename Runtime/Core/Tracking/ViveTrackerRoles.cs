using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The facts of the OpenXR extension <c>XR_HTCX_vive_tracker_interaction</c> (VIVE Trackers under OpenXR, roles
    /// assigned in SteamVR's "Manage Trackers") that AvatarGo's OpenXR feature declares and its sources read: the interaction
    /// profile, the role user paths of the three body trackers, the characteristics bit each role's device carries (the
    /// community tracker profiles' values, which <see cref="XrDeviceKind"/> reads), and the Input System usage the
    /// feature's device layout gives each role (what <see cref="InputSystemBindings"/> binds).
    /// Path names from the extension's specification (as listed by the OpenXR runtimes that implement it).
    /// </summary>
    public static class ViveTrackerRoles
    {
        /// <summary>The OpenXR extension name.</summary>
        public const string Extension = "XR_HTCX_vive_tracker_interaction";

        /// <summary>The extension's interaction profile path.</summary>
        public const string InteractionProfile = "/interaction_profiles/htc/vive_tracker_htcx";

        /// <summary>The tracker's pose input (the only input AvatarGo binds).</summary>
        public const string GripPose = "/input/grip/pose";

        /// <summary>What every role user path starts with.</summary>
        public const string RolePathPrefix = "/user/vive_tracker_htcx/role/";

        /// <summary>The device name (Unity's <c>InputDevice.name</c>, the Input System's product) AvatarGo's feature gives its trackers.</summary>
        public const string DeviceName = "AvatarGo VIVE Tracker OpenXR";

        /// <summary>The Input System layout AvatarGo's feature registers for them.</summary>
        public const string LayoutName = "XRViveTracker";

        /// <summary>The name of the layout's pose control (the action's name in the action map).</summary>
        public const string PoseControl = "devicePose";

        /// <summary>The Input System usage of the waist (pelvis) tracker.</summary>
        public const string WaistUsage = "Waist";

        /// <summary>The Input System usage of the left foot tracker.</summary>
        public const string LeftFootUsage = "LeftFoot";

        /// <summary>The Input System usage of the right foot tracker.</summary>
        public const string RightFootUsage = "RightFoot";

        /// <summary>The body roles a tracker can have, in the order the feature declares them.</summary>
        public static readonly DeviceRole[] Roles = { DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot };

        /// <summary>The user path of a body role (<c>/user/vive_tracker_htcx/role/waist</c>, <c>left_foot</c>, <c>right_foot</c>).</summary>
        public static string RolePath(DeviceRole role) => RolePathPrefix + RoleName(role);

        /// <summary>The role's name in its path: <c>waist</c>, <c>left_foot</c>, <c>right_foot</c>.</summary>
        public static string RoleName(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Pelvis: return "waist";
                case DeviceRole.LeftFoot: return "left_foot";
                case DeviceRole.RightFoot: return "right_foot";
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "Not a tracker role.");
            }
        }

        /// <summary>The characteristics bit a role's device carries besides <c>TrackedDevice</c>.</summary>
        public static uint RoleBit(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Pelvis: return XrDeviceKind.TrackerWaist;
                case DeviceRole.LeftFoot: return XrDeviceKind.TrackerLeftFoot;
                case DeviceRole.RightFoot: return XrDeviceKind.TrackerRightFoot;
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "Not a tracker role.");
            }
        }

        /// <summary>The full characteristics of a role's device: <c>TrackedDevice</c> and its role bit.</summary>
        public static uint Characteristics(DeviceRole role) => XrDeviceKind.TrackedDevice | RoleBit(role);

        /// <summary>The Input System usage the layout gives a role's device, for bindings such as <c>&lt;XRViveTracker&gt;{Waist}</c>.</summary>
        public static string Usage(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Pelvis: return WaistUsage;
                case DeviceRole.LeftFoot: return LeftFootUsage;
                case DeviceRole.RightFoot: return RightFootUsage;
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "Not a tracker role.");
            }
        }

        /// <summary>The usage of a device with these characteristics (from its role bit), or null for none of the three roles.</summary>
        public static string UsageOf(uint characteristics)
        {
            if (!XrDeviceKind.TryClassify(characteristics, out DeviceClass cls, out DeviceRole role) || cls != DeviceClass.Tracker || role == DeviceRole.None) return null;
            return Usage(role);
        }
    }
}
