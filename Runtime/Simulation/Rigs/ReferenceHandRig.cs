using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// A humanoid rig of two forearms and hands built in code, for tests, tools and previews when no avatar's hand is
    /// available: forearm, hand, five fingers of three joints plus an end site each, with adult hand
    /// proportions (wrist to middle knuckle 9.5 cm at scale 1; phalanx lengths typical of an adult
    /// hand, rounded to 1 mm). The geometry is fixed; what varies is the rig's convention: the local axis each bone points along,
    /// a twist of every bone about that axis, and the orientation of the whole arm in the rest pose. A finger solver
    /// that reads the closing axis from geometry must give the same grip for every convention.
    /// </summary>
    public static class ReferenceHandRig
    {
        // Knuckle (proximal joint) positions in a canonical right-hand frame: x along the hand (wrist → middle knuckle),
        // y out of the back of the hand (the palm faces −y), z across toward the thumb side. Metres.
        private static readonly Vector3[] Knuckles =
        {
            new Vector3(0.025f, -0.012f, 0.022f), // thumb base (Unity's ThumbProximal is the thumb's first bone)
            new Vector3(0.090f, 0f, 0.023f),
            new Vector3(0.095f, 0f, 0.006f),
            new Vector3(0.091f, 0f, -0.011f),
            new Vector3(0.083f, -0.002f, -0.027f),
        };

        // Lengths of the proximal and intermediate phalanges and of the distal one (distal joint → fingertip), metres.
        private static readonly float[][] Lengths =
        {
            new[] { 0.040f, 0.032f, 0.026f },
            new[] { 0.040f, 0.024f, 0.019f },
            new[] { 0.045f, 0.028f, 0.020f },
            new[] { 0.042f, 0.026f, 0.019f },
            new[] { 0.033f, 0.018f, 0.017f },
        };

        // Finger directions in the canonical frame (the rest pose is a flat hand, the thumb spread forward and down).
        private static readonly Vector3[] Directions =
        {
            Vector3.Normalize(new Vector3(1f, -0.45f, 0.8f)),
            Vector3.Normalize(new Vector3(1f, 0f, 0.06f)),
            Vector3.UnitX,
            Vector3.Normalize(new Vector3(1f, 0f, -0.06f)),
            Vector3.Normalize(new Vector3(1f, 0f, -0.12f)),
        };

        // The finger names used in the joint names (L_Index1 … R_Little3, L_Index_End …).
        private static readonly string[] FingerNames = { "Thumb", "Index", "Middle", "Ring", "Little" };

        /// <summary>
        /// A rig with both hands. <paramref name="boneAxis"/> is the local axis every bone points along (e.g. +Y as
        /// Mixamo, +X or −X as other exporters); <paramref name="seed"/> turns each bone by a random twist about
        /// that axis (0: none); <paramref name="armRotation"/> orients the whole rest pose (identity: T-pose with
        /// the palms down).
        /// Joints are named <c>L_Hand</c>, <c>L_Index1</c> … <c>L_Index3</c>, <c>L_Index_End</c> (R_ for the right side).
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The scale is not positive and finite, the axis is zero or not
        /// finite, or the rotation is not a unit quaternion.</exception>
        public static HumanoidMap Build(float scale, Vector3 boneAxis, int seed, Quaternion armRotation)
        {
            if (!(scale > 0f) || !Vectors.IsFinite(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "Scale must be positive and finite.");
            if (!Vectors.IsFinite(boneAxis) || boneAxis.LengthSquared() < 1e-12f) throw new ArgumentOutOfRangeException(nameof(boneAxis), boneAxis, "The bone axis must be a finite, non-zero vector.");
            if (!Rotations.IsUnit(armRotation)) throw new ArgumentOutOfRangeException(nameof(armRotation), armRotation, "The arm rotation must be a unit quaternion.");
            var names = new List<string>();
            var parents = new List<int>();
            var world = new List<RigidPose>();
            var ends = new List<bool>();
            var bones = new List<KeyValuePair<HumanoidBone, string>>();
            var rng = new Random(seed);
            boneAxis = Vector3.Normalize(boneAxis);

            RigidPose Frame(Vector3 position, Vector3 direction)
            {
                Quaternion q = Rotations.FromTo(boneAxis, direction);
                if (seed != 0) q = q * Quaternion.CreateFromAxisAngle(boneAxis, (float)(rng.NextDouble() * 2 * Math.PI));
                return new RigidPose(position, Quaternion.Normalize(armRotation * q));
            }

            int Add(string name, int parent, RigidPose w, bool end)
            {
                names.Add(name); parents.Add(parent); world.Add(w); ends.Add(end);
                return names.Count - 1;
            }

            names.Add("Root"); parents.Add(-1); world.Add(RigidPose.Identity); ends.Add(false);
            for (int side = 0; side < 2; side++)
            {
                bool left = side == 0;
                string prefix = left ? "L_" : "R_";
                // Canonical right hand: along +X, palm −Y, thumb +Z (Unity's T-pose, facing +Z). Left: mirror x.
                // Canon: the mirror for the left side (directions before the arm rotation, which Frame applies);
                // Map: a canonical offset to world (mirror, then the arm rotation).
                Vector3 Canon(Vector3 v) => left ? new Vector3(-v.X, v.Y, v.Z) : v;
                Vector3 Map(Vector3 v) => Vector3.Transform(Canon(v), armRotation);
                Vector3 elbow = Map(new Vector3(0.45f, 1.4f, 0f));
                int arm = Add(prefix + "ForeArm", 0, Frame(elbow, Canon(Vector3.UnitX)), false);
                int hand = Add(prefix + "Hand", arm, Frame(elbow + Map(new Vector3(0.25f * scale, 0f, 0f)), Canon(Vector3.UnitX)), false);
                bones.Add(new KeyValuePair<HumanoidBone, string>(left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm, prefix + "ForeArm"));
                bones.Add(new KeyValuePair<HumanoidBone, string>(left ? HumanoidBone.LeftHand : HumanoidBone.RightHand, prefix + "Hand"));
                Vector3 wristWorld = world[hand].Position;
                for (int f = 0; f < 5; f++)
                {
                    Vector3 dir = Canon(Directions[f]);
                    Vector3 p = wristWorld + Map(Knuckles[f] * scale);
                    int parent = hand;
                    for (int k = 0; k < 3; k++)
                    {
                        string name = prefix + FingerNames[f] + (k + 1);
                        parent = Add(name, parent, Frame(p, dir), false);
                        bones.Add(new KeyValuePair<HumanoidBone, string>(HumanoidBones.Finger(left ? BodySide.Left : BodySide.Right, (Finger)f, (Phalanx)k), name));
                        p += Map(Directions[f] * (Lengths[f][k] * scale));
                    }
                    Add(prefix + FingerNames[f] + "_End", parent, new RigidPose(p, world[parent].Rotation), true);
                }
            }

            var local = new RigidPose[names.Count];
            for (int i = 0; i < local.Length; i++)
                local[i] = parents[i] < 0 ? world[i] : world[i].RelativeTo(world[parents[i]]);
            var skeleton = new Skeleton(names, parents, local, ends);
            return new HumanoidMap(skeleton, bones);
        }

        /// <summary>The default rig: bones along +Y (Mixamo's convention), no twist, T-pose, palms down.</summary>
        public static HumanoidMap Build(float scale = 1f) => Build(scale, Vector3.UnitY, 0, Quaternion.Identity);
    }
}
