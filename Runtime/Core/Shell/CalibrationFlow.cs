using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// What the calibrator component shows and announces, decided from the pipeline's calibration steps: the events of each
    /// frame (a step accepted or refused, a press ignored, a profile restored, a reset, a calibration to save), the message
    /// for the wearer (the current instruction or what to change; after calibrating, a confirmation for
    /// <see cref="ConfirmationSeconds"/>, then nothing), and whether the avatar, the mirror and the device markers are shown.
    /// Engine-free and allocation-free per frame.
    /// </summary>
    public sealed class CalibrationFlow
    {
        /// <summary>What the wearer reads once calibrated, for <see cref="ConfirmationSeconds"/>.</summary>
        public const string CalibratedMessage = "Calibrated: the avatar follows you.";

        /// <summary>What the wearer reads after a saved calibration was restored.</summary>
        public const string RestoredMessage = "Calibration restored: the avatar follows you. Reset to calibrate again.";

        private double _confirmedAt = double.NegativeInfinity;
        private string _confirmation = CalibratedMessage;
        private CalibrationState _state = CalibrationState.WaitingForTPose;
        private string _stepMessage = string.Empty;
        private double _now;

        /// <summary>The default of <see cref="ConfirmationSeconds"/> (s).</summary>
        public const float DefaultConfirmationSeconds = 4f;

        private float _confirmationSeconds = DefaultConfirmationSeconds;

        /// <summary>
        /// How long (s) the confirmation stays up after calibrating or restoring (4 s; NaN gives the default, a negative time
        /// 0, infinity keeps it up for good).
        /// </summary>
        public float ConfirmationSeconds
        {
            get => _confirmationSeconds;
            set => _confirmationSeconds = float.IsNaN(value) ? DefaultConfirmationSeconds : Math.Max(0f, value);
        }

        /// <summary>Keep the mirror once calibrated (to look at oneself), not only during the walk-in.</summary>
        public bool KeepMirrorAfterCalibration { get; set; }

        /// <summary>The calibration state after the last frame.</summary>
        public CalibrationState State => _state;

        /// <summary>The text for the wearer now; empty when nothing should be shown.</summary>
        public string Message => _state != CalibrationState.Calibrated ? _stepMessage
            : double.IsNaN(_confirmedAt) || _now - _confirmedAt < ConfirmationSeconds ? _confirmation : string.Empty;

        /// <summary>True while there is a <see cref="Message"/> to show.</summary>
        public bool ShowsMessage => Message.Length > 0;

        /// <summary>True while the mirror (a mirrored copy of the avatar) should be shown.</summary>
        public bool ShowsMirror => _state == CalibrationState.WalkIn || (_state == CalibrationState.Calibrated && KeepMirrorAfterCalibration);

        /// <summary>True while the device markers should be shown (until calibrated: the wearer sees where each device is).</summary>
        public bool ShowsMarkers => _state != CalibrationState.Calibrated;

        /// <summary>
        /// Feeds the step the pipeline returned this frame (at <paramref name="time"/> seconds) and the state after it; returns
        /// what happened.
        /// </summary>
        public CalibrationFlowEvents Update(double time, CalibrationStep step, CalibrationState state)
        {
            // A time that is not a number or infinite (a broken clock, a bad recording) is a frame in which no time passed, as
            // the pipeline takes it: compared with the confirmation's, it hid the confirmation.
            if (double.IsNaN(time) || double.IsInfinity(time)) time = _now;
            _now = time;
            if (double.IsNaN(_confirmedAt)) _confirmedAt = time; // a restore's confirmation counts from the first frame after it
            _state = state;
            _stepMessage = step.Message ?? string.Empty;
            switch (step.Outcome)
            {
                case CalibrationStepOutcome.Advanced when step.State == CalibrationState.WalkIn:
                    return CalibrationFlowEvents.TPoseAccepted;
                case CalibrationStepOutcome.Advanced when step.State == CalibrationState.Calibrated:
                    Confirm(time, CalibratedMessage);
                    return CalibrationFlowEvents.Calibrated | CalibrationFlowEvents.SaveProfile;
                case CalibrationStepOutcome.Refused:
                    return CalibrationFlowEvents.StepRefused;
                case CalibrationStepOutcome.PressIgnored:
                    return CalibrationFlowEvents.PressIgnored;
                default:
                    return CalibrationFlowEvents.None;
            }
        }

        /// <summary>
        /// A saved profile was restored at <paramref name="time"/>: calibrated, with the restore's confirmation, whose
        /// <see cref="ConfirmationSeconds"/> count from the next <see cref="Update"/>'s time. A restore comes between frames
        /// (at start, before the source's first frame; when the devices changed), from a time the next frame's clock need not
        /// continue: counted from it, the confirmation of a restore at 0 was never shown once the source's clock was past 4 s.
        /// </summary>
        public CalibrationFlowEvents Restored(double time)
        {
            _now = time;
            _state = CalibrationState.Calibrated;
            Confirm(double.NaN, RestoredMessage);
            return CalibrationFlowEvents.Restored;
        }

        /// <summary>The calibration was reset at <paramref name="time"/>; <paramref name="instruction"/> is the pipeline's new message.</summary>
        public CalibrationFlowEvents Reset(double time, string instruction)
        {
            _now = time;
            _state = CalibrationState.WaitingForTPose;
            _stepMessage = instruction ?? string.Empty;
            _confirmedAt = double.NegativeInfinity;
            return CalibrationFlowEvents.Reset;
        }

        private void Confirm(double time, string message)
        {
            _confirmedAt = time;
            _confirmation = message;
        }
    }
}
