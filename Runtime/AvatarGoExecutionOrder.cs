namespace AvatarGo
{
    /// <summary>
    /// The execution order the components rely on (their <c>[DefaultExecutionOrder]</c>), in the order a frame runs them:
    /// the calibrator reads the tracking source and runs the pipeline early in <c>Update</c>; the Animator IK driver places
    /// the avatar's root before the Animator evaluates; the Animator runs (its IK pass calls the driver's
    /// <c>OnAnimatorIK</c>); then, in <c>LateUpdate</c>, the transform driver, the fingers and the held controllers write
    /// their bones; the calibrator's mirror follows in <c>Application.onBeforeRender</c>, after every bone is final.
    /// </summary>
    public static class AvatarGoExecutionOrder
    {
        /// <summary>AvatarGoCalibrator: reads the source once and runs the pipeline, before the application's scripts (order 0).</summary>
        public const int Calibrator = -100;

        /// <summary>AvatarGoRecorder: records the frame the calibrator read (or reads a source itself), right after it.</summary>
        public const int Recorder = -95;

        /// <summary>AvatarGoAnimatorIKDriver: places the avatar's root in Update, after the calibrator and before the Animator.</summary>
        public const int AnimatorIKDriver = -90;

        /// <summary>AvatarGoTransformDriver: writes the whole solve in LateUpdate, after the Animator.</summary>
        public const int TransformDriver = 100;

        /// <summary>AvatarGoFingers: writes the finger bones in LateUpdate, after the Animator's IK and the transform driver.</summary>
        public const int Fingers = 110;

        /// <summary>AvatarGoHeldController: moves the controller models in LateUpdate, once the hands are final.</summary>
        public const int HeldController = 120;
    }
}
