using AvatarGo.Core;
using UnityEngine;
using UnityEngine.InputSystem;

namespace AvatarGo
{
    /// <summary>
    /// Devices read through Input System actions (package <c>com.unity.inputsystem</c>; this assembly only compiles when it
    /// is installed): one device per body role, each with position, rotation and tracking-state actions, and the controllers'
    /// trigger and grip. No action asset is needed: an action left without bindings gets its role's default binding, made in
    /// code (<see cref="InputSystemBindings"/>: the HMD's centre eye, <c>&lt;XRController&gt;{LeftHand}</c>'s device pose,
    /// <c>&lt;XRViveTracker&gt;{Waist}</c>'s pose, which AvatarGo's OpenXR VIVE tracker feature provides). Actions from an
    /// asset (an <c>InputActionReference</c>) are used as they are, enabled while this component is if they were not.
    /// The trackers carry the role their binding gives as runtime role (checked against the T-pose by the calibration);
    /// the Input System gives no serials here, so a saved calibration is never restored from them.
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/Input System Tracking Source")]
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#input-system-tracking-source")]
    [DisallowMultipleComponent]
    public sealed class InputSystemTrackingSource : AvatarGoTrackingSource
    {
        private const int PoseActions = BodyRoles.Count * 3;
        private const int ActionCount = PoseActions + 4;

        [SerializeField, Tooltip("The HMD. Default: <XRHMD>/centerEyePosition, centerEyeRotation, trackingState.")]
        private InputSystemDeviceActions m_Head = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The controller in the left hand. Default: <XRController>{LeftHand}/devicePosition, deviceRotation, trackingState.")]
        private InputSystemDeviceActions m_LeftController = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The controller in the right hand. Default: <XRController>{RightHand}/devicePosition, deviceRotation, trackingState.")]
        private InputSystemDeviceActions m_RightController = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The pelvis tracker. Default: <XRViveTracker>{Waist}/devicePose (AvatarGo's OpenXR VIVE tracker feature).")]
        private InputSystemDeviceActions m_PelvisTracker = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The left foot tracker. Default: <XRViveTracker>{LeftFoot}/devicePose (AvatarGo's OpenXR VIVE tracker feature).")]
        private InputSystemDeviceActions m_LeftFootTracker = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The right foot tracker. Default: <XRViveTracker>{RightFoot}/devicePose (AvatarGo's OpenXR VIVE tracker feature).")]
        private InputSystemDeviceActions m_RightFootTracker = new InputSystemDeviceActions();

        [SerializeField, Tooltip("The left controller's analog trigger, 0..1 (Axis). Default: <XRController>{LeftHand}/{Trigger}.")]
        private InputActionProperty m_LeftTrigger;

        [SerializeField, Tooltip("The left controller's analog grip, 0..1 (Axis). Default: <XRController>{LeftHand}/{Grip}.")]
        private InputActionProperty m_LeftGrip;

        [SerializeField, Tooltip("The right controller's analog trigger, 0..1 (Axis). Default: <XRController>{RightHand}/{Trigger}.")]
        private InputActionProperty m_RightTrigger;

        [SerializeField, Tooltip("The right controller's analog grip, 0..1 (Axis). Default: <XRController>{RightHand}/{Grip}.")]
        private InputActionProperty m_RightGrip;

        private readonly RoleSlotDevices _slots = new RoleSlotDevices();
        private readonly TriggerEdges _edges = new TriggerEdges(BodyRoles.Count);
        private readonly InputAction[] _actions = new InputAction[ActionCount];
        private readonly bool[] _created = new bool[ActionCount];
        private readonly bool[] _enabledHere = new bool[ActionCount];

        /// <summary>The HMD's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions Head => m_Head;

        /// <summary>The left controller's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions LeftController => m_LeftController;

        /// <summary>The right controller's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions RightController => m_RightController;

        /// <summary>The pelvis tracker's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions PelvisTracker => m_PelvisTracker;

        /// <summary>The left foot tracker's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions LeftFootTracker => m_LeftFootTracker;

        /// <summary>The right foot tracker's actions (changes take effect when the component is next enabled).</summary>
        public InputSystemDeviceActions RightFootTracker => m_RightFootTracker;

        /// <summary>The left trigger action. Changes take effect when the component is next enabled.</summary>
        public InputActionProperty LeftTrigger { get => m_LeftTrigger; set => m_LeftTrigger = value; }

        /// <summary>The left grip action. Changes take effect when the component is next enabled.</summary>
        public InputActionProperty LeftGrip { get => m_LeftGrip; set => m_LeftGrip = value; }

        /// <summary>The right trigger action. Changes take effect when the component is next enabled.</summary>
        public InputActionProperty RightTrigger { get => m_RightTrigger; set => m_RightTrigger = value; }

        /// <summary>The right grip action. Changes take effect when the component is next enabled.</summary>
        public InputActionProperty RightGrip { get => m_RightGrip; set => m_RightGrip = value; }

        /// <inheritdoc/>
        public override SessionHeader Header => _slots.Header;

        // Unity calls Reset when the component is added in the Editor: the defaults become visible, editable embedded actions.
        private void Reset()
        {
            for (int k = 0; k < ActionCount; k++) SetProperty(k, new InputActionProperty(CreateDefault(k)));
        }

        private void OnEnable()
        {
#if !ENABLE_INPUT_SYSTEM
            Debug.LogWarning("AvatarGo: the Input System package is installed but not enabled (Project Settings > Player > Active Input Handling): the Input System Tracking Source will see no device.", this);
#endif
            for (int k = 0; k < ActionCount; k++)
            {
                InputActionProperty property = Property(k);
                InputAction action = property.action;
                bool fromAsset = property.reference != null;
                if (action == null || action.bindings.Count == 0)
                {
                    action = CreateDefault(k);
                    _created[k] = true;
                    fromAsset = false;
                }
                _actions[k] = action;
                if (!action.enabled)
                {
                    action.Enable();
                    // An asset's action is shared (XRI's rig reads the same XRI Default Input Actions): enabled here if no
                    // one had, but never disabled here, which froze the rig's controllers whenever this source was disabled
                    // (Unity's TrackedPoseDriver and XRI manage only their own direct actions the same way).
                    _enabledHere[k] = !fromAsset;
                }
            }
        }

        private void OnDisable()
        {
            for (int k = 0; k < ActionCount; k++)
            {
                InputAction action = _actions[k];
                if (action == null) continue;
                if (_enabledHere[k]) action.Disable();
                if (_created[k]) action.Dispose();
                _actions[k] = null;
                _created[k] = _enabledHere[k] = false;
            }
            for (int d = 0; d < BodyRoles.Count; d++) _edges.Forget(d);
        }

        /// <inheritdoc/>
        public override void Read(SessionFrame frame)
        {
            if (frame == null) return;
            frame.Clear();
            frame.Time = Time.unscaledTimeAsDouble; // real time: a paused game (timeScale 0) still tracks and calibrates
            if (_actions[0] == null || frame.Samples.Length < BodyRoles.Count) return; // disabled: every device lost
            try
            {
                ReadActions(frame);
            }
            catch (System.InvalidOperationException e)
            {
                // An action bound to a control of another type (ReadValue<Vector3> on an axis): a setup error, logged once.
                frame.Clear();
                frame.Time = Time.unscaledTimeAsDouble; // real time: a paused game (timeScale 0) still tracks and calibrates
                SetupErrors.Disable(this, "AvatarGo: the Input System Tracking Source cannot read its actions (" + e.Message +
                                          "): check that each is bound to a control of its type (Vector3, Quaternion, Integer, Axis). The component is disabled.");
            }
        }

        private void ReadActions(SessionFrame frame)
        {
            for (int d = 0; d < BodyRoles.Count; d++)
            {
                InputAction position = _actions[3 * d], rotation = _actions[3 * d + 1], state = _actions[3 * d + 2];
                bool stateBound = state.controls.Count > 0;
                bool tracked = XrPoseRules.IsTracked(position.controls.Count > 0, rotation.controls.Count > 0, false, false,
                    stateBound, stateBound ? (uint)state.ReadValue<int>() : 0u);
                frame.Samples[d] = tracked
                    ? new DeviceSample(new RigidPose(position.ReadValue<Vector3>().ToCore(), rotation.ReadValue<Quaternion>().ToCore()), true)
                    : DeviceSample.Lost;
            }
            for (int side = 0; side < 2; side++)
            {
                int d = BodyRoles.IndexOf(BodyRoles.Hand((BodySide)side));
                float trigger = ReadAxis(_actions[PoseActions + 2 * side]);
                frame.Trigger[d] = trigger;
                frame.Grip[d] = ReadAxis(_actions[PoseActions + 2 * side + 1]);
                _edges.Feed(d, Header.Devices[d].Id, trigger, false, frame.Events);
            }
        }

        private static float ReadAxis(InputAction action) => action.controls.Count > 0 ? action.ReadValue<float>() : float.NaN;

        // Action k: 3 per role in BodyRoles.All order (position, rotation, tracking state), then left trigger, left grip,
        // right trigger, right grip.
        private static InputAction CreateDefault(int k)
        {
            if (k >= PoseActions)
            {
                var side = (BodySide)((k - PoseActions) / 2);
                bool grip = (k - PoseActions) % 2 == 1;
                return new InputAction(side + (grip ? " Grip" : " Trigger"), InputActionType.Value,
                    grip ? InputSystemBindings.Grip(side) : InputSystemBindings.Trigger(side), expectedControlType: "Axis");
            }
            DeviceRole role = BodyRoles.All[k / 3];
            switch (k % 3)
            {
                case 0: return new InputAction(role + " Position", InputActionType.Value, InputSystemBindings.Position(role), expectedControlType: "Vector3");
                case 1: return new InputAction(role + " Rotation", InputActionType.Value, InputSystemBindings.Rotation(role), expectedControlType: "Quaternion");
                default: return new InputAction(role + " Tracking State", InputActionType.Value, InputSystemBindings.TrackingState(role), expectedControlType: "Integer");
            }
        }

        private InputSystemDeviceActions Device(int d) =>
            RoleSlots.Pick(d, m_Head, m_LeftController, m_RightController, m_PelvisTracker, m_LeftFootTracker, m_RightFootTracker);

        private InputActionProperty Property(int k)
        {
            switch (k - PoseActions)
            {
                case 0: return m_LeftTrigger;
                case 1: return m_LeftGrip;
                case 2: return m_RightTrigger;
                case 3: return m_RightGrip;
            }
            InputSystemDeviceActions device = Device(k / 3) ?? new InputSystemDeviceActions();
            return k % 3 == 0 ? device.Position : k % 3 == 1 ? device.Rotation : device.TrackingState;
        }

        private void SetProperty(int k, InputActionProperty value)
        {
            switch (k - PoseActions)
            {
                case 0: m_LeftTrigger = value; return;
                case 1: m_LeftGrip = value; return;
                case 2: m_RightTrigger = value; return;
                case 3: m_RightGrip = value; return;
            }
            InputSystemDeviceActions device = Device(k / 3);
            if (k % 3 == 0) device.Position = value;
            else if (k % 3 == 1) device.Rotation = value;
            else device.TrackingState = value;
        }
    }
}
