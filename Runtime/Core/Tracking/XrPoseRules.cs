using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// How a source reads a Unity XR device's pose, decided engine-free: which feature gives the HMD's pose, and when a pose
    /// counts as tracked. The usage names are the native feature names of Unity's <c>UnityEngine.XR.CommonUsages</c>
    /// (UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs).
    /// </summary>
    public static class XrPoseRules
    {
        /// <summary>The native name of <c>CommonUsages.centerEyePosition</c>.</summary>
        public const string CenterEyePosition = "CenterEyePosition";

        /// <summary>The native name of <c>CommonUsages.centerEyeRotation</c>.</summary>
        public const string CenterEyeRotation = "CenterEyeRotation";

        /// <summary><c>InputTrackingState.Position</c>.</summary>
        public const uint TrackingPosition = 1u << 0;

        /// <summary><c>InputTrackingState.Rotation</c>.</summary>
        public const uint TrackingRotation = 1u << 1;

        /// <summary>
        /// True when the HMD's pose is read from the centre eye (<c>centerEyePosition</c>/<c>centerEyeRotation</c>) instead
        /// of <c>devicePosition</c>/<c>deviceRotation</c>: for an HMD that reports both centre-eye features. The centre eye
        /// is where the XR camera renders from (Unity's Tracked Pose Driver and the XR Interaction Toolkit bind the HMD's
        /// <c>centerEyePosition</c>), so the avatar's head is calibrated against the viewpoint the wearer sees and the same
        /// point as the transform and Input System sources give (a runtime may put <c>devicePosition</c> elsewhere on the
        /// headset). Decided once, when the device connects, so a session never mixes the two. Controllers and trackers
        /// always use the device pose (under OpenXR a controller's device pose is its grip pose).
        /// </summary>
        public static bool UsesCenterEye(DeviceClass deviceClass, IReadOnlyList<string> usageNames)
        {
            if (deviceClass != DeviceClass.Hmd || usageNames == null) return false;
            bool position = false, rotation = false;
            for (int i = 0; i < usageNames.Count; i++)
            {
                position |= usageNames[i] == CenterEyePosition;
                rotation |= usageNames[i] == CenterEyeRotation;
            }
            return position && rotation;
        }

        /// <summary>
        /// True when a pose counts as tracked: both its position and its rotation were read, and every tracking flag the
        /// device reports agrees (<c>isTracked</c> true; <c>trackingState</c> with both the position and rotation bits).
        /// A flag the device does not report (the read failed) does not count against it.
        /// </summary>
        public static bool IsTracked(bool gotPosition, bool gotRotation, bool reportsIsTracked, bool isTracked, bool reportsTrackingState, uint trackingState)
        {
            if (!gotPosition || !gotRotation) return false;
            if (reportsIsTracked && !isTracked) return false;
            const uint both = TrackingPosition | TrackingRotation;
            return !reportsTrackingState || (trackingState & both) == both;
        }
    }
}
