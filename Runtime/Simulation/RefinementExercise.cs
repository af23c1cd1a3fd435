using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// The guided exercise of the refinement from motion (<see cref="ProportionRefinement"/>), performed by a simulated
    /// wearer from the T-pose they walked into: arm circles with the arms stretched, reaches with the stretched arms to the
    /// front and overhead, then squats (feet kept where they stand, back upright). Built from the wearer's own skeleton by
    /// turning its shoulder, hip, knee and ankle joints in the world (no clip is copied), so it works in any rest convention.
    /// </summary>
    public static class RefinementExercise
    {
        /// <summary>
        /// The wearer's pose at <paramref name="t"/> (0…1 through the exercise) into <paramref name="pose"/>, starting and
        /// ending in the T-pose <paramref name="tpose"/> (local transforms of <paramref name="map"/>'s skeleton).
        /// </summary>
        public static void Pose(HumanoidMap map, RigidPose[] tpose, float t, SkeletonPose pose)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (tpose == null) throw new ArgumentNullException(nameof(tpose));
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            Array.Copy(tpose, pose.Local, tpose.Length);
            pose.UpdateWorld();
            RigidPose[] w = pose.World;
            Vector3 lHip = w[map[HumanoidBone.LeftUpperLeg]].Position, rHip = w[map[HumanoidBone.RightUpperLeg]].Position;
            Vector3 right = rHip - lHip;
            right.Y = 0f;
            right = Vectors.NormalizeOr(right, Vector3.UnitX);
            Vector3 up = Vector3.UnitY, forward = Vector3.Cross(right, up);
            t = Math.Min(1f, Math.Max(0f, t));
            if (t < 0.6f) Arms(map, pose, t / 0.6f, right, up, forward);
            else Squats(map, pose, (t - 0.6f) / 0.4f, right, up, forward);
            pose.UpdateWorld();
        }

        // Two circles (0 … 0.5) with the stretched arms, then a reach to the front and one overhead (0.5 … 1).
        private static void Arms(HumanoidMap map, SkeletonPose pose, float u, Vector3 right, Vector3 up, Vector3 forward)
        {
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Vector3 lateral = side == BodySide.Left ? -right : right;
                Vector3 direction;
                if (u < 0.5f)
                {
                    float c = u / 0.5f;
                    float radius = 0.7f * (float)Math.Sin(Math.PI * c); // in and out of the circles smoothly
                    double phi = 4.0 * Math.PI * c;
                    direction = lateral + radius * ((float)Math.Cos(phi) * up + (float)Math.Sin(phi) * forward);
                }
                else
                {
                    float c = (u - 0.5f) / 0.5f;
                    // lateral -> front -> lateral -> overhead -> lateral
                    float a = (float)Math.Sin(Math.PI * (c < 0.5f ? c / 0.5f : (c - 0.5f) / 0.5f));
                    Vector3 goal = c < 0.5f ? forward + 0.15f * lateral : up + 0.3f * lateral;
                    direction = Vector3.Lerp(lateral, Vectors.NormalizeOr(goal, up), a);
                }
                int shoulder = map[HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side)];
                Quaternion turn = Rotations.FromTo(lateral, Vectors.NormalizeOr(direction, lateral));
                pose.SetWorldRotation(shoulder, Quaternion.Normalize(turn * pose.World[shoulder].Rotation));
            }
        }

        // Two squats to 75° of hip flexion: thighs forward, shins back by the same angle, feet flat, the body lowered so
        // that the ankles stay where they stood.
        private static void Squats(HumanoidMap map, SkeletonPose pose, float u, Vector3 right, Vector3 up, Vector3 forward)
        {
            float s = (float)Math.Sin(2.0 * Math.PI * u);
            float degrees = 75f * s * s;
            int lAnkle = map[HumanoidBone.LeftFoot], rAnkle = map[HumanoidBone.RightFoot];
            Vector3 ankles0 = 0.5f * (pose.World[lAnkle].Position + pose.World[rAnkle].Position);
            Quaternion flex = Rotations.FromTo(-up, Vectors.NormalizeOr(-up * (float)Math.Cos(degrees * Math.PI / 180) + forward * (float)Math.Sin(degrees * Math.PI / 180), -up));
            Quaternion back = Quaternion.Conjugate(flex);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int hip = map[HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side)];
                int knee = map[HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side)];
                int ankle = map[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)];
                Quaternion thigh = pose.World[hip].Rotation, shin = pose.World[knee].Rotation, foot = pose.World[ankle].Rotation;
                pose.SetWorldRotation(hip, Quaternion.Normalize(flex * thigh));
                pose.UpdateWorld();
                pose.SetWorldRotation(knee, Quaternion.Normalize(back * shin));
                pose.UpdateWorld();
                pose.SetWorldRotation(ankle, foot);
                pose.UpdateWorld();
            }
            pose.UpdateWorld();
            Vector3 ankles = 0.5f * (pose.World[lAnkle].Position + pose.World[rAnkle].Position);
            Skeleton sk = pose.Skeleton;
            for (int j = 0; j < sk.JointCount; j++)
                if (sk.GetParent(j) < 0) pose.Local[j] = new RigidPose(pose.Local[j].Position + (ankles0 - ankles), pose.Local[j].Rotation);
        }
    }
}
