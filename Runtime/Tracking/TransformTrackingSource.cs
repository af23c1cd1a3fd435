using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Devices given as plain transforms (an XR Interaction Toolkit rig's camera and controllers, objects a tracking SDK
    /// moves, or test fixtures): the HMD, both controllers and three trackers. A transform left empty is a device that is
    /// never tracked. Triggers come from script (<see cref="SetTrigger"/>) as the transforms carry no input.
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
            frame.Time = Time.timeAsDouble;
            _events.Clear();
            for (int d = 0; d < header.Devices.Count; d++)
            {
                Transform device = DeviceTransform(d);
                frame.Samples[d] = device == null ? DeviceSample.Lost : new DeviceSample(ToTrackingSpace(device), true);
            }
            for (int s = 0; s < 2; s++)
            {
                int d = s + 1; // devices 1 and 2 are the controllers
                frame.Trigger[d] = _trigger[s];
                _edges.Feed(d, header.Devices[d].Id, _trigger[s], false, _events);
            }
            for (int e = 0; e < _events.Count; e++) frame.Events.Add(_events[e]);
        }

        private RigidPose ToTrackingSpace(Transform device)
        {
            RigidPose world = device.GetWorldPose();
            return TrackingSpaceOrigin == null ? world : GetTrackingSpace().ToTracking(world);
        }

        private Transform DeviceTransform(int index)
        {
            switch (index)
            {
                case 0: return m_Head;
                case 1: return m_LeftController;
                case 2: return m_RightController;
                case 3: return m_PelvisTracker;
                case 4: return m_LeftFootTracker;
                default: return m_RightFootTracker;
            }
        }

        private SessionHeader CreateHeader()
        {
            // The transforms say which device plays which role; calibration still checks that against the T-pose.
            var devices = new[]
            {
                new DeviceInfo(0, DeviceClass.Hmd, "transform-head"),
                new DeviceInfo(1, DeviceClass.Controller, "transform-left-controller"),
                new DeviceInfo(2, DeviceClass.Controller, "transform-right-controller"),
                new DeviceInfo(3, DeviceClass.Tracker, "transform-pelvis", DeviceRole.Pelvis),
                new DeviceInfo(4, DeviceClass.Tracker, "transform-left-foot", DeviceRole.LeftFoot),
                new DeviceInfo(5, DeviceClass.Tracker, "transform-right-foot", DeviceRole.RightFoot),
            };
            _edges = new TriggerEdges(devices.Length);
            HeaderVersion++;
            return new SessionHeader(90f, devices);
        }
    }
}
