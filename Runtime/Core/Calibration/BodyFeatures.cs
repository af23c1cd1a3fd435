using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// What one still T-pose window shows of the wearer's proportions, from the devices: the eye height, the hips joint's
    /// height (the pelvis tracker less its nominal strap offset), each controller's reach from the body's midline (the
    /// HMD) along the line between the controllers, and each controller's height. In metres, above the floor. Independent
    /// of where the wearer stands and which way they face. An immutable value.
    /// </summary>
    public readonly struct BodyFeatures
    {
        /// <summary>Eye height (the HMD).</summary>
        public readonly float Eye;

        /// <summary>Hips joint height.</summary>
        public readonly float Hips;

        /// <summary>The left controller's horizontal distance from the midline along the shoulder line.</summary>
        public readonly float LeftReach;

        /// <summary>The right controller's horizontal distance from the midline along the shoulder line.</summary>
        public readonly float RightReach;

        /// <summary>The left controller's height.</summary>
        public readonly float LeftGripHeight;

        /// <summary>The right controller's height.</summary>
        public readonly float RightGripHeight;

        /// <summary>Creates features.</summary>
        public BodyFeatures(float eye, float hips, float leftReach, float rightReach, float leftGripHeight, float rightGripHeight)
        {
            Eye = eye;
            Hips = hips;
            LeftReach = leftReach;
            RightReach = rightReach;
            LeftGripHeight = leftGripHeight;
            RightGripHeight = rightGripHeight;
        }

        /// <summary>One side's reach.</summary>
        public float Reach(BodySide side) => side == BodySide.Left ? LeftReach : RightReach;

        /// <summary>One side's grip height.</summary>
        public float GripHeight(BodySide side) => side == BodySide.Left ? LeftGripHeight : RightGripHeight;

        /// <summary>True when every number is finite.</summary>
        public bool IsFinite => Vectors.IsFinite(Eye) && Vectors.IsFinite(Hips) && Vectors.IsFinite(LeftReach) && Vectors.IsFinite(RightReach)
            && Vectors.IsFinite(LeftGripHeight) && Vectors.IsFinite(RightGripHeight);

        /// <summary>
        /// The features of a T-pose from its devices' window averages (positions in tracking space) and the floor height;
        /// the pelvis tracker is taken <paramref name="pelvisAboveHips"/> above the hips joint.
        /// </summary>
        public static BodyFeatures FromDevices(Vector3 hmd, Vector3 pelvis, Vector3 leftController, Vector3 rightController, float floor, float pelvisAboveHips)
        {
            Vector3 across = rightController - leftController;
            across.Y = 0f;
            Vector3 right = Vectors.NormalizeOr(across, Vector3.UnitX);
            return new BodyFeatures(hmd.Y - floor, pelvis.Y - floor - pelvisAboveHips,
                Math.Abs(Vector3.Dot(leftController - hmd, right)), Math.Abs(Vector3.Dot(rightController - hmd, right)),
                leftController.Y - floor, rightController.Y - floor);
        }

        /// <summary>The mean of two windows' features.</summary>
        public static BodyFeatures Mean(in BodyFeatures a, in BodyFeatures b) => new BodyFeatures(
            (a.Eye + b.Eye) * 0.5f, (a.Hips + b.Hips) * 0.5f, (a.LeftReach + b.LeftReach) * 0.5f, (a.RightReach + b.RightReach) * 0.5f,
            (a.LeftGripHeight + b.LeftGripHeight) * 0.5f, (a.RightGripHeight + b.RightGripHeight) * 0.5f);

        /// <summary>The largest difference between two windows' features (how repeatable the T-pose was).</summary>
        public static float Difference(in BodyFeatures a, in BodyFeatures b) => Math.Max(Math.Max(Math.Abs(a.Eye - b.Eye), Math.Abs(a.Hips - b.Hips)),
            Math.Max(Math.Max(Math.Abs(a.LeftReach - b.LeftReach), Math.Abs(a.RightReach - b.RightReach)),
                Math.Max(Math.Abs(a.LeftGripHeight - b.LeftGripHeight), Math.Abs(a.RightGripHeight - b.RightGripHeight))));
    }
}
