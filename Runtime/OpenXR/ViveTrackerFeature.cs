using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;
using UnityEngine.InputSystem;
using UnityEngine.InputSystem.Layouts;
using UnityEngine.InputSystem.XR;
using UnityEngine.XR;
using UnityEngine.XR.OpenXR;
using UnityEngine.XR.OpenXR.Features;

namespace AvatarGo
{
    /// <summary>
    /// An OpenXR interaction profile for VIVE Trackers (extension <c>XR_HTCX_vive_tracker_interaction</c>), which Unity's
    /// OpenXR plug-in does not ship. Enable it in Project Settings &gt; XR Plug-in Management &gt; OpenXR &gt; Enabled
    /// Interaction Profiles ("AvatarGo VIVE Tracker Profile"). It declares one device per body role (the role user paths
    /// <c>/user/vive_tracker_htcx/role/waist</c>, <c>left_foot</c> and <c>right_foot</c>), each with the tracker's grip pose,
    /// so that the trackers appear:
    /// <list type="bullet">
    /// <item>to <c>UnityEngine.XR.InputDevices</c> (the <see cref="XRInputDevicesTrackingSource"/>) as devices named
    /// <see cref="ViveTrackerRoles.DeviceName"/> with characteristics <c>TrackedDevice</c> plus the role bit
    /// (<see cref="ViveTrackerRoles.RoleBit"/>: the values the community tracker profiles use), and the device pose
    /// features (<c>devicePosition</c>, <c>deviceRotation</c>, <c>isTracked</c>, <c>trackingState</c>);</item>
    /// <item>to the Input System as <see cref="XRViveTracker"/> devices with the usage of their role
    /// (<c>&lt;XRViveTracker&gt;{Waist}/devicePose/position</c>).</item>
    /// </list>
    /// OpenXR reports no serial numbers. The roles are those assigned in SteamVR's "Manage Trackers"; the calibration checks
    /// them against where the trackers are worn. Enable only one VIVE tracker profile: two profiles suggesting bindings for
    /// the same interaction profile replace each other's.
    /// </summary>
#if UNITY_EDITOR
    [UnityEditor.XR.OpenXR.Features.OpenXRFeature(
        UiName = "AvatarGo VIVE Tracker Profile",
        Company = "AvatarGo",
        Desc = "VIVE Trackers on the waist and feet through XR_HTCX_vive_tracker_interaction, for AvatarGo's full-body avatar.",
        DocumentationLink = AvatarGoDocs.Manual + "tracking-sources.md#openxr-vive-trackers",
        OpenxrExtensionStrings = ViveTrackerRoles.Extension,
        Version = "0.1.0",
        Category = UnityEditor.XR.OpenXR.Features.FeatureCategory.Interaction,
        FeatureId = FeatureId)]
#endif
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#openxr-vive-trackers")]
    public class ViveTrackerFeature : OpenXRInteractionFeature
    {
        /// <summary>The feature's id in the OpenXR settings.</summary>
        public const string FeatureId = "com.avatargo.openxr.feature.input.vivetracker";

        /// <summary>The action map's name.</summary>
        private const string ActionMapName = "avatargovivetracker";

        /// <summary>Refuses to start (the feature is then off for the session) when the runtime lacks the extension.</summary>
        protected override bool OnInstanceCreate(ulong xrInstance)
        {
            if (!OpenXRRuntime.IsExtensionEnabled(ViveTrackerRoles.Extension))
            {
                Debug.LogWarning("AvatarGo: the OpenXR runtime does not offer " + ViveTrackerRoles.Extension + ": no VIVE Tracker will be reported (SteamVR and VIVE's PC runtimes have it).", this);
                return false;
            }
            return base.OnInstanceCreate(xrInstance);
        }

        /// <summary>Registers the <see cref="XRViveTracker"/> layout for the devices this feature creates.</summary>
        protected override void RegisterDeviceLayout()
        {
            UnityEngine.InputSystem.InputSystem.RegisterLayout(typeof(XRViveTracker), ViveTrackerRoles.LayoutName,
                matches: new InputDeviceMatcher()
                    .WithInterface(XRUtilities.InterfaceMatchAnyVersion)
                    .WithProduct(ViveTrackerRoles.DeviceName));
        }

        /// <summary>Removes the layout.</summary>
        protected override void UnregisterDeviceLayout() => UnityEngine.InputSystem.InputSystem.RemoveLayout(ViveTrackerRoles.LayoutName);

#if AVATARGO_OPENXR_1_9_OR_NEWER
        /// <summary>The devices are trackers, not controllers (OpenXR 1.9's binding validation).</summary>
        protected override InteractionProfileType GetInteractionProfileType() => InteractionProfileType.Device;

        /// <summary>The layout the binding validation checks bindings against.</summary>
        protected override string GetDeviceLayoutName() => ViveTrackerRoles.LayoutName;
#endif

        /// <summary>Declares the action map: one device per body role, one pose action bound to the tracker's grip pose.</summary>
        protected override void RegisterActionMapsWithRuntime()
        {
            var devices = new List<DeviceConfig>();
            foreach (DeviceRole role in ViveTrackerRoles.Roles)
                devices.Add(new DeviceConfig
                {
                    characteristics = (InputDeviceCharacteristics)ViveTrackerRoles.Characteristics(role),
                    userPath = ViveTrackerRoles.RolePath(role),
                });
            AddActionMap(new ActionMapConfig
            {
                name = ActionMapName,
                localizedName = ViveTrackerRoles.DeviceName,
                desiredInteractionProfile = ViveTrackerRoles.InteractionProfile,
                manufacturer = "HTC",
                serialNumber = "",
                deviceInfos = devices,
                actions = new List<ActionConfig>
                {
                    new ActionConfig
                    {
                        name = ViveTrackerRoles.PoseControl,
                        localizedName = "Device Pose",
                        type = ActionType.Pose,
                        usages = new List<string> { "Device" },
                        bindings = new List<ActionBinding>
                        {
                            new ActionBinding
                            {
                                interactionPath = ViveTrackerRoles.GripPose,
                                interactionProfileName = ViveTrackerRoles.InteractionProfile,
                            },
                        },
                    },
                },
            });
        }
    }
}
