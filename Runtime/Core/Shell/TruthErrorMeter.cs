using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The error a sample shows live while a synthetic session plays: how far the solved avatar's joints are from the
    /// wearer's true joints the session carries, in millimetres, for the last frame and averaged since calibration. The
    /// same joints and the same distances as the evaluator's report (every non-finger humanoid bone both have; end
    /// effectors: hips, head, hands and feet; mid joints: elbows and knees), so the number on screen is the number
    /// <c>avatargo evaluate</c> prints. Allocation-free per frame.
    /// </summary>
    public sealed class TruthErrorMeter
    {
        private double _allSum, _endSum, _midSum;
        private long _allCount, _endCount, _midCount;

        /// <summary>The last measured frame's mean error over all compared joints (mm), or NaN before the first.</summary>
        public double LastMeanMm { get; private set; } = double.NaN;

        /// <summary>The last measured frame's mean end-effector error (mm), or NaN.</summary>
        public double LastEndEffectorMm { get; private set; } = double.NaN;

        /// <summary>The last measured frame's mean elbow and knee error (mm), or NaN.</summary>
        public double LastMidJointMm { get; private set; } = double.NaN;

        /// <summary>The mean per-joint position error over every measured frame (MPJPE, mm), or NaN.</summary>
        public double MeanMm => _allCount > 0 ? _allSum / _allCount : double.NaN;

        /// <summary>The mean end-effector error over every measured frame (mm), or NaN.</summary>
        public double MeanEndEffectorMm => _endCount > 0 ? _endSum / _endCount : double.NaN;

        /// <summary>The mean elbow and knee error over every measured frame (mm), or NaN.</summary>
        public double MeanMidJointMm => _midCount > 0 ? _midSum / _midCount : double.NaN;

        /// <summary>How many frames have been measured.</summary>
        public int Frames { get; private set; }

        /// <summary>Forgets every frame (after a recalibration, for example).</summary>
        public void Reset()
        {
            _allSum = _endSum = _midSum = 0;
            _allCount = _endCount = _midCount = 0;
            Frames = 0;
            LastMeanMm = LastEndEffectorMm = LastMidJointMm = double.NaN;
        }

        /// <summary>
        /// Measures one frame: <paramref name="avatar"/>'s joints in <paramref name="pose"/> (world poses up to date, in the
        /// session's tracking space) against <paramref name="frame"/>'s truth. A frame without truth, or taken before
        /// calibration, is not measured (returns false; <paramref name="avatar"/> and <paramref name="pose"/> may then be null).
        /// </summary>
        public bool Measure(HumanoidMap avatar, SkeletonPose pose, SessionFrame frame, CalibrationState state)
        {
            if (frame == null) throw new ArgumentNullException(nameof(frame));
            if (state != CalibrationState.Calibrated) return false; // before calibration the pipeline may have no pose yet
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            double all = 0, end = 0, mid = 0;
            int allN = 0, endN = 0, midN = 0;
            for (int b = 0; b < HumanoidBones.Count; b++)
            {
                var bone = (HumanoidBone)b;
                if (!frame.HasTruth[b] || !avatar.Has(bone) || HumanoidBones.IsFinger(bone)) continue;
                double mm = Vector3.Distance(pose.World[avatar[bone]].Position, frame.Truth[b].Position) * 1000.0;
                all += mm;
                allN++;
                if (HumanoidBones.IsEndEffector(bone)) { end += mm; endN++; }
                if (HumanoidBones.IsMidJoint(bone)) { mid += mm; midN++; }
            }
            if (allN == 0) return false;
            _allSum += all; _allCount += allN;
            _endSum += end; _endCount += endN;
            _midSum += mid; _midCount += midN;
            LastMeanMm = all / allN;
            LastEndEffectorMm = endN > 0 ? end / endN : double.NaN;
            LastMidJointMm = midN > 0 ? mid / midN : double.NaN;
            Frames++;
            return true;
        }
    }
}
