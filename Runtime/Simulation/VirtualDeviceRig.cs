using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Produces the six device poses a wearer would have (HMD, two controllers, pelvis and foot trackers)
    /// from a posed humanoid skeleton: each device rigidly attached to its joint with a <see cref="DeviceMountings"/>
    /// offset, plus optional Gaussian noise. Used to turn mocap into sessions and by tests; allocation-free per frame.
    /// </summary>
    public sealed class VirtualDeviceRig
    {
        private readonly int[] _joints = new int[BodyRoles.Count]; // per role, in BodyRoles.IndexOf order
        private readonly RigidPose[] _deviceInJoint = new RigidPose[BodyRoles.Count];

        /// <summary>Handle radius (m) of the controller held when none is given: 2 cm, a typical grip.</summary>
        public const float DefaultHandleRadius = 0.02f;

        /// <summary>
        /// Builds the rig for the wearer's skeleton: the mountings (given in the T-pose body frame) are converted
        /// once into each joint's own frame using the wearer's canonical T-pose. Controllers are held in the palm: the
        /// grip of <paramref name="controller"/> (or of a handle of <see cref="DefaultHandleRadius"/>) on the palm that the
        /// finger bones give (<see cref="HandModel"/>), or, for a hand without finger bones, on a palm estimated from the
        /// forearm (its length 0.36 of the forearm's, the palm facing down in the T-pose).
        /// </summary>
        public VirtualDeviceRig(HumanoidMap wearer, DeviceMountings mountings, ControllerProfile controller = null)
        {
            Wearer = wearer ?? throw new ArgumentNullException(nameof(wearer));
            Mountings = mountings ?? throw new ArgumentNullException(nameof(mountings));
            var tpose = new SkeletonPose(wearer.Skeleton);
            TPoser.Apply(wearer, tpose, RigidPose.Identity);
            for (int i = 0; i < BodyRoles.All.Length; i++)
            {
                DeviceRole role = BodyRoles.All[i];
                HumanoidBone bone = BodyRoles.JointOf(role);
                _joints[i] = wearer[bone];
                RigidPose joint = tpose.World[_joints[i]];
                RigidPose mount = mountings[role];
                if (role == DeviceRole.LeftHand || role == DeviceRole.RightHand)
                {
                    BodySide side = role == DeviceRole.LeftHand ? BodySide.Left : BodySide.Right;
                    _deviceInJoint[i] = GripInHand(wearer, tpose, side, controller) * mount;
                    continue;
                }
                Vector3 reference = role == DeviceRole.Head ? TPoser.EyePosition(wearer, tpose, Quaternion.Identity) : joint.Position;
                var device = new RigidPose(reference + mount.Position, mount.Rotation);
                _deviceInJoint[i] = device.RelativeTo(joint);
            }
        }

        // Where the hand holds the controller, in the hand joint's frame.
        private static RigidPose GripInHand(HumanoidMap wearer, SkeletonPose tpose, BodySide side, ControllerProfile controller)
        {
            float radius = controller != null ? -controller.Shape.Distance(Vector3.Zero) : DefaultHandleRadius;
            if (HandModel.CanModel(wearer, side, out _))
            {
                var hand = new HandModel(wearer, side);
                return HandModel.GripPose(hand.PalmCentreInHand, hand.PalmNormalInHand, hand.AcrossInHand, radius);
            }
            // No finger bones: the palm from the forearm, facing down in the T-pose, the thumb forward.
            RigidPose wrist = tpose.World[wearer[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]];
            Vector3 elbow = tpose.World[wearer[HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side)]].Position;
            Vector3 along = Vectors.NormalizeOr(wrist.Position - elbow, side == BodySide.Left ? -Vector3.UnitX : Vector3.UnitX);
            Vector3 normal = Vectors.NormalizeOr(Vectors.ProjectOnPlane(-Vector3.UnitY, along), -Vector3.UnitY);
            Vector3 across = side == BodySide.Left ? Vector3.Cross(along, normal) : Vector3.Cross(normal, along);
            float handLength = 0.36f * Vector3.Distance(wrist.Position, elbow);
            float fingerRadius = 0.0085f * handLength / 0.095f;
            Vector3 palmCentre = wrist.Position + along * (HandModel.GripAlongPalm * handLength) + normal * fingerRadius;
            return wrist.Inverse() * HandModel.GripPose(palmCentre, normal, across, radius);
        }

        /// <summary>The wearer's skeleton and humanoid map.</summary>
        public HumanoidMap Wearer { get; }

        /// <summary>The mountings used.</summary>
        public DeviceMountings Mountings { get; }

        /// <summary>The true pose of a role's device in its joint's frame (what exact calibration should recover).</summary>
        public RigidPose DeviceInJoint(DeviceRole role) => _deviceInJoint[BodyRoles.IndexOf(role)];

        /// <summary>
        /// Writes the device poses for the wearer's world joint poses <paramref name="world"/> into
        /// <paramref name="devices"/>, indexed by <see cref="BodyRoles.IndexOf"/>. Allocation-free.
        /// </summary>
        public void Compute(ReadOnlySpan<RigidPose> world, Span<RigidPose> devices)
        {
            if (devices.Length < _joints.Length) throw new ArgumentException("Six device poses are needed.", nameof(devices));
            for (int i = 0; i < _joints.Length; i++) devices[i] = world[_joints[i]] * _deviceInJoint[i];
        }

        /// <summary>
        /// Adds Gaussian noise: each position coordinate with standard deviation <paramref name="positionSigma"/> (m),
        /// each rotation by a random axis and a Gaussian angle of <paramref name="rotationSigmaDegrees"/>.
        /// </summary>
        public static void AddNoise(Span<RigidPose> poses, Random rng, float positionSigma, float rotationSigmaDegrees)
        {
            if (rng == null) throw new ArgumentNullException(nameof(rng));
            for (int i = 0; i < poses.Length; i++)
            {
                var dp = new Vector3(Gaussian(rng), Gaussian(rng), Gaussian(rng)) * positionSigma;
                var axis = new Vector3(Gaussian(rng), Gaussian(rng), Gaussian(rng));
                Quaternion dq = Rotations.AngleAxis(Gaussian(rng) * rotationSigmaDegrees, axis);
                poses[i] = new RigidPose(poses[i].Position + dp, Quaternion.Normalize(dq * poses[i].Rotation));
            }
        }

        private static float Gaussian(Random rng)
        {
            double u1 = 1.0 - rng.NextDouble(), u2 = rng.NextDouble();
            return (float)(Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2.0 * Math.PI * u2));
        }
    }
}
