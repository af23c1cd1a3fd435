using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>A synthetic wearer: a mocap skeleton in T-pose with virtual devices, streamed to a calibrator.</summary>
    public sealed class Wearer
    {
        public readonly HumanoidMap Map;
        public readonly SkeletonPose Pose;
        public readonly VirtualDeviceRig Rig;
        public readonly DeviceInfo[] Devices;
        private readonly Random _rng;
        private readonly Core.RigidPose[] _devicePoses = new Core.RigidPose[6];

        public Wearer(string clip, int seed, DeviceMountings mountings = null)
        {
            BvhClip c = BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true });
            Map = HumanoidNaming.Detect(c.Skeleton);
            Pose = new SkeletonPose(c.Skeleton);
            _rng = new Random(seed);
            Rig = new VirtualDeviceRig(Map, mountings ?? DeviceMountings.Sample(_rng));
            // Device order deliberately not role order: the calibrator must find the roles.
            Devices = new[]
            {
                new DeviceInfo(4, DeviceClass.Tracker, "T-" + seed + "-a"),
                new DeviceInfo(0, DeviceClass.Hmd, "H-" + seed),
                new DeviceInfo(2, DeviceClass.Controller, "C-" + seed + "-b"),
                new DeviceInfo(7, DeviceClass.Tracker, "T-" + seed + "-b"),
                new DeviceInfo(1, DeviceClass.Controller, "C-" + seed + "-a"),
                new DeviceInfo(9, DeviceClass.Tracker, "T-" + seed + "-c"),
            };
        }

        /// <summary>Which role each device truly has, in <see cref="Devices"/> order.</summary>
        public static readonly DeviceRole[] TrueRoles =
            { DeviceRole.LeftFoot, DeviceRole.Head, DeviceRole.RightHand, DeviceRole.Pelvis, DeviceRole.LeftHand, DeviceRole.RightFoot };

        public void StandInTPose(Core.RigidPose placement) => TPoser.Apply(Map, Pose, placement);

        /// <summary>Turns one joint (and what hangs from it) by <paramref name="degrees"/> about a world axis.</summary>
        public void Turn(HumanoidBone bone, System.Numerics.Vector3 axis, float degrees)
        {
            int j = Map[bone];
            int parent = Map.Skeleton.GetParent(j);
            System.Numerics.Quaternion world = Rotations.AngleAxis(degrees, axis) * Pose.World[j].Rotation;
            Pose.Local[j] = Pose.Local[j].WithRotation(System.Numerics.Quaternion.Conjugate(Pose.World[parent].Rotation) * world);
            Pose.UpdateWorld();
        }

        /// <summary>The device samples of the current pose, with noise, in <see cref="Devices"/> order.</summary>
        public void Sample(DeviceSample[] samples, float positionNoise, float rotationNoiseDegrees)
        {
            Rig.Compute(Pose.World, _devicePoses);
            VirtualDeviceRig.AddNoise(_devicePoses, _rng, positionNoise, rotationNoiseDegrees);
            for (int i = 0; i < samples.Length; i++)
                samples[i] = new DeviceSample(_devicePoses[BodyRoles.IndexOf(TrueRoles[i])], true);
        }

        /// <summary>Feeds 1 s at 90 Hz to the pipeline, with a trigger press on the last frame.</summary>
        public void HoldAndPress(SelfAvatarPipeline pipeline, ref double time, float positionNoise, float rotationNoiseDegrees)
        {
            var samples = new DeviceSample[Devices.Length];
            var press = new List<DeviceEvent> { new DeviceEvent(1, DeviceEventKind.TriggerPressed) };
            for (int i = 0; i < 90; i++)
            {
                Sample(samples, positionNoise, rotationNoiseDegrees);
                time += 1.0 / 90;
                pipeline.Update(time, samples, default, default, i == 89 ? press : null);
            }
        }

        /// <summary>Calibrates the pipeline: T-pose at <paramref name="placement"/>, press, walk exactly into the avatar, press.</summary>
        public void Calibrate(SelfAvatarPipeline pipeline, RigidPose placement, ref double time, float positionNoise = 0.001f, float rotationNoiseDegrees = 0.1f)
        {
            StandInTPose(placement);
            HoldAndPress(pipeline, ref time, positionNoise, rotationNoiseDegrees);
            StandInTPose(pipeline.Profile.Placement);
            HoldAndPress(pipeline, ref time, positionNoise, rotationNoiseDegrees);
        }

        /// <summary>Feeds 1 s at 90 Hz to the calibrator, with a trigger press on the last frame.</summary>
        public void HoldAndPress(Calibrator calibrator, ref double time, float positionNoise, float rotationNoiseDegrees)
        {
            var samples = new DeviceSample[Devices.Length];
            var none = new List<DeviceEvent>();
            var press = new List<DeviceEvent> { new DeviceEvent(1, DeviceEventKind.TriggerPressed) };
            for (int i = 0; i < 90; i++)
            {
                Sample(samples, positionNoise, rotationNoiseDegrees);
                time += 1.0 / 90;
                calibrator.Update(time, samples, i == 89 ? press : none);
            }
        }
    }
}
