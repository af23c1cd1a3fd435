using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>Settings of <see cref="SessionSimulator"/>.</summary>
    public sealed class SimulationOptions
    {
        /// <summary>Frame rate of the session, in Hz (90).</summary>
        public float Rate { get; set; } = 90f;

        /// <summary>Seed for mountings, noise and the starting place (1).</summary>
        public int Seed { get; set; } = 1;

        /// <summary>Standard deviation of the position noise per coordinate, in metres (1 mm).</summary>
        public float PositionNoise { get; set; } = 0.001f;

        /// <summary>Standard deviation of the rotation noise, in degrees (0.1°).</summary>
        public float RotationNoiseDegrees { get; set; } = 0.1f;

        /// <summary>The device mountings; null draws them from <see cref="Seed"/> (<see cref="DeviceMountings.Sample"/>).</summary>
        public DeviceMountings Mountings { get; set; }

        /// <summary>
        /// The controller the wearer holds in both hands (its handle's radius decides where it sits in the palm); null for a
        /// generic handle of <see cref="VirtualDeviceRig.DefaultHandleRadius"/>. Evaluate with the same profile.
        /// </summary>
        public ControllerProfile Controller { get; set; }

        /// <summary>
        /// How far from the shown avatar the wearer ends the walk-in, in the avatar's frame (x right, y up, z forward),
        /// in metres (none: a perfect walk-in). Only x and z are used: the wearer stands on the floor, so y is ignored.
        /// </summary>
        public Vector3 Misalignment { get; set; }

        /// <summary>How much the wearer's facing differs from the avatar's after the walk-in, in degrees (0).</summary>
        public float MisalignmentYawDegrees { get; set; }

        /// <summary>Seconds standing in T-pose before the first trigger press (1.5).</summary>
        public float TPoseSeconds { get; set; } = 1.5f;

        /// <summary>Seconds walking into the avatar and holding still before the second press (2.5).</summary>
        public float WalkInSeconds { get; set; } = 2.5f;

        /// <summary>
        /// Seconds of the refinement exercise (<see cref="RefinementExercise"/>: arm circles, reaches, squats) performed in
        /// the T-pose right after the walk-in press, before the blend into the clip (0: none).
        /// </summary>
        public float ExerciseSeconds { get; set; }

        /// <summary>Seconds blending from the T-pose into the clip's first frame (1).</summary>
        public float BlendSeconds { get; set; } = 1f;

        /// <summary>
        /// Whether a clip recorded with another axis up (a Z-up export) is stood up before simulating
        /// (<see cref="SessionSimulator.Upright"/>; default true). False simulates the clip as it is, +Y up as BVH defines it.
        /// </summary>
        public bool StandClipUp { get; set; } = true;

        /// <summary>
        /// Whether a clip whose knees bend backward (written in a left-handed frame, or its sides named the wrong way round)
        /// is mirrored left to right before simulating (<see cref="SessionSimulator.Mirrored"/>; default true). False
        /// simulates every clip as it is.
        /// </summary>
        public bool MirrorBackwardClip { get; set; } = true;
    }
}
