namespace AvatarGo.Core
{
    /// <summary>What to tell the wearer for each <see cref="CalibrationError"/>.</summary>
    public static class CalibrationMessages
    {
        /// <summary>What the wearer is asked to do in <paramref name="state"/> when nothing went wrong.</summary>
        public static string Instruction(CalibrationState state)
        {
            switch (state)
            {
                case CalibrationState.WaitingForTPose: return "Stand in a T-pose and press a trigger.";
                case CalibrationState.WalkIn: return "Walk into the avatar, match its pose, and press a trigger again.";
                default: return "Calibrated.";
            }
        }

        /// <summary>A short instruction for the wearer after <paramref name="error"/>.</summary>
        public static string For(CalibrationError error)
        {
            switch (error)
            {
                case CalibrationError.None: return "Calibrated.";
                case CalibrationError.DeviceMissing: return "A device is missing: connect the headset, both controllers and three trackers (waist and both feet).";
                case CalibrationError.DeviceNotTracked: return "A device is not being tracked: make sure every tracker and controller is visible to the base stations.";
                case CalibrationError.DevicesMoving: return "Hold still for a moment while pressing the trigger.";
                case CalibrationError.ArmsNotLevel: return "Raise both arms straight out to the sides at shoulder height.";
                case CalibrationError.ArmsNotSpread: return "Spread your arms wide, straight out to the sides.";
                case CalibrationError.HeadNotUpright: return "Keep your head upright and look straight ahead.";
                case CalibrationError.NotFacingPlane: return "Stand straight in a T-pose and look straight ahead, not to the side.";
                case CalibrationError.RoleConflict: return "Hold one controller in each hand and wear one tracker on each foot.";
                case CalibrationError.FeetNotOnFloor: return "Stand with both feet on the floor and the foot trackers on your feet.";
                case CalibrationError.PelvisNotBetweenHeadAndFeet: return "Wear the waist tracker on your lower back.";
                case CalibrationError.RuntimeRoleMismatch: return "A tracker's assigned role does not match where it is worn: check the tracker roles in your VR runtime.";
                case CalibrationError.WrongState: return "Start again from the T-pose.";
                case CalibrationError.NotInsideAvatar: return "Walk into the avatar until your eyes are where its eyes are, then press the trigger again.";
                case CalibrationError.AvatarScaleOutOfRange: return "This avatar cannot be scaled to you: its size is not a person's in any unit. Check the avatar's import scale.";
                default: return error.ToString();
            }
        }
    }
}
