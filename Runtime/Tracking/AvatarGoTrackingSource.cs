using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Where the devices' poses, analog inputs and trigger events come from: the Unity XR input devices, Input System
    /// actions, the SteamVR plugin, plain transforms, or a recorded session. One per rig; the calibrator (<c>AvatarGoCalibrator</c>)
    /// reads it once a frame, before the Animator updates. Every source reports poses in tracking space (the XR runtime's
    /// own space, floor at y = 0); <see cref="TrackingSpaceOrigin"/> says where that space lies in the scene.
    /// </summary>
    public abstract class AvatarGoTrackingSource : MonoBehaviour
    {
        [SerializeField]
        [Tooltip("The transform whose space the devices are tracked in: the XR Origin's Camera Offset object. Empty: the scene's world space.")]
        private Transform m_TrackingSpaceOrigin;

        /// <summary>The transform whose space the devices are tracked in (the XR Origin's camera offset), or null for the world.</summary>
        public Transform TrackingSpaceOrigin
        {
            get => m_TrackingSpaceOrigin;
            set => m_TrackingSpaceOrigin = value;
        }

        /// <summary>
        /// The devices, in the order <see cref="Read"/> fills samples, and the nominal frame rate. A new header (and a new
        /// <see cref="HeaderVersion"/>) whenever a device connects; a device that disconnects stays, reported as lost.
        /// </summary>
        public abstract SessionHeader Header { get; }

        /// <summary>Changes whenever <see cref="Header"/> is replaced.</summary>
        public int HeaderVersion { get; protected set; }

        /// <summary>
        /// Fills <paramref name="frame"/> (made for the current <see cref="Header"/>) with this frame: the time in seconds,
        /// every device's pose in tracking space and whether it is tracked, each controller's trigger and grip (NaN when not
        /// given), and the trigger presses and releases since the last call. Allocation-free.
        /// </summary>
        public abstract void Read(SessionFrame frame);

        /// <summary>Where tracking space lies in the scene this frame.</summary>
        public TrackingSpace GetTrackingSpace() =>
            m_TrackingSpaceOrigin == null ? TrackingSpace.World : new TrackingSpace(m_TrackingSpaceOrigin.GetWorldPose());

        /// <summary>
        /// The pose of a device given as a <paramref name="device"/> transform (world space), in tracking space: relative to
        /// <see cref="TrackingSpaceOrigin"/>, or the world pose when there is none. Allocation-free.
        /// </summary>
        protected RigidPose ToTrackingSpace(Transform device)
        {
            RigidPose world = device.GetWorldPose();
            return m_TrackingSpaceOrigin == null ? world : GetTrackingSpace().ToTracking(world);
        }
    }
}
