using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Whether the wearer really stands in a T-pose, from the window averages of the devices
    /// <see cref="DeviceIdentifier"/> chose, and where the avatar is shown: every check has its own
    /// <see cref="CalibrationError"/> so the wearer is told what to change. The body plane is fitted through all six
    /// devices by orthogonal least squares (<see cref="BodyPlane"/>), so any facing direction and any place in the play
    /// area works. Thresholds suit adults; see Documentation~/calibration.md.
    /// </summary>
    public sealed class TPoseValidator
    {
        private readonly CalibrationSettings _settings;

        /// <summary>Creates a validator with these settings.</summary>
        public TPoseValidator(CalibrationSettings settings) => _settings = settings ?? throw new ArgumentNullException(nameof(settings));

        /// <summary>Every chosen device was still through the window, else <see cref="CalibrationError.DevicesMoving"/> (the detail names the first that moved).</summary>
        public CalibrationError CheckStill(in DeviceSelection selection, ReadOnlySpan<WindowAverage> averages, out int moving)
        {
            for (int i = 0; i < 6; i++)
                if (!averages[selection[i]].IsStill)
                {
                    moving = selection[i];
                    return CalibrationError.DevicesMoving;
                }
            moving = -1;
            return CalibrationError.None;
        }

        /// <summary>
        /// The head is upright (the HMD's up within 25° of vertical; else <see cref="CalibrationError.HeadNotUpright"/>) and the
        /// hands are spread (at least 0.7 × eye height apart horizontally; else <see cref="CalibrationError.ArmsNotSpread"/>).
        /// </summary>
        public CalibrationError CheckPosture(in DeviceSelection selection, ReadOnlySpan<WindowAverage> averages, out string detail)
        {
            detail = null;
            Quaternion head = averages[selection.Hmd].Mean.Rotation;
            float tilt = Vectors.AngleDegrees(Vector3.Transform(Vector3.UnitY, head), Vector3.UnitY);
            if (tilt > 25f)
            {
                detail = $"the headset tilted {tilt:0}°";
                return CalibrationError.HeadNotUpright;
            }
            float spread = Vectors.HorizontalDistance(averages[selection.ControllerA].Position, averages[selection.ControllerB].Position);
            if (spread < 0.7f * selection.EyeHeight)
            {
                detail = $"hands {spread:0.00} m apart";
                return CalibrationError.ArmsNotSpread;
            }
            return CalibrationError.None;
        }

        /// <summary>
        /// Fits the body plane through the six devices: it must be vertical (|normal.y| ≤ 0.35), face within 45° of the way
        /// the HMD looks, and be flat (RMS distance ≤ 15 cm); else <see cref="CalibrationError.NotFacingPlane"/>.
        /// <paramref name="forward"/> is then the wearer's horizontal facing (the plane's normal).
        /// </summary>
        public CalibrationError FitBodyPlane(in DeviceSelection selection, ReadOnlySpan<WindowAverage> averages, out Vector3 forward) =>
            FitBodyPlane(selection, averages, out forward, out _);

        /// <summary>As <see cref="FitBodyPlane(in DeviceSelection, ReadOnlySpan{WindowAverage}, out Vector3)"/>, with which test failed and by how much.</summary>
        public CalibrationError FitBodyPlane(in DeviceSelection selection, ReadOnlySpan<WindowAverage> averages, out Vector3 forward, out string detail)
        {
            forward = Vector3.UnitZ;
            detail = null;
            Vector3 look = Vectors.ProjectOnPlane(Vector3.Transform(Vector3.UnitZ, averages[selection.Hmd].Mean.Rotation), Vector3.UnitY);
            Span<Vector3> points = stackalloc Vector3[6];
            for (int i = 0; i < 6; i++) points[i] = averages[selection[i]].Position;
            BodyPlane plane = BodyPlane.Fit(points, look);
            var facing = new Vector3(plane.Normal.X, 0f, plane.Normal.Z);
            if (Math.Abs(plane.Normal.Y) > 0.35f || facing.LengthSquared() < 1e-6f)
            {
                // A seated wearer (the feet forward) or one bending over: the devices do not stand in a vertical plane.
                detail = $"the devices' plane leans {MathF.Asin(Math.Min(1f, Math.Abs(plane.Normal.Y))) * Rotations.Rad2Deg:0}° from vertical";
                return CalibrationError.NotFacingPlane;
            }
            float away = Vectors.AngleDegrees(facing, look);
            if (away > 45f)
            {
                detail = $"the body faces {away:0}° away from where the headset looks";
                return CalibrationError.NotFacingPlane;
            }
            if (plane.RmsDistance > 0.15f)
            {
                detail = $"the devices lie {plane.RmsDistance:0.00} m (RMS) off one plane";
                return CalibrationError.NotFacingPlane;
            }
            forward = Vector3.Normalize(facing);
            return CalibrationError.None;
        }

        /// <summary>
        /// With the roles known: the hands at shoulder height (0.75–1.02 × eye height, within 15 cm of each other; else
        /// <see cref="CalibrationError.ArmsNotLevel"/>), the foot trackers within 30 cm of the floor (else
        /// <see cref="CalibrationError.FeetNotOnFloor"/>) and the pelvis tracker at least 25 cm above the feet and 25 cm
        /// below the HMD, and horizontally nearer the body's axis (midway between the HMD and the feet) than
        /// <see cref="PelvisOffAxisOfHandReach"/> of the nearer hand's distance from it (else
        /// <see cref="CalibrationError.PelvisNotBetweenHeadAndFeet"/>: a tracker held in a hand is not the pelvis).
        /// </summary>
        public CalibrationError CheckLevels(PerRole<int> roles, ReadOnlySpan<WindowAverage> averages, float floor, float eyeHeight, out string detail)
        {
            if (roles == null) throw new ArgumentNullException(nameof(roles));
            detail = null;
            float lh = averages[roles[DeviceRole.LeftHand]].Position.Y - floor, rh = averages[roles[DeviceRole.RightHand]].Position.Y - floor;
            if (Math.Abs(lh - rh) > 0.15f || Math.Min(lh, rh) < 0.75f * eyeHeight || Math.Max(lh, rh) > 1.02f * eyeHeight)
            {
                detail = $"hands at {lh:0.00} m and {rh:0.00} m, eyes at {eyeHeight:0.00} m";
                return CalibrationError.ArmsNotLevel;
            }
            float feetTop = Math.Max(averages[roles[DeviceRole.LeftFoot]].Position.Y, averages[roles[DeviceRole.RightFoot]].Position.Y);
            if (feetTop - floor > 0.3f)
            {
                detail = $"{feetTop - floor:0.00} m above the floor";
                return CalibrationError.FeetNotOnFloor;
            }
            Vector3 pelvisAt = averages[roles[DeviceRole.Pelvis]].Position, head = averages[roles[DeviceRole.Head]].Position;
            float pelvis = pelvisAt.Y;
            if (pelvis < feetTop + 0.25f || pelvis > head.Y - 0.25f)
            {
                detail = $"the waist tracker at {pelvis - floor:0.00} m, the feet's at {feetTop - floor:0.00} m, eyes at {eyeHeight:0.00} m";
                return CalibrationError.PelvisNotBetweenHeadAndFeet;
            }
            // Horizontally: a tracker held out in a hand passes every height check (hands lowered toward the waist).
            Vector3 axis = 0.5f * (head + 0.5f * (averages[roles[DeviceRole.LeftFoot]].Position + averages[roles[DeviceRole.RightFoot]].Position));
            float pelvisOff = Vectors.HorizontalDistance(pelvisAt, axis);
            float handOff = Math.Min(Vectors.HorizontalDistance(averages[roles[DeviceRole.LeftHand]].Position, axis), Vectors.HorizontalDistance(averages[roles[DeviceRole.RightHand]].Position, axis));
            if (pelvisOff > PelvisOffAxisOfHandReach * handOff)
            {
                detail = $"the waist tracker {pelvisOff:0.00} m from the body's axis, the hands {handOff:0.00} m";
                return CalibrationError.PelvisNotBetweenHeadAndFeet;
            }
            return CalibrationError.None;
        }

        /// <summary>
        /// How far from the body's axis the pelvis tracker may be, as a share of the nearer hand's distance from it in the
        /// T-pose (0.6): a tracker on the lower back or the hip sits 0.1–0.25 m from it, a hand 0.5–0.9 m (a child's to a tall
        /// adult's arms spread), so the share keeps both apart at any size.
        /// </summary>
        public const float PelvisOffAxisOfHandReach = 0.6f;

        /// <summary>
        /// Where the avatar is shown: on the floor between the ankles (the foot trackers' midpoint moved back by
        /// <see cref="CalibrationSettings.FootTrackerForward"/>, as they sit on the insteps), facing the wearer's way.
        /// </summary>
        public RigidPose Placement(PerRole<int> roles, ReadOnlySpan<WindowAverage> averages, float floor, Vector3 forward)
        {
            if (roles == null) throw new ArgumentNullException(nameof(roles));
            Vector3 feet = (averages[roles[DeviceRole.LeftFoot]].Position + averages[roles[DeviceRole.RightFoot]].Position) * 0.5f - forward * _settings.FootTrackerForward;
            return new RigidPose(new Vector3(feet.X, floor, feet.Z), Rotations.LookRotation(forward, Vector3.UnitY));
        }
    }
}
