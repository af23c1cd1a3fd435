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
        /// Builds the rig for the wearer's skeleton: each mounting is given in a frame of landmarks of the wearer's canonical
        /// T-pose (<see cref="DeviceMountings"/>) and converted once into its joint's own frame, so no bone's local axes
        /// matter. Controllers are held in the palm: the grip of <paramref name="controller"/> (or of a handle of
        /// <see cref="DefaultHandleRadius"/>) on the palm that the finger bones give (<see cref="HandModel"/>), or, for a hand
        /// without finger bones, on a palm estimated from the arm (see <see cref="PalmWithoutFingers"/>).
        /// </summary>
        /// <param name="wearer">The wearer's skeleton.</param>
        /// <param name="mountings">Where each device sits.</param>
        /// <param name="controller">The controller held in both hands, or null for a generic handle.</param>
        /// <param name="twistReference">The local poses the wearer's T-pose takes its bone twists from (see
        /// <see cref="TPoser.Apply(HumanoidMap, SkeletonPose, RigidPose, RigidPose[])"/>), or null for the rest pose: pass the
        /// same as for the T-pose the wearer stands in.</param>
        public VirtualDeviceRig(HumanoidMap wearer, DeviceMountings mountings, ControllerProfile controller = null, RigidPose[] twistReference = null)
        {
            Wearer = wearer ?? throw new ArgumentNullException(nameof(wearer));
            Mountings = mountings ?? throw new ArgumentNullException(nameof(mountings));
            var tpose = new SkeletonPose(wearer.Skeleton);
            TPoser.Apply(wearer, tpose, RigidPose.Identity, twistReference);
            for (int i = 0; i < BodyRoles.All.Length; i++)
            {
                DeviceRole role = BodyRoles.All[i];
                _joints[i] = wearer[BodyRoles.JointOf(role)];
                RigidPose joint = tpose.World[_joints[i]];
                RigidPose device = role == DeviceRole.LeftHand || role == DeviceRole.RightHand
                    ? joint * GripInHand(wearer, tpose, role == DeviceRole.LeftHand ? BodySide.Left : BodySide.Right, controller)
                    : LandmarkFrame(wearer, tpose, role);
                _deviceInJoint[i] = (device * mountings[role]).RelativeTo(joint);
            }
        }

        // The frame a mounting is given in, from landmarks of the T-pose (facing +Z): the HMD's at the centre eye, looking
        // the way the body faces; the pelvis tracker's at the hips joint, x along the hip line, y up; a foot tracker's at the
        // ankle, z toward the toes (level), y up (for a foot without a toe landmark, the body's forward).
        private static RigidPose LandmarkFrame(HumanoidMap wearer, SkeletonPose tpose, DeviceRole role)
        {
            RigidPose[] w = tpose.World;
            switch (role)
            {
                case DeviceRole.Head:
                    return new RigidPose(TPoser.EyePosition(wearer, tpose, Quaternion.Identity), Quaternion.Identity);
                case DeviceRole.Pelvis:
                {
                    Vector3 hipLine = w[wearer[HumanoidBone.RightUpperLeg]].Position - w[wearer[HumanoidBone.LeftUpperLeg]].Position;
                    Vector3 forward = Vectors.NormalizeOr(Vector3.Cross(hipLine, Vector3.UnitY), Vector3.UnitZ);
                    return new RigidPose(w[wearer[HumanoidBone.Hips]].Position, Rotations.LookRotation(forward, Vector3.UnitY));
                }
                default:
                {
                    BodySide side = role == DeviceRole.LeftFoot ? BodySide.Left : BodySide.Right;
                    Vector3 ankle = w[wearer[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)]].Position;
                    int toe = TPoser.ToeLandmark(wearer, side);
                    Vector3 toward = toe >= 0 ? Vectors.ProjectOnPlane(w[toe].Position - ankle, Vector3.UnitY) : Vector3.UnitZ;
                    return new RigidPose(ankle, Rotations.LookRotation(Vectors.NormalizeOr(toward, Vector3.UnitZ), Vector3.UnitY));
                }
            }
        }

        // Where the hand holds the controller, in the hand joint's frame.
        private static RigidPose GripInHand(HumanoidMap wearer, SkeletonPose tpose, BodySide side, ControllerProfile controller)
        {
            float radius = controller != null ? -controller.Shape.Distance(Vector3.Zero) : DefaultHandleRadius;
            if (HandModel.CanModel(wearer, side, tpose, out _))
            {
                var hand = new HandModel(wearer, side, tpose);
                return HandModel.GripPose(hand.PalmCentreInHand, hand.PalmNormalInHand, hand.AcrossInHand, radius);
            }
            RigidPose wrist = tpose.World[wearer[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]];
            PalmWithoutFingers(wearer, tpose, side, out Vector3 palmCentre, out Vector3 normal, out Vector3 across);
            return wrist.Inverse() * HandModel.GripPose(palmCentre, normal, across, radius);
        }

        /// <summary>
        /// The palm of a hand without finger bones, in the T-pose <paramref name="tpose"/> (world): the hand points along the
        /// wrist's child (an End Site), or along the forearm when it has none; the palm faces down and the thumb forward,
        /// as the T-pose holds them; the hand is 0.36 of the forearm long (wrist to middle knuckle, typical proportions), and
        /// the palm centre is <see cref="HandModel.GripAlongPalm"/> of the way along it, one finger radius out of the palm.
        /// </summary>
        public static void PalmWithoutFingers(HumanoidMap wearer, SkeletonPose tpose, BodySide side, out Vector3 palmCentre, out Vector3 normal, out Vector3 across) =>
            HandModel.PalmWithoutFingers(wearer, tpose, side, out palmCentre, out normal, out across);

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
