using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// How a clip is expressed, read from its motion: which way is up (<see cref="UprightTurn"/>) and whether its sides are
    /// the right way round (<see cref="LooksMirrored"/>). The simulator stands a clip up and mirrors it back before wearing it
    /// (<see cref="SessionSimulator.Upright"/>, <see cref="SessionSimulator.Mirrored"/>); <c>avatargo bvh info</c> prints both.
    /// </summary>
    public static class ClipConventions
    {
        /// <summary>
        /// The turn that would stand <paramref name="clip"/> up (<see cref="SessionSimulator.Upright"/>, which gives the rule):
        /// the identity for a clip whose up is +Y or whose frames disagree about their up.
        /// </summary>
        public static Quaternion UprightTurn(BvhClip clip, HumanoidMap map)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (map == null) throw new ArgumentNullException(nameof(map));
            Skeleton s = clip.Skeleton;
            var local = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            int head = map[HumanoidBone.Head], left = map[HumanoidBone.LeftFoot], right = map[HumanoidBone.RightFoot];
            Vector3 sum = Vector3.Zero;
            int step = Math.Max(1, clip.FrameCount / 200);
            for (int f = 0; f < clip.FrameCount; f += step)
            {
                clip.GetWorldPoses(f, local, world);
                Vector3 up = world[head].Position - 0.5f * (world[left].Position + world[right].Position);
                if (up.LengthSquared() > 1e-12f) sum += Vector3.Normalize(up);
            }
            int samples = (clip.FrameCount + step - 1) / step;
            Vector3 mean = sum / Math.Max(1, samples);
            if (mean.Y >= 0.5f || mean.Length() < 0.8f) return Quaternion.Identity;
            Vector3 direction = Vector3.Normalize(mean);
            Vector3 axis = Vector3.Zero;
            foreach (Vector3 candidate in new[] { Vector3.UnitX, -Vector3.UnitX, -Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitZ })
                if (Vector3.Dot(direction, candidate) > 0.906f) axis = candidate; // within 25°
            if (axis == Vector3.Zero) return Quaternion.Identity;
            // A half turn about X for -Y; otherwise the quarter turn from the axis to +Y.
            return axis == -Vector3.UnitY ? Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI) : Rotations.FromTo(axis, Vector3.UnitY);
        }

        /// <summary>
        /// Whether <paramref name="clip"/>'s knees bend backward in at least <see cref="MirroredMinimumBends"/> bent frames
        /// and twice as many as they bend forward (<see cref="CountKneeBends"/>, whose counts are returned): its joints named
        /// Left are on the body's right.
        /// </summary>
        public static bool LooksMirrored(BvhClip clip, HumanoidMap map, out int forward, out int backward)
        {
            CountKneeBends(clip, map, out forward, out backward);
            return backward >= MirroredMinimumBends && backward >= 2 * forward;
        }

        /// <summary>The fewest backward knee bends that make a clip look mirrored (10): a few frames of a hyperextended knee do not.</summary>
        public const int MirroredMinimumBends = 10;

        /// <summary>
        /// Counts, over every frame of <paramref name="clip"/> and both knees bent 20° or more, the knees that bend forward and
        /// those that bend backward: the knee's hinge axis (the thigh crossed with the shin) against the hip line (left to
        /// right hip); a hinge axis more than 60° from the hip line counts neither way (<see cref="KneeBend.Direction"/>). It reads the legs and the pelvis only,
        /// so a trunk folded forward or a clip lying down changes nothing, nor do the rest pose, the bones' axes or the up axis.
        /// </summary>
        public static void CountKneeBends(BvhClip clip, HumanoidMap map, out int forward, out int backward)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (map == null) throw new ArgumentNullException(nameof(map));
            forward = backward = 0;
            Skeleton s = clip.Skeleton;
            var local = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                clip.GetWorldPoses(f, local, world);
                Vector3 leftHip = world[map[HumanoidBone.LeftUpperLeg]].Position, rightHip = world[map[HumanoidBone.RightUpperLeg]].Position;
                Vector3 hipLine = rightHip - leftHip;
                if (!(hipLine.LengthSquared() > 1e-12f)) continue;
                hipLine = Vector3.Normalize(hipLine);
                for (int side = 0; side < 2; side++)
                {
                    BodySide body = side == 0 ? BodySide.Left : BodySide.Right;
                    Vector3 hip = side == 0 ? leftHip : rightHip;
                    Vector3 knee = world[map[HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, body)]].Position;
                    Vector3 ankle = world[map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, body)]].Position;
                    int bend = KneeBend.Direction(hip, knee, ankle, hipLine);
                    if (bend > 0) forward++;
                    else if (bend < 0) backward++;
                }
            }
        }
    }
}
