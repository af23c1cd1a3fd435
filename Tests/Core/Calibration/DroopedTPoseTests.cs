using System;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// A T-pose with the arms a little below horizontal, which the posture check accepts, measures the arms as long as they
    /// are: the wearer is the avatar, so fitted proportions keep the avatar's arms (found in review: 15° down fitted them
    /// 4.8 % short and measured the arm 23 mm short, beyond its stated uncertainty; the reach was taken horizontally).
    /// </summary>
    public class DroopedTPoseTests
    {
        [TestCase("mocapbank_30fps.bvh", 0f), TestCase("mocapbank_30fps.bvh", 8f), TestCase("mocapbank_30fps.bvh", 15f),
         TestCase("mixamo_fingers_30fps.bvh", 8f), TestCase("rigify_6channel_24fps_first240.bvh", 5f)]
        public void ArmsHeldALittleLowAreMeasuredAtTheirLength(string clip, float droopDegrees)
        {
            var wearer = new Wearer(clip, 7, DeviceMountings.Default());
            var settings = new CalibrationSettings();
            settings.Proportions.Mode = ScaleMode.Fitted;
            wearer.StandInTPose(RigidPose.Identity);
            // Each upper arm turned down about the body's forward axis (+Z), whichever way lowers its hand.
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                HumanoidBone upperArm = HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side);
                int hand = wearer.Map[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)];
                float level = wearer.Pose.World[hand].Position.Y;
                wearer.Turn(upperArm, Vector3.UnitZ, droopDegrees);
                if (wearer.Pose.World[hand].Position.Y > level) wearer.Turn(upperArm, Vector3.UnitZ, -2f * droopDegrees);
                Assert.That(wearer.Pose.World[hand].Position.Y, Is.LessThanOrEqualTo(level + 1e-5f), side + " hand lowered");
            }
            var calibrator = new Calibrator(wearer.Devices, wearer.Map, settings);
            double t = 0;
            wearer.HoldAndPress(calibrator, ref t, 0.001f, 0.1f);
            Assume.That(calibrator.State, Is.EqualTo(CalibrationState.WalkIn), calibrator.LastStep.Message);
            BodyMeasurements truth = ProportionFitter.MeasureSkeleton(wearer.Map);
            CalibrationProfile p = calibrator.Profile;
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                Measurement arm = p.Measurements.ArmLength(side);
                Assert.That(Math.Abs(arm.Value - truth.ArmLength(side).Value), Is.LessThanOrEqualTo(arm.Uncertainty), $"{side} arm {arm} against {truth.ArmLength(side).Value:0.000} m");
            }
            Assert.That(p.Proportions.LeftArm, Is.EqualTo(1f).Within(0.01f), "the avatar's own arms kept: " + calibrator.LastStep.Explanation);
            Assert.That(p.Proportions.RightArm, Is.EqualTo(1f).Within(0.01f));
        }
    }
}
