using System;
using UnityEngine;
using UnityEngine.InputSystem;

namespace AvatarGo
{
    /// <summary>
    /// The Input System actions of one tracked device of an <see cref="InputSystemTrackingSource"/>: its position (a Vector3
    /// control), its rotation (a Quaternion control) and its tracking state (an integer control, <c>InputTrackingState</c>
    /// bits). An action left without bindings gets the default binding of its role (<see cref="AvatarGo.Core.InputSystemBindings"/>).
    /// The source takes its actions when it is enabled: an action changed while it is enabled is used from its next enable.
    /// </summary>
    [Serializable]
    public sealed class InputSystemDeviceActions
    {
        [SerializeField, Tooltip("The device's position in tracking space (Vector3). Without bindings: the default binding of its role.")]
        private InputActionProperty m_Position;

        [SerializeField, Tooltip("The device's rotation in tracking space (Quaternion). Without bindings: the default binding of its role.")]
        private InputActionProperty m_Rotation;

        [SerializeField, Tooltip("The device's tracking state (Integer, InputTrackingState bits: position and rotation must both be set). Without bindings: the default binding of its role; a device without the control counts as tracked while its pose is bound.")]
        private InputActionProperty m_TrackingState;

        /// <summary>The position action.</summary>
        public InputActionProperty Position { get => m_Position; set => m_Position = value; }

        /// <summary>The rotation action.</summary>
        public InputActionProperty Rotation { get => m_Rotation; set => m_Rotation = value; }

        /// <summary>The tracking-state action.</summary>
        public InputActionProperty TrackingState { get => m_TrackingState; set => m_TrackingState = value; }
    }
}
