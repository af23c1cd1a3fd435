using AvatarGo.Core;
using UnityEngine.InputSystem.Layouts;
using UnityEngine.InputSystem.XR;
using UnityEngine.Scripting;
using UnityEngine.XR.OpenXR.Input;

// OpenXR's PoseControl is marked obsolete (a warning) when a project defines USE_INPUT_SYSTEM_POSE_CONTROL; this layout
// keeps it, as its state layout is the one the plug-in writes for a pose action either way.
#pragma warning disable CS0618

namespace AvatarGo
{
    /// <summary>
    /// The Input System device of a VIVE Tracker that <see cref="ViveTrackerFeature"/> declares: one pose control at the start
    /// of the device's state (its only action, as Unity's own single-pose profiles lay it out), and the usage of its body
    /// role (<c>Waist</c>, <c>LeftFoot</c>, <c>RightFoot</c>) from the role bit of its characteristics, so a binding picks a
    /// role: <c>&lt;XRViveTracker&gt;{Waist}/devicePose/position</c>.
    /// </summary>
    [Preserve, InputControlLayout(displayName = "VIVE Tracker (OpenXR, AvatarGo)",
        commonUsages = new[] { ViveTrackerRoles.WaistUsage, ViveTrackerRoles.LeftFootUsage, ViveTrackerRoles.RightFootUsage })]
    public class XRViveTracker : OpenXRDevice
    {
        /// <summary>The tracker's pose (<c>/input/grip/pose</c>): isTracked, trackingState, position, rotation, velocities.</summary>
        [Preserve, InputControl(offset = 0, usage = "Device")]
        public PoseControl devicePose { get; private set; }

        /// <summary>Finds the pose control and gives the device its role's usage.</summary>
        protected override void FinishSetup()
        {
            base.FinishSetup();
            devicePose = GetChildControl<PoseControl>(ViveTrackerRoles.PoseControl);
            XRDeviceDescriptor descriptor = XRDeviceDescriptor.FromJson(description.capabilities);
            string usage = descriptor == null ? null : ViveTrackerRoles.UsageOf((uint)descriptor.characteristics);
            if (usage != null) UnityEngine.InputSystem.InputSystem.SetDeviceUsage(this, usage);
        }
    }
}
