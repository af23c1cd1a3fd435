using System;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    // Injects a session's disturbances frame by frame and measures, per end effector, what they did (DisturbanceReport).
    internal sealed class DisturbanceTracker
    {
        private readonly SessionDisturber _disturber;
        private readonly SelfAvatarPipeline _pipeline;
        private readonly DisturbanceReport _report;
        private readonly int[] _device = new int[BodyRoles.Count];
        private readonly double[] _recoveredAt = new double[BodyRoles.Count];
        private readonly bool[] _wasDisturbed = new bool[BodyRoles.Count];
        private readonly Vector3[] _lastSolved = new Vector3[BodyRoles.Count];
        private readonly Vector3[] _lastTruth = new Vector3[BodyRoles.Count];
        private bool _first = true;

        public DisturbanceTracker(SessionHeader header, DisturbanceOptions options, SelfAvatarPipeline pipeline, DisturbanceReport report)
        {
            _disturber = new SessionDisturber(header.Devices.Count, header.Rate, options);
            _pipeline = pipeline;
            _report = report;
            foreach (DeviceRole role in BodyRoles.All)
            {
                _device[BodyRoles.IndexOf(role)] = pipeline.DeviceIndexOf(role);
                _recoveredAt[BodyRoles.IndexOf(role)] = double.NegativeInfinity;
            }
        }

        public void Disturb(SessionFrame frame) => _disturber.Apply(frame);

        public void Measure(SessionFrame frame)
        {
            HumanoidMap avatar = _pipeline.ScaledAvatar;
            // A frame is undisturbed when no body device is lost, teleported or recovering: a loss moves other parts too.
            bool calm = true;
            foreach (DeviceRole role in BodyRoles.All)
            {
                int r = BodyRoles.IndexOf(role);
                bool disturbed = _disturber.IsDisturbed(_device[r]);
                if (disturbed) _report.DisturbedDeviceFrames++;
                if (_wasDisturbed[r] && !disturbed) _recoveredAt[r] = frame.Time;
                _wasDisturbed[r] = disturbed;
                calm &= !disturbed && frame.Time - _recoveredAt[r] > DisturbanceReport.RecoverySeconds;
            }
            foreach (DeviceRole role in BodyRoles.All)
            {
                int r = BodyRoles.IndexOf(role);
                bool disturbed = _wasDisturbed[r];
                HumanoidBone bone = BodyRoles.JointOf(role);
                if (!frame.HasTruth[(int)bone]) continue;
                Vector3 solved = _pipeline.Pose.World[avatar[bone]].Position, truth = frame.Truth[(int)bone].Position;
                double error = Vector3.Distance(solved, truth) * 1000.0;
                bool recovering = frame.Time - _recoveredAt[r] <= DisturbanceReport.RecoverySeconds;
                if (disturbed) _report.WhileDisturbedMm.Add(error);
                else if (recovering) _report.AfterRecoveryMm.Add(error);
                if (calm) _report.UndisturbedMm.Add(error);
                if (!_first)
                {
                    double jump = Vector3.Distance(solved, _lastSolved[r]) * 1000.0;
                    double excess = Vector3.Distance(solved - _lastSolved[r], truth - _lastTruth[r]) * 1000.0;
                    _report.LargestJumpMm = Math.Max(_report.LargestJumpMm, jump);
                    if (excess > _report.LargestExcessJumpMm)
                    {
                        _report.LargestExcessJumpMm = excess;
                        _report.LargestExcessJumpJoint = bone;
                        _report.LargestExcessJumpTime = frame.Time;
                    }
                    // The jump a device's return causes: on its first frame back the whole displacement (the part was not
                    // following the wearer the frame before), afterwards the displacement beyond the wearer's own.
                    double recoveryJump = frame.Time == _recoveredAt[r] ? jump : excess;
                    if (recovering && !disturbed && recoveryJump > _report.LargestRecoveryJumpMm)
                    {
                        _report.LargestRecoveryJumpMm = recoveryJump;
                        _report.LargestRecoveryJumpJoint = bone;
                        _report.LargestRecoveryJumpTime = frame.Time;
                    }
                }
                _lastSolved[r] = solved;
                _lastTruth[r] = truth;
            }
            _first = false;
        }
    }
}
