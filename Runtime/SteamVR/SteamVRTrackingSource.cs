using System;
using AvatarGo.Core;
using UnityEngine;
using Valve.VR;

namespace AvatarGo
{
    /// <summary>
    /// Devices read through the SteamVR Unity Plugin's input system (2.7.3 or newer, imported into Assets; this assembly
    /// compiles only when the scripting define <c>AVATARGO_STEAMVR</c> is set, as the plug-in sets none): one pose action
    /// read for the input sources <c>Head</c>, <c>LeftHand</c>, <c>RightHand</c>, <c>Waist</c>, <c>LeftFoot</c> and
    /// <c>RightFoot</c>, and the controllers' trigger (analog and button) and grip. The trackers' roles are the SteamVR roles
    /// their bindings give (Manage Trackers, then a binding of the pose action for the controller types
    /// <c>vive_tracker_waist</c>, <c>vive_tracker_left_foot</c>, <c>vive_tracker_right_foot</c>): without those bindings the
    /// trackers stay lost. Serials come from OpenVR once a device is bound (when the OpenVR XR plug-in provides the OpenVR
    /// API), and give a new header. Poses are in SteamVR's tracking universe: set <see cref="AvatarGoTrackingSource.TrackingSpaceOrigin"/>
    /// to the rig object the SteamVR poses are relative to.
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/SteamVR Tracking Source")]
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#steamvr-tracking-source")]
    [DisallowMultipleComponent]
    public sealed class SteamVRTrackingSource : AvatarGoTrackingSource
    {
        private const uint NoDevice = 0xFFFFFFFFu; // OpenVR k_unTrackedDeviceIndexInvalid

        [SerializeField, Tooltip("The SteamVR pose action read for every role (its full path). Bind it for the HMD and the tracker roles in the SteamVR binding UI.")]
        private string m_PoseAction = "/actions/default/in/Pose";

        [SerializeField, Tooltip("Optional: the HMD's transform (the XR camera), used instead of the pose action's Head source, which SteamVR's default bindings leave unbound.")]
        private Transform m_Head;

        [SerializeField, Tooltip("The analog trigger (a Single action, 0..1). Empty: none.")]
        private string m_TriggerAction = "/actions/default/in/Squeeze";

        [SerializeField, Tooltip("The trigger button (a Boolean action). Empty: none.")]
        private string m_TriggerButtonAction = "/actions/default/in/GrabPinch";

        [SerializeField, Tooltip("The grip (a Boolean action, reported as grip 1 or 0). Empty: none.")]
        private string m_GripAction = "/actions/default/in/GrabGrip";

        private readonly RoleSlotDevices _slots = new RoleSlotDevices();
        private readonly TriggerEdges _edges = new TriggerEdges(BodyRoles.Count);
        private readonly uint[] _deviceIndex = { NoDevice, NoDevice, NoDevice, NoDevice, NoDevice, NoDevice };
        private SteamVR_Action_Pose _pose;
        private SteamVR_Action_Single _trigger;
        private SteamVR_Action_Boolean _triggerButton;
        private SteamVR_Action_Boolean _grip;

        /// <summary>The HMD transform used instead of the pose action's Head source, or null.</summary>
        public Transform Head { get => m_Head; set => m_Head = value; }

        /// <inheritdoc/>
        public override SessionHeader Header => _slots.Header;

        private void OnEnable()
        {
            if (string.IsNullOrEmpty(m_PoseAction))
            {
                SetupErrors.Disable(this, "AvatarGo: the SteamVR Tracking Source has no pose action path; it is disabled.");
            }
        }

        // The actions are looked up once SteamVR's input is initialized (before, SteamVR_Input only makes placeholders).
        // A pose action the project's actions lack is a setup error: logged once, and the source disables itself.
        private bool ResolveActions()
        {
            // GetPoseActionFromPath never returns null (an unknown path gives a placeholder that is never active), so the
            // path is checked first.
            SteamVR_Action_Pose pose = null;
            string wrongType = null;
            try
            {
                pose = SteamVR_Input.HasActionPath(m_PoseAction) ? SteamVR_Input.GetPoseActionFromPath(m_PoseAction) : null;
            }
            catch (InvalidCastException)
            {
                wrongType = " is not a Pose action";
            }
            if (pose == null)
            {
                SetupErrors.Disable(this, "AvatarGo: the SteamVR Tracking Source's pose action '" + m_PoseAction + "'" +
                                          (wrongType ?? " is not in the project's SteamVR actions") + " (Window > SteamVR Input); it is disabled.");
                return false;
            }
            // The optional actions before the pose is kept, so that a failure here leaves nothing half resolved.
            SteamVR_Action_Single trigger = Typed(m_TriggerAction, "Single", SteamVR_Input.GetSingleActionFromPath);
            SteamVR_Action_Boolean triggerButton = Typed(m_TriggerButtonAction, "Boolean", SteamVR_Input.GetBooleanActionFromPath);
            SteamVR_Action_Boolean grip = Typed(m_GripAction, "Boolean", SteamVR_Input.GetBooleanActionFromPath);
            _trigger = trigger;
            _triggerButton = triggerButton;
            _grip = grip;
            _pose = pose;
            return true;
        }

        // An optional action of the type the field needs, or none (warned about). During play SteamVR hands out the action
        // itself cast to the type asked for (SteamVR_Action.GetCopy: "(CreateType)this"), so an action of another type (a
        // Boolean GrabPinch given as the trigger's Single) throws InvalidCastException; it stopped the whole calibrator.
        private T Typed<T>(string path, string type, Func<string, bool, T> lookup) where T : class
        {
            if (!Known(path)) return null;
            try
            {
                return lookup(path, false);
            }
            catch (InvalidCastException)
            {
                Debug.LogWarning("AvatarGo: the SteamVR Tracking Source's action '" + path + "' is not a " + type + " action; it is not read.", this);
                return null;
            }
        }

        // An optional action: none when no path is set; a path the project's actions lack is warned about (SteamVR would give
        // a placeholder that never fires: no trigger, so no calibration step, with nothing said).
        private bool Known(string path)
        {
            if (string.IsNullOrEmpty(path)) return false;
            if (SteamVR_Input.HasActionPath(path)) return true;
            Debug.LogWarning("AvatarGo: the SteamVR Tracking Source found no action '" + path + "' in the project's SteamVR actions (Window > SteamVR Input); it is not read.", this);
            return false;
        }

        private void OnDisable()
        {
            for (int d = 0; d < BodyRoles.Count; d++)
            {
                _edges.Forget(d);
                _deviceIndex[d] = NoDevice;
            }
        }

        /// <inheritdoc/>
        public override void Read(SessionFrame frame)
        {
            if (frame == null) return;
            frame.Clear();
            frame.Time = Time.unscaledTimeAsDouble; // real time: a paused game (timeScale 0) still tracks and calibrates
            if (frame.Samples.Length < BodyRoles.Count || !isActiveAndEnabled) return;
            if (m_Head != null) frame.Samples[0] = new DeviceSample(ToTrackingSpace(m_Head), true);
            if (!SteamVR_Input.initialized) return; // before SteamVR starts: only the head transform
            if (_pose == null && !ResolveActions()) return;
            for (int d = m_Head != null ? 1 : 0; d < BodyRoles.Count; d++)
            {
                SteamVR_Input_Sources source = Source(BodyRoles.All[d]);
                bool connected = _pose.GetDeviceIsConnected(source);
                if (connected) NoteDevice(d, _pose.GetDeviceIndex(source));
                frame.Samples[d] = connected && _pose.GetPoseIsValid(source)
                    ? new DeviceSample(new RigidPose(_pose.GetLocalPosition(source).ToCore(), _pose.GetLocalRotation(source).ToCore()), true)
                    : DeviceSample.Lost;
            }
            if (m_Head != null) NoteDevice(0, 0u); // the HMD is OpenVR's device 0 (k_unTrackedDeviceIndex_Hmd)
            for (int side = 0; side < 2; side++)
            {
                DeviceRole hand = BodyRoles.Hand((BodySide)side);
                int d = BodyRoles.IndexOf(hand);
                SteamVR_Input_Sources source = Source(hand);
                float trigger = _trigger != null ? _trigger.GetAxis(source) : float.NaN;
                bool button = _triggerButton != null && _triggerButton.GetState(source);
                frame.Trigger[d] = trigger;
                frame.Grip[d] = _grip == null ? float.NaN : _grip.GetState(source) ? 1f : 0f;
                _edges.Feed(d, d, trigger, button, frame.Events);
            }
        }

        // A device newly bound to a role: its OpenVR serial (allocates; once per change of device).
        private void NoteDevice(int d, uint deviceIndex)
        {
            if (deviceIndex == _deviceIndex[d]) return;
            _deviceIndex[d] = deviceIndex;
#if AVATARGO_OPENVR_XR
            if (deviceIndex == NoDevice || !SteamVR.active) return;
            string serial = SteamVR.instance.GetStringProperty(ETrackedDeviceProperty.Prop_SerialNumber_String, deviceIndex);
            if (_slots.SetSerial(BodyRoles.All[d], serial)) HeaderVersion++;
#endif
        }

        private static SteamVR_Input_Sources Source(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Head: return SteamVR_Input_Sources.Head;
                case DeviceRole.LeftHand: return SteamVR_Input_Sources.LeftHand;
                case DeviceRole.RightHand: return SteamVR_Input_Sources.RightHand;
                case DeviceRole.Pelvis: return SteamVR_Input_Sources.Waist;
                case DeviceRole.LeftFoot: return SteamVR_Input_Sources.LeftFoot;
                default: return SteamVR_Input_Sources.RightFoot;
            }
        }
    }
}
