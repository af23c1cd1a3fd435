using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The default Input System binding paths of each body role's device, the ones the Input System source creates in code
    /// when no action is assigned. The HMD and controller paths are those Unity's XR Interaction Toolkit ships in its default
    /// input actions (the HMD at its centre eye, the controllers at their device pose: the grip pose under OpenXR). The
    /// trackers are bound through the <see cref="ViveTrackerRoles.LayoutName"/> layout and its role usages, which AvatarGo's
    /// OpenXR tracker feature registers (other backends give no tracker to the Input System: see tracking-sources.md).
    /// </summary>
    public static class InputSystemBindings
    {
        /// <summary>The binding of the device's position (a Vector3 control).</summary>
        public static string Position(DeviceRole role) => Device(role) + (IsTracker(role) ? "/" + ViveTrackerRoles.PoseControl + "/position" : role == DeviceRole.Head ? "/centerEyePosition" : "/devicePosition");

        /// <summary>The binding of the device's rotation (a Quaternion control).</summary>
        public static string Rotation(DeviceRole role) => Device(role) + (IsTracker(role) ? "/" + ViveTrackerRoles.PoseControl + "/rotation" : role == DeviceRole.Head ? "/centerEyeRotation" : "/deviceRotation");

        /// <summary>The binding of the device's tracking state (an integer control: <c>InputTrackingState</c> bits).</summary>
        public static string TrackingState(DeviceRole role) => Device(role) + (IsTracker(role) ? "/" + ViveTrackerRoles.PoseControl + "/trackingState" : "/trackingState");

        /// <summary>The binding of a controller's analog trigger (the control with usage Trigger, 0..1).</summary>
        public static string Trigger(BodySide side) => Device(BodyRoles.Hand(side)) + "/{Trigger}";

        /// <summary>The binding of a controller's analog grip (the control with usage Grip, 0..1).</summary>
        public static string Grip(BodySide side) => Device(BodyRoles.Hand(side)) + "/{Grip}";

        /// <summary>The device part of the paths: <c>&lt;XRHMD&gt;</c>, <c>&lt;XRController&gt;{LeftHand}</c>, <c>&lt;XRViveTracker&gt;{Waist}</c>, ...</summary>
        public static string Device(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Head: return "<XRHMD>";
                case DeviceRole.LeftHand: return "<XRController>{LeftHand}";
                case DeviceRole.RightHand: return "<XRController>{RightHand}";
                case DeviceRole.Pelvis:
                case DeviceRole.LeftFoot:
                case DeviceRole.RightFoot:
                    return "<" + ViveTrackerRoles.LayoutName + ">{" + ViveTrackerRoles.Usage(role) + "}";
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "Not a body role.");
            }
        }

        private static bool IsTracker(DeviceRole role) => role == DeviceRole.Pelvis || role == DeviceRole.LeftFoot || role == DeviceRole.RightFoot;
    }
}
