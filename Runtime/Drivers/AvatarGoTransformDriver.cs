using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Writes the pipeline's full-body solve straight into the avatar's transforms in <c>LateUpdate</c>: the root placed and
    /// scaled, every bound transform's local rotation and position, fingers included. For avatars without an Animator (bound
    /// by their bones' names), and for applications that want the core's measured accuracy rather than Unity's IK (no
    /// centre-of-mass compensation, no effector frames, nothing left to Unity). Allocation-free per frame.
    /// </summary>
    /// <remarks>
    /// Runs after the Animator (<see cref="AvatarGoExecutionOrder.TransformDriver"/>), so whatever the Animator wrote is
    /// overwritten; by default the Animator is disabled while this component is enabled, so that it does no useless work.
    /// While the calibrator is stopped nothing is written and the Animator is enabled again.
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Transform Driver")]
    [HelpURL(AvatarGoDocs.Manual + "transform-driver.md")]
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.TransformDriver)]
    public sealed class AvatarGoTransformDriver : MonoBehaviour
    {
        [SerializeField, Tooltip("The calibrator whose pipeline drives this avatar (found in the parents when empty).")]
        private AvatarGoCalibrator m_Calibrator;

        [SerializeField, Tooltip("Disable the avatar's Animator while this component drives the bones (it would only be overwritten).")]
        private bool m_DisableAnimator = true;

        private Animator _disabledAnimator;
        private bool _failed;

        /// <summary>
        /// The calibrator whose pipeline drives this avatar. Set at run time, the Animator this driver disabled is enabled
        /// again and the new calibrator (null: the nearest in the parents) is used from the next <c>LateUpdate</c>, its
        /// avatar's Animator disabled then; a setup error of the old one is forgotten (a component that disabled itself stays
        /// off until enabled).
        /// </summary>
        public AvatarGoCalibrator Calibrator
        {
            get => m_Calibrator;
            set
            {
                if (value == m_Calibrator) return;
                // The old avatar's Animator is its own again (it would stay disabled for good, and the new avatar's never
                // be disabled, as _disabledAnimator was taken).
                GiveAnimatorBack();
                m_Calibrator = value;
                _failed = false;
            }
        }

        private void OnDisable() => GiveAnimatorBack();

        private void GiveAnimatorBack()
        {
            if (_disabledAnimator != null) _disabledAnimator.enabled = true;
            _disabledAnimator = null;
        }

        private void LateUpdate()
        {
            if (_failed) return;
            if (!SetupErrors.FindCalibrator(this, ref m_Calibrator, ref _failed)) return;
            if (!m_Calibrator.isActiveAndEnabled)
            {
                // A stopped (or failed) calibrator has put the bind positions back (its OnDisable): the last solved pose
                // written over them every frame would freeze the avatar. The avatar is its Animator's again until it comes back.
                GiveAnimatorBack();
                return;
            }
            HumanoidBinding binding = m_Calibrator.Binding;
            SelfAvatarPipeline pipeline = m_Calibrator.Pipeline;
            SkeletonPose pose = pipeline?.Pose;
            if (binding == null || pose == null || pipeline.Profile == null || binding.Root == null) return;
            if (m_DisableAnimator && _disabledAnimator == null && m_Calibrator.Animator != null && m_Calibrator.Animator.enabled)
            {
                _disabledAnimator = m_Calibrator.Animator;
                _disabledAnimator.enabled = false;
            }
            binding.ApplyPose(pose, m_Calibrator.TrackingSpace, pipeline.Profile.AvatarScale);
        }
    }
}
