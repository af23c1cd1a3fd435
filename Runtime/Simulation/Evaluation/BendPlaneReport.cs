using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// How far one knee or elbow bent in the wrong direction over a session: per frame, the signed angle about the limb's
    /// axis (hip to ankle, shoulder to wrist, the wearer's) from the wearer's bend direction to the avatar's (each the
    /// middle joint's offset from its own limb's axis, the avatar's seen square to the wearer's axis), in degrees in
    /// (-180, 180]. A knee bent backward is about 180° off; a frame
    /// beyond <see cref="FlippedDegrees"/> counts as flipped. Frames in which the wearer's limb is nearly straight (bent
    /// less than <see cref="MinBendDegrees"/>) have no bend direction to compare and are only counted.
    /// </summary>
    public sealed class BendPlaneReport
    {
        /// <summary>An error beyond this many degrees counts as a flipped frame (90°: bent more sideways than the right way).</summary>
        public const double FlippedDegrees = 90.0;

        /// <summary>
        /// The wearer's limb must bend at least this much (180° minus its interior angle) for a frame to count: 15°, where a
        /// knee is 4–6 cm (legs of 65–87 cm) and an elbow about 3 cm off the line between its neighbours. Below that the bend direction is within
        /// what mocap joint centres are sure of (1-2 cm): the shared Rigify clip's knees, never bent more than 12°, lean
        /// sideways and backward by a few degrees (hyperextended), which no solver that bends knees forward reproduces.
        /// </summary>
        public const double MinBendDegrees = 15.0;

        internal BendPlaneReport(HumanoidBone joint) => Joint = joint;

        /// <summary>The middle joint measured (LeftLowerLeg, RightLowerLeg, LeftLowerArm or RightLowerArm).</summary>
        public HumanoidBone Joint { get; }

        /// <summary>The signed angle error of every counted frame, in degrees (its median shows a bias to one side).</summary>
        public ErrorSeries SignedDegrees { get; } = new ErrorSeries();

        /// <summary>The size of the angle error of every counted frame, in degrees (median, p95, max).</summary>
        public ErrorSeries AbsoluteDegrees { get; } = new ErrorSeries();

        /// <summary>Counted frames whose error exceeds <see cref="FlippedDegrees"/>.</summary>
        public int FlippedFrames { get; internal set; }

        /// <summary>Frames left out because the wearer's limb was nearly straight.</summary>
        public int StraightFrames { get; internal set; }

        /// <summary>The share of counted frames that flipped, 0..1 (0 with no counted frame).</summary>
        public double FlippedShare => AbsoluteDegrees.Count == 0 ? 0.0 : FlippedFrames / (double)AbsoluteDegrees.Count;

        /// <summary>
        /// The signed bend-plane angle error of one frame, in degrees in (-180, 180]: about the wearer's limb axis
        /// (<paramref name="root"/> to <paramref name="end"/>), from the wearer's bend direction (<paramref name="middle"/>'s
        /// offset from that axis) to the avatar's (its middle joint's offset from its own limb axis). NaN when the wearer's
        /// limb bends less than <see cref="MinBendDegrees"/>; 180 when the avatar's limb is straight where the wearer's bends.
        /// The sign is right-handed about that axis on every limb, so it is mirror-handed: the same anatomical error (both
        /// elbows swivelled outward) reads positive on one side and negative on the other.
        /// </summary>
        public static double SignedAngleDegrees(Vector3 root, Vector3 middle, Vector3 end, Vector3 avatarRoot, Vector3 avatarMiddle, Vector3 avatarEnd)
        {
            return BendsEnough(root, middle, end) ? SignedAngleOfBentDegrees(root, middle, end, avatarRoot, avatarMiddle, avatarEnd) : double.NaN;
        }

        // SignedAngleDegrees for a wearer's limb already known to bend enough (the evaluator checks that first).
        internal static double SignedAngleOfBentDegrees(Vector3 root, Vector3 middle, Vector3 end, Vector3 avatarRoot, Vector3 avatarMiddle, Vector3 avatarEnd)
        {
            Vector3 axis = Vectors.NormalizeOr(end - root, Vector3.UnitY);
            Vector3 truthBend = Vectors.ProjectOnPlane(middle - root, axis);
            // The avatar's bend direction off its own limb axis, then seen about the wearer's: a shoulder a few
            // centimetres off tilts the avatar's axis, which must not read as swivel.
            Vector3 avatarAxis = Vectors.NormalizeOr(avatarEnd - avatarRoot, axis);
            Vector3 avatarBend = Vectors.ProjectOnPlane(Vectors.ProjectOnPlane(avatarMiddle - avatarRoot, avatarAxis), axis);
            if (avatarBend.LengthSquared() < 1e-12f) return 180.0;
            return Math.Atan2(Vector3.Dot(axis, Vector3.Cross(truthBend, avatarBend)), Vector3.Dot(truthBend, avatarBend)) * (180.0 / Math.PI);
        }

        /// <summary>True when the wearer's limb (root, middle, end joint) bends at least <see cref="MinBendDegrees"/>.</summary>
        public static bool BendsEnough(Vector3 root, Vector3 middle, Vector3 end) =>
            180.0 - Vectors.AngleDegrees(root - middle, end - middle) >= MinBendDegrees;

        // One counted frame; NaN or infinity (a non-finite avatar) goes to the series' InvalidCount and is not a flip.
        internal void Add(double signedDegrees)
        {
            SignedDegrees.Add(signedDegrees);
            AbsoluteDegrees.Add(Math.Abs(signedDegrees));
            if (Math.Abs(signedDegrees) > FlippedDegrees) FlippedFrames++;
        }
    }
}
