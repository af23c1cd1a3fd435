using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Devices given as plain transforms (an XR Interaction Toolkit rig's camera and controllers, objects a tracking SDK
    /// moves, or test fixtures): the HMD, both controllers and three trackers. A transform left empty is a device that is
    /// never tracked, and so is one whose GameObject is inactive (the XR Interaction Toolkit's input modality manager
    /// deactivates a controller until it is tracked). Triggers come from script (<see cref="SetTrigger"/>) as the
    /// transforms carry no input. Disabled, it reports every device lost, as the live sources do.
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/Transform Tracking Source")]
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#transform-tracking-source")]
    [DisallowMultipleComponent]
    public sealed class TransformTrackingSource : AvatarGoTrackingSource
    {
        [SerializeField, Tooltip("The HMD: the camera, at the centre of the eyes.")] private Transform m_Head;
        [SerializeField, Tooltip("The controller in the left hand.")] private Transform m_LeftController;
        [SerializeField, Tooltip("The controller in the right hand.")] private Transform m_RightController;
        [SerializeField, Tooltip("The tracker on the lower back.")] private Transform m_PelvisTracker;
        [SerializeField, Tooltip("The tracker on the left foot.")] private Transform m_LeftFootTracker;
        [SerializeField, Tooltip("The tracker on the right foot.")] private Transform m_RightFootTracker;

        // The serial of each role's transform device, in BodyRoles.All order.
        private static readonly string[] Serials =
        {
            "transform-head", "transform-left-controller", "transform-right-controller",
            "transform-pelvis", "transform-left-foot", "transform-right-foot",
        };

        private SessionHeader _header;
        private readonly float[] _trigger = { float.NaN, float.NaN };
        private TriggerEdges _edges;
        private readonly List<DeviceEvent> _events = new List<DeviceEvent>(4);

        /// <summary>The HMD transform.</summary>
        public Transform Head { get => m_Head; set => m_Head = value; }

        /// <summary>The left controller transform.</summary>
        public Transform LeftController { get => m_LeftController; set => m_LeftController = value; }

        /// <summary>The right controller transform.</summary>
        public Transform RightController { get => m_RightController; set => m_RightController = value; }

        /// <summary>The pelvis tracker transform.</summary>
        public Transform PelvisTracker { get => m_PelvisTracker; set => m_PelvisTracker = value; }

        /// <summary>The left foot tracker transform.</summary>
        public Transform LeftFootTracker { get => m_LeftFootTracker; set => m_LeftFootTracker = value; }

        /// <summary>The right foot tracker transform.</summary>
        public Transform RightFootTracker { get => m_RightFootTracker; set => m_RightFootTracker = value; }

        /// <inheritdoc/>
        public override SessionHeader Header => _header ?? (_header = CreateHeader());

        /// <summary>Sets a controller's analog trigger (0..1); crossing 0.75 presses it and 0.25 releases it.</summary>
        public void SetTrigger(BodySide side, float value) => _trigger[(int)side] = value;

        /// <inheritdoc/>
        public override void Read(SessionFrame frame)
        {
            SessionHeader header = Header;
            frame.Clear();
            frame.Time = Time.unscaledTimeAsDouble; // real time: a paused game (timeScale 0) still tracks and calibrates
            if (!isActiveAndEnabled) return; // disabled: every device lost, as the live sources report it
            _events.Clear();
            for (int d = 0; d < header.Devices.Count; d++)
            {
                Transform device = DeviceTransform(d);
                // An inactive transform is not tracked: the XR Interaction Toolkit's input modality manager keeps a
                // controller's GameObject inactive until it is tracked, and while hands are tracked instead.
                frame.Samples[d] = device == null || !device.gameObject.activeInHierarchy ? DeviceSample.Lost : new DeviceSample(ToTrackingSpace(device), true);
            }
            for (int s = 0; s < 2; s++)
            {
                int d = s + 1; // devices 1 and 2 are the controllers
                frame.Trigger[d] = _trigger[s];
                _edges.Feed(d, header.Devices[d].Id, _trigger[s], false, _events);
            }
            for (int e = 0; e < _events.Count; e++) frame.Events.Add(_events[e]);
        }

        private Transform DeviceTransform(int index) =>
            RoleSlots.Pick(index, m_Head, m_LeftController, m_RightController, m_PelvisTracker, m_LeftFootTracker, m_RightFootTracker);

        private SessionHeader CreateHeader()
        {
            // The transforms say which device plays which role; calibration still checks that against the T-pose.
            var slots = new RoleSlotDevices();
            for (int d = 0; d < BodyRoles.Count; d++) slots.SetSerial(BodyRoles.All[d], Serials[d]);
            _edges = new TriggerEdges(BodyRoles.Count);
            HeaderVersion++;
            return slots.Header;
        }
    }
}
