using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text.RegularExpressions;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The same motion on a skeleton built another way: twist joints inserted along the limbs, a floor-level root above the
    /// hips, joints dropped, or the whole clip mirrored left to right. Every variant is rebuilt from the clip's world poses:
    /// each joint of the new skeleton takes its world pose in every frame from the original's (its own, halfway along a
    /// bone, on the floor below the hips, or reflected), and its local poses follow from its new parent. A joint gets
    /// position channels where its source had them or where its translation from its parent changes over the clip.
    /// </summary>
    public static class Topology
    {
        // A joint of the rebuilt skeleton: its name, its parent's index in the new list, whether it is an End Site, the
        // original joint whose channel order it keeps (or -1), and its world pose from the original's world poses.
        private sealed class NewJoint
        {
            public string Name;
            public int Parent;
            public bool EndSite;
            public int Source = -1;
            public Func<RigidPose[], RigidPose> World;
        }

        /// <summary>The humanoid bones a twist joint follows, and the bone whose joint is the twist joint's child.</summary>
        public static readonly (HumanoidBone bone, HumanoidBone next, string twist)[] TwistedBones =
        {
            (HumanoidBone.LeftUpperArm, HumanoidBone.LeftLowerArm, "LeftArmTwist"),
            (HumanoidBone.LeftLowerArm, HumanoidBone.LeftHand, "LeftForeArmTwist"),
            (HumanoidBone.RightUpperArm, HumanoidBone.RightLowerArm, "RightArmTwist"),
            (HumanoidBone.RightLowerArm, HumanoidBone.RightHand, "RightForeArmTwist"),
            (HumanoidBone.LeftUpperLeg, HumanoidBone.LeftLowerLeg, "LeftUpLegTwist"),
            (HumanoidBone.LeftLowerLeg, HumanoidBone.LeftFoot, "LeftLegTwist"),
            (HumanoidBone.RightUpperLeg, HumanoidBone.RightLowerLeg, "RightUpLegTwist"),
            (HumanoidBone.RightLowerLeg, HumanoidBone.RightFoot, "RightLegTwist"),
        };

        /// <summary>The name of the floor-level root <see cref="WithFloorRoot"/> adds.</summary>
        public const string FloorRootName = "Root";

        /// <summary>
        /// <paramref name="clip"/> with a twist joint halfway along each upper arm, forearm, thigh and shin
        /// (<see cref="TwistedBones"/>): the bone's joint, then the twist joint with the same rotation, then the next joint
        /// (elbow, wrist, knee, ankle), which keeps its world pose. A hand that is an End Site (a rig without hand bones)
        /// stays the forearm's End Site: no twist joint goes before it.
        /// </summary>
        public static BvhClip WithTwistJoints(BvhClip clip)
        {
            Skeleton s = clip.Skeleton;
            HumanoidMap map = HumanoidNaming.Detect(s);
            var twistBefore = new Dictionary<int, (int bone, string name)>(); // the next joint -> the twisted bone's joint and the twist's name
            foreach (var (bone, next, twist) in TwistedBones)
            {
                int b = map[bone], c = map[next];
                if (s.IsEndSite(c)) continue; // a hand that is the forearm's End Site (Rigify's clip) stays its child
                if (s.GetParent(c) != b) throw new ArgumentException($"{s.GetName(c)} is not a child of {s.GetName(b)}.", nameof(clip));
                twistBefore[c] = (b, twist);
            }
            var joints = new List<NewJoint>();
            var index = new int[s.JointCount];
            for (int j = 0; j < s.JointCount; j++)
            {
                int parent = s.GetParent(j) < 0 ? -1 : index[s.GetParent(j)];
                if (twistBefore.TryGetValue(j, out var t))
                {
                    int bone = t.bone, child = j;
                    joints.Add(new NewJoint { Name = t.name, Parent = parent, Source = bone, World = w => new RigidPose(0.5f * (w[bone].Position + w[child].Position), w[bone].Rotation) });
                    parent = joints.Count - 1;
                }
                index[j] = joints.Count;
                joints.Add(Same(s, j, parent, s.GetName(j)));
            }
            return Rebuild(clip, joints);
        }

        /// <summary>
        /// <paramref name="clip"/> under a new root, <see cref="FloorRootName"/>, on the floor (y = 0) right below the hips
        /// in every frame, with the identity rotation; the hips become its child and keep their world pose.
        /// </summary>
        public static BvhClip WithFloorRoot(BvhClip clip)
        {
            Skeleton s = clip.Skeleton;
            int hips = HumanoidNaming.Detect(s)[HumanoidBone.Hips];
            var joints = new List<NewJoint> { new NewJoint { Name = FloorRootName, Parent = -1, World = w => RigidPose.FromPosition(new Vector3(w[hips].Position.X, 0f, w[hips].Position.Z)) } };
            for (int j = 0; j < s.JointCount; j++)
                joints.Add(Same(s, j, s.GetParent(j) < 0 ? 0 : s.GetParent(j) + 1, s.GetName(j)));
            return Rebuild(clip, joints);
        }

        /// <summary>
        /// <paramref name="clip"/> with a joint inserted above each named child: <c>name</c> hangs from the child's parent,
        /// with the parent's rotation, <c>along</c> of the way from the parent to the child (0: at the parent, as the CMU
        /// database's BVH conversion puts its LHipJoint and LowerBack), and the child hangs from it, keeping its world pose.
        /// </summary>
        public static BvhClip WithJointsAbove(BvhClip clip, params (string child, string name, float along)[] inserted) => WithJointsAbove(clip, false, inserted);

        /// <summary>
        /// As <see cref="WithJointsAbove(BvhClip, (string, string, float)[])"/>; with <paramref name="turning"/>, each inserted
        /// joint takes the rotation <c>along</c> of the way from the parent's to the child's, so it turns in the motion as a
        /// vertebra between two others would (UE5's spine_02, the CMU conversion's Neck1).
        /// </summary>
        public static BvhClip WithJointsAbove(BvhClip clip, bool turning, params (string child, string name, float along)[] inserted)
        {
            Skeleton s = clip.Skeleton;
            var joints = new List<NewJoint>();
            var index = new int[s.JointCount];
            for (int j = 0; j < s.JointCount; j++)
            {
                int parent = s.GetParent(j) < 0 ? -1 : index[s.GetParent(j)];
                foreach (var (child, name, along) in inserted)
                {
                    if (child != s.GetName(j)) continue;
                    int above = s.GetParent(j), below = j;
                    if (above < 0) throw new ArgumentException($"{child} is a root.", nameof(inserted));
                    joints.Add(new NewJoint
                    {
                        Name = name, Parent = parent, Source = above,
                        World = w => new RigidPose(Vector3.Lerp(w[above].Position, w[below].Position, along),
                            turning ? Quaternion.Normalize(Quaternion.Slerp(w[above].Rotation, w[below].Rotation, along)) : w[above].Rotation),
                    });
                    parent = joints.Count - 1;
                }
                index[j] = joints.Count;
                joints.Add(Same(s, j, parent, s.GetName(j)));
            }
            return Rebuild(clip, joints);
        }

        /// <summary>
        /// <paramref name="clip"/> with leaf joints added: each named <c>name</c>, hanging from <c>parent</c> at
        /// <c>offset</c> in the parent's frame with its rotation, carried with it in every frame (ears and hair on a head,
        /// a prop on a hand).
        /// </summary>
        public static BvhClip WithLeaves(BvhClip clip, params (string parent, string name, Vector3 offset)[] leaves)
        {
            Skeleton s = clip.Skeleton;
            var joints = new List<NewJoint>();
            for (int j = 0; j < s.JointCount; j++) joints.Add(Same(s, j, s.GetParent(j), s.GetName(j)));
            foreach (var (parent, name, offset) in leaves)
            {
                int p = s.IndexOf(parent);
                if (p < 0) throw new ArgumentException($"No joint {parent}.", nameof(leaves));
                joints.Add(new NewJoint { Name = name, Parent = p, Source = p, World = w => w[p] * new RigidPose(offset, Quaternion.Identity) });
            }
            return Rebuild(clip, joints);
        }

        /// <summary>
        /// <paramref name="clip"/> with each named joint hanging from another parent (3ds Max Biped's clavicles under the
        /// neck), every joint keeping its world pose in every frame; the joints are reordered so that parents come first.
        /// </summary>
        public static BvhClip Reparented(BvhClip clip, params (string joint, string parent)[] moves)
        {
            Skeleton s = clip.Skeleton;
            int ParentOf(int j)
            {
                foreach (var (joint, parent) in moves)
                    if (joint == s.GetName(j)) return s.IndexOf(parent) >= 0 ? s.IndexOf(parent) : throw new ArgumentException($"No joint {parent}.", nameof(moves));
                return s.GetParent(j);
            }
            var order = new List<int>();
            void Visit(int j)
            {
                if (order.Contains(j)) throw new ArgumentException("The moves make a cycle.", nameof(moves));
                order.Add(j);
                for (int c = 0; c < s.JointCount; c++) if (ParentOf(c) == j) Visit(c);
            }
            for (int j = 0; j < s.JointCount; j++) if (ParentOf(j) < 0) Visit(j);
            var index = new int[s.JointCount];
            for (int i = 0; i < order.Count; i++) index[order[i]] = i;
            var joints = new List<NewJoint>();
            foreach (int j in order) joints.Add(Same(s, j, ParentOf(j) < 0 ? -1 : index[ParentOf(j)], s.GetName(j)));
            return Rebuild(clip, joints);
        }

        /// <summary><paramref name="clip"/> without the joints <paramref name="dropped"/>: their children hang from the nearest kept ancestor and keep their world poses.</summary>
        public static BvhClip Without(BvhClip clip, params int[] dropped)
        {
            Skeleton s = clip.Skeleton;
            var joints = new List<NewJoint>();
            var index = new int[s.JointCount];
            for (int j = 0; j < s.JointCount; j++)
            {
                if (Array.IndexOf(dropped, j) >= 0) { index[j] = -2; continue; }
                int p = s.GetParent(j);
                while (p >= 0 && index[p] == -2) p = s.GetParent(p);
                if (p < 0 && s.GetParent(j) >= 0) throw new ArgumentException("A root cannot be dropped.", nameof(dropped));
                index[j] = joints.Count;
                joints.Add(Same(s, j, p < 0 ? -1 : index[p], s.GetName(j)));
            }
            return Rebuild(clip, joints);
        }

        /// <summary>
        /// <paramref name="clip"/> reflected through the plane x = 0 (BVH's and the T-pose's sagittal plane: x is the body's
        /// right): every world position with x negated and every rotation R turned into M R M, M = diag(-1, 1, 1), a proper
        /// rotation; every Left/Right in a name swapped (<see cref="SwapSides"/>), so the limb that is now on the left is
        /// named left. The joints keep their order and channel layout.
        /// </summary>
        public static BvhClip Mirrored(BvhClip clip)
        {
            Skeleton s = clip.Skeleton;
            var joints = new List<NewJoint>();
            for (int j = 0; j < s.JointCount; j++)
            {
                int joint = j;
                joints.Add(new NewJoint { Name = SwapSides(s.GetName(j)), Parent = s.GetParent(j), EndSite = s.IsEndSite(j), Source = j, World = w => Mirror(w[joint]) });
            }
            return Rebuild(clip, joints);
        }

        /// <summary>The reflection of a pose through the plane x = 0: the position's x negated, the rotation R as M R M, M = diag(-1, 1, 1).</summary>
        public static RigidPose Mirror(RigidPose p) =>
            new RigidPose(new Vector3(-p.Position.X, p.Position.Y, p.Position.Z), new Quaternion(p.Rotation.X, -p.Rotation.Y, -p.Rotation.Z, p.Rotation.W));

        /// <summary>
        /// The mountings a mirrored wearer wears when <paramref name="m"/> is the original's: each is given in the T-pose's
        /// body frame (x right, y up, z forward) at landmarks that the mirror maps onto the other side's
        /// (<see cref="DeviceMountings"/>), so the left hand's device sits as the right hand's did, reflected.
        /// </summary>
        public static DeviceMountings Mirrored(DeviceMountings m)
        {
            var mirrored = new DeviceMountings();
            foreach (DeviceRole role in BodyRoles.All) mirrored[role] = Mirror(m[OtherSide(role)]);
            return mirrored;
        }

        /// <summary>
        /// A joint name with its side swapped: Left and Right (capitalised, lower or upper case) anywhere, and a lone L or R
        /// after a dot or underscore (Rigify's <c>forearm.L</c> and its End Site <c>forearm.L_End</c>, <c>Bip01_L_Thigh</c>).
        /// </summary>
        public static string SwapSides(string name) =>
            Regex.Replace(name, @"Left|Right|left|right|LEFT|RIGHT|(?<=[._])[LlRr](?=$|[._])", m => m.Value switch
            {
                "Left" => "Right", "Right" => "Left", "left" => "right", "right" => "left", "LEFT" => "RIGHT", "RIGHT" => "LEFT",
                "L" => "R", "R" => "L", "l" => "r", _ => "l",
            });

        /// <summary>
        /// The largest distance (mm) and angle (°) over every frame between a joint of <paramref name="original"/> as
        /// <paramref name="expected"/> makes it and the joint of <paramref name="variant"/> named <paramref name="nameIn"/>
        /// of its name, over every original joint the variant keeps.
        /// </summary>
        public static (double mm, double degrees) WorldDeviation(BvhClip original, BvhClip variant, Func<RigidPose, RigidPose> expected, Func<string, string> nameIn)
        {
            Skeleton a = original.Skeleton, b = variant.Skeleton;
            var la = new RigidPose[a.JointCount]; var wa = new RigidPose[a.JointCount];
            var lb = new RigidPose[b.JointCount]; var wb = new RigidPose[b.JointCount];
            double mm = 0, degrees = 0;
            for (int f = 0; f < original.FrameCount; f++)
            {
                original.GetWorldPoses(f, la, wa);
                variant.GetWorldPoses(f, lb, wb);
                for (int j = 0; j < a.JointCount; j++)
                {
                    int k = b.IndexOf(nameIn(a.GetName(j)));
                    if (k < 0) continue;
                    RigidPose e = expected(wa[j]);
                    mm = Math.Max(mm, 1000.0 * Vector3.Distance(e.Position, wb[k].Position));
                    if (!a.IsEndSite(j)) degrees = Math.Max(degrees, Rotations.AngleDegrees(e.Rotation, wb[k].Rotation));
                }
            }
            return (mm, degrees);
        }

        /// <summary>
        /// <paramref name="session"/> (simulated without noise, device order <see cref="SessionSimulator.DeviceRoles"/>)
        /// with Gaussian noise on every device sample: a position offset of <paramref name="positionSigma"/> (m) per
        /// coordinate and a turn by a Gaussian angle of <paramref name="rotationSigmaDegrees"/> about a random axis, both
        /// in the device's own frame, drawn per frame and role from <paramref name="seed"/> in the order of
        /// <see cref="BodyRoles.All"/>. With <paramref name="mirrored"/>, each device gets the reflection of the noise the
        /// other side's device gets unmirrored, so a mirrored clip's session is the mirror of the original's, noise and
        /// all. Isotropic noise in the device's frame has the same distribution as the simulator's in the world's.
        /// </summary>
        public static string WithNoise(string session, int seed, float positionSigma, float rotationSigmaDegrees, bool mirrored)
        {
            var rng = new Random(seed);
            var noise = new RigidPose[BodyRoles.Count];
            return Sessions.Edit(session, (i, frame) =>
            {
                for (int r = 0; r < noise.Length; r++)
                {
                    var dp = new Vector3(Gaussian(rng), Gaussian(rng), Gaussian(rng)) * positionSigma;
                    var axis = new Vector3(Gaussian(rng), Gaussian(rng), Gaussian(rng));
                    noise[BodyRoles.IndexOf(BodyRoles.All[r])] = new RigidPose(dp, Rotations.AngleAxis(Gaussian(rng) * rotationSigmaDegrees, axis));
                }
                for (int d = 0; d < frame.Samples.Length; d++)
                {
                    DeviceRole role = SessionSimulator.DeviceRoles[d];
                    RigidPose n = mirrored ? Mirror(noise[BodyRoles.IndexOf(OtherSide(role))]) : noise[BodyRoles.IndexOf(role)];
                    DeviceSample s = frame.Samples[d];
                    frame.Samples[d] = new DeviceSample(s.Pose * n, s.IsTracked);
                }
            });
        }

        /// <summary>The role of the other side's device (the head's and the pelvis's own).</summary>
        public static DeviceRole OtherSide(DeviceRole role) => role switch
        {
            DeviceRole.LeftHand => DeviceRole.RightHand, DeviceRole.RightHand => DeviceRole.LeftHand,
            DeviceRole.LeftFoot => DeviceRole.RightFoot, DeviceRole.RightFoot => DeviceRole.LeftFoot,
            _ => role,
        };

        private static float Gaussian(Random rng)
        {
            double u1 = 1.0 - rng.NextDouble(), u2 = rng.NextDouble();
            return (float)(Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2.0 * Math.PI * u2));
        }

        private static bool HasPositions(BvhClip clip, int joint)
        {
            foreach (BvhChannel c in clip.GetChannels(joint))
                if (c == BvhChannel.Xposition || c == BvhChannel.Yposition || c == BvhChannel.Zposition) return true;
            return false;
        }

        private static NewJoint Same(Skeleton s, int j, int parent, string name) =>
            new NewJoint { Name = name, Parent = parent, EndSite = s.IsEndSite(j), Source = j, World = w => w[j] };

        // The clip of the new skeleton: rest and frames from the original's world poses through each joint's World, the
        // rotation channels in the order of the joint's source (Z X Y for a new joint), position channels where needed.
        private static BvhClip Rebuild(BvhClip clip, List<NewJoint> joints)
        {
            Skeleton s = clip.Skeleton;
            int n = joints.Count;
            var names = new string[n];
            var parents = new int[n];
            var endSites = new bool[n];
            for (int i = 0; i < n; i++) { names[i] = joints[i].Name; parents[i] = joints[i].Parent; endSites[i] = joints[i].EndSite; }
            var shape = new Skeleton(names, parents, new RigidPose[n], endSites);

            var local = new RigidPose[s.JointCount];
            var world = new RigidPose[s.JointCount];
            var newWorld = new RigidPose[n];
            RigidPose[] ToLocal()
            {
                for (int i = 0; i < n; i++) newWorld[i] = joints[i].World(world);
                var l = new RigidPose[n];
                shape.ComputeLocal(newWorld, l, RigidPose.Identity);
                return l;
            }
            s.GetRestLocal(local);
            s.ComputeWorld(local, world);
            var skeleton = new Skeleton(names, parents, ToLocal(), endSites);

            var frames = new List<RigidPose[]>(clip.FrameCount);
            var moves = new bool[n];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                clip.GetWorldPoses(f, local, world);
                RigidPose[] l = ToLocal();
                for (int i = 0; i < n; i++)
                    moves[i] |= parents[i] < 0 || Vector3.Distance(l[i].Position, skeleton.GetRestLocal(i).Position) > 1e-6f;
                frames.Add(l);
            }

            var channels = new BvhChannel[n][];
            for (int i = 0; i < n; i++)
            {
                if (endSites[i]) { channels[i] = Array.Empty<BvhChannel>(); continue; }
                var list = new List<BvhChannel>();
                int source = joints[i].Source;
                if (moves[i] || (source >= 0 && HasPositions(clip, source))) list.AddRange(new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition });
                int rotations = 0;
                if (source >= 0)
                    foreach (BvhChannel c in clip.GetChannels(source))
                        if (c == BvhChannel.Xrotation || c == BvhChannel.Yrotation || c == BvhChannel.Zrotation) { list.Add(c); rotations++; }
                if (rotations != 3)
                {
                    list.RemoveAll(c => c == BvhChannel.Xrotation || c == BvhChannel.Yrotation || c == BvhChannel.Zrotation);
                    list.AddRange(new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation });
                }
                channels[i] = list.ToArray();
            }
            return BvhClip.FromPoses(skeleton, frames, clip.FrameTime, 1f, channels);
        }
    }
}
