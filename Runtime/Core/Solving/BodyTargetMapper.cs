using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Turns the current device poses into <see cref="BodyTargets"/> with a <see cref="CalibrationProfile"/> (the
    /// paper's "Avatar movement"): each joint's world pose is <c>device * JointInDevice</c>, i.e.
    /// <c>p_t(J) = p_t(T) + R_t(T) R0(T)^-1 v0(TJ)</c> and <c>R_t(J) = R_t(T) R0(T)^-1 R0(J)</c>, for the root, the feet,
    /// the head and the wrists; the spine bend is the rotation from w0 (turned with the root) to wt; knee and elbow hints
    /// follow the feet and hands. The same code runs exact and fixed profiles. Allocation-free per frame.
    /// </summary>
    /// <remarks>
    /// w is measured between the hips and head joints the devices give (rather than between the devices
    /// themselves, as the paper writes it): the same vector up to the constant device offsets, but without the
    /// HMD's lever arm, so that nodding does not bend the back.
    /// </remarks>
    public sealed class BodyTargetMapper
    {
        private readonly PerRole<int> _deviceIndex = new PerRole<int>(-1);
        private readonly PerRole<RigidPose> _jointInDevice = new PerRole<RigidPose>();
        private readonly Vector3 _rootToHead0;
        private readonly Quaternion _hipsRotation0;
        private readonly Vector3[] _kneeInFoot = new Vector3[2];
        private readonly Vector3[] _elbowInHand = new Vector3[2];

        /// <summary>
        /// Prepares the mapping for a calibration. <paramref name="devices"/> is the device list whose order the
        /// per-frame samples follow; <paramref name="avatar"/> and <paramref name="calibrationPose"/> are the scaled
        /// avatar and its T-pose at the walk-in (<see cref="Calibrator.ScaledAvatar"/>, <see cref="Calibrator.AvatarPose"/>).
        /// </summary>
        public BodyTargetMapper(CalibrationProfile profile, IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, SkeletonPose calibrationPose)
        {
            Profile = profile ?? throw new ArgumentNullException(nameof(profile));
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            if (calibrationPose == null) throw new ArgumentNullException(nameof(calibrationPose));
            foreach (DeviceRole role in BodyRoles.All)
            {
                for (int i = 0; i < devices.Count; i++)
                    if (devices[i].Id == profile.DeviceId(role)) _deviceIndex[role] = i;
                if (_deviceIndex[role] < 0) throw new ArgumentException($"No device has the id calibrated for {role}.", nameof(devices));
                _jointInDevice[role] = profile.JointInDevice(role);
            }
            RigidPose[] w = calibrationPose.World;
            RigidPose hips = w[avatar[HumanoidBone.Hips]];
            _hipsRotation0 = hips.Rotation;
            _rootToHead0 = w[avatar[HumanoidBone.Head]].Position - hips.Position;
            Vector3 forward = Vector3.Transform(Vector3.UnitZ, profile.Placement.Rotation);
            Vector3 down = -Vector3.UnitY;
            for (int side = 0; side < 2; side++)
            {
                bool left = side == 0;
                RigidPose foot = w[avatar[left ? HumanoidBone.LeftFoot : HumanoidBone.RightFoot]];
                RigidPose hand = w[avatar[left ? HumanoidBone.LeftHand : HumanoidBone.RightHand]];
                // Hints: where the knee (elbow) was relative to the foot (hand) at calibration, pushed the way it
                // bends (knees forward; elbows back and down, as from a T-pose with the palms down), so the hint
                // is never on the hip-ankle (shoulder-wrist) line. The ankle's and wrist's limited range keeps the
                // shin's and forearm's direction close to what the foot and hand say.
                Vector3 knee = w[avatar[left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg]].Position;
                Vector3 elbow = w[avatar[left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm]].Position;
                float leg = Vector3.Distance(knee, foot.Position), arm = Vector3.Distance(elbow, hand.Position);
                _kneeInFoot[side] = foot.InverseTransformPoint(knee + forward * leg);
                _elbowInHand[side] = hand.InverseTransformPoint(elbow + Vector3.Normalize(-forward + 0.5f * down) * arm);
            }
        }

        /// <summary>The calibration used.</summary>
        public CalibrationProfile Profile { get; }

        /// <summary>Computes this frame's targets from the device samples (in the constructor's device order). Allocation-free.</summary>
        public void Compute(ReadOnlySpan<DeviceSample> samples, ref BodyTargets targets)
        {
            targets.HipsActive = Joint(samples, DeviceRole.Pelvis, out targets.Hips);
            targets.HeadActive = Joint(samples, DeviceRole.Head, out targets.Head);
            targets.SpineBend = Quaternion.Identity;
            if (targets.HipsActive && targets.HeadActive)
            {
                Quaternion rootTurn = targets.Hips.Rotation * Quaternion.Conjugate(_hipsRotation0);
                Vector3 w0 = Vector3.Transform(_rootToHead0, rootTurn);
                targets.SpineBend = Rotations.FromTo(w0, targets.Head.Position - targets.Hips.Position);
            }
            Limb(samples, DeviceRole.LeftFoot, 0, _kneeInFoot, ref targets.LeftFoot);
            Limb(samples, DeviceRole.RightFoot, 1, _kneeInFoot, ref targets.RightFoot);
            Limb(samples, DeviceRole.LeftHand, 0, _elbowInHand, ref targets.LeftHand);
            Limb(samples, DeviceRole.RightHand, 1, _elbowInHand, ref targets.RightHand);
        }

        private bool Joint(ReadOnlySpan<DeviceSample> samples, DeviceRole role, out RigidPose joint)
        {
            DeviceSample s = samples[_deviceIndex[role]];
            if (!s.IsUsable)
            {
                joint = RigidPose.Identity;
                return false;
            }
            joint = s.Pose * _jointInDevice[role];
            return true;
        }

        private void Limb(ReadOnlySpan<DeviceSample> samples, DeviceRole role, int side, Vector3[] hintInEnd, ref LimbTarget target)
        {
            target.IsActive = Joint(samples, role, out target.Goal);
            if (target.IsActive) target.Hint = target.Goal.TransformPoint(hintInEnd[side]);
        }
    }
}
