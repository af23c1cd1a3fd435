using System;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>Lost tracking and garbage poses mid-motion: nothing throws, nothing turns NaN, the avatar keeps its last good pose.</summary>
    public class BadInputTests
    {
        [Test]
        public void NaNZeroQuaternionAndLostDevicesKeepTheLastGoodPose()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 41);
            var calibrator = new Calibrator(wearer.Devices, wearer.Map);
            wearer.StandInTPose(RigidPose.Identity);
            double t = 0;
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            wearer.StandInTPose(calibrator.Profile.Placement);
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.Calibrated), calibrator.LastStep.Message);

            var solver = new BodyTargetMapper(calibrator.Profile, wearer.Devices, calibrator.ScaledAvatar, calibrator.AvatarPose);
            var ik = new FullBodyIk(calibrator.ScaledAvatar, calibrator.AvatarPose);
            var pose = new SkeletonPose(calibrator.ScaledAvatar.Skeleton);
            pose.CopyFrom(calibrator.AvatarPose);
            var targets = new BodyTargets();
            var samples = new DeviceSample[6];
            wearer.Sample(samples, 0.001f, 0.1f);
            solver.Compute(samples, ref targets);
            ik.Solve(in targets, pose);
            int hips = calibrator.ScaledAvatar[HumanoidBone.Hips];
            RigidPose goodHips = pose.World[hips];

            int pelvis = Array.IndexOf(Wearer.TrueRoles, DeviceRole.Pelvis);
            int hmd = Array.IndexOf(Wearer.TrueRoles, DeviceRole.Head);
            int hand = Array.IndexOf(Wearer.TrueRoles, DeviceRole.LeftHand);
            var bad = new[]
            {
                new DeviceSample(new RigidPose(new Vector3(float.NaN, 1, 0), Quaternion.Identity), true),
                new DeviceSample(new RigidPose(new Vector3(0, 1, 0), new Quaternion(0, 0, 0, 0)), true),
                new DeviceSample(new RigidPose(new Vector3(float.PositiveInfinity, 0, 0), Quaternion.Identity), true),
                DeviceSample.Lost,
            };
            foreach (DeviceSample garbage in bad)
            {
                wearer.Sample(samples, 0.001f, 0.1f);
                samples[pelvis] = garbage;
                samples[hmd] = garbage;
                samples[hand] = garbage;
                solver.Compute(samples, ref targets);
                Assert.That(targets.HipsActive, Is.False);
                Assert.That(targets.LeftHand.IsActive, Is.False);
                ik.Solve(in targets, pose);
                Approx.Near(goodHips, pose.World[hips], 1e-6f, 1e-3f, "hips keep their last good pose");
                foreach (RigidPose p in pose.World)
                {
                    Assert.That(p.IsValid, Is.True, "no NaN anywhere in the avatar");
                }
            }
        }
    }
}
