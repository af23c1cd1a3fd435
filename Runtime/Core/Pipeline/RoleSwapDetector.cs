using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Notices, after calibration, controllers swapped between the hands or foot trackers moved to the other feet, from the
    /// geometry alone, since two VIVE wands or two trackers look the same to the runtime. A pair is swapped when, over
    /// <see cref="TrackingSettings.SwapWindowSeconds"/>, the device playing the left side stays at least
    /// <see cref="TrackingSettings.SwapMargin"/> to the right of the one playing the right side (along the hips' right axis)
    /// (half that for the feet) in nearly every frame the wearer stands upright; for the hands, the current assignment must
    /// also often put a wrist out of its arm's reach while the swapped one would not, so that arms folded across the chest,
    /// which are reachable, are not taken for a swap. Averages are exponential over the window: allocation-free and
    /// frame-rate independent.
    /// </summary>
    public sealed class RoleSwapDetector
    {
        private readonly TrackingSettings _settings;
        private readonly Vector3 _hipsRightLocal;
        private readonly float _standingHeight;   // head above the feet when standing (the calibration's)
        private float _handsInverted, _handsMisplaced, _feetInverted;
        private bool _handsReported, _feetReported;   // reported and still swapped: not reported again

        // A reported pair is reported again only after its inversion has faded below this (the devices were put back): half,
        // about 0.7 s put back with the 3 s window (at 0.1 it took 2.3 s, and a swap made again sooner was never reported);
        // rising to 0.9 again takes 1.6 s of steady inversion, so crossing the legs for a moment is not reported.
        private const float ReportAgainBelow = 0.5f;

        /// <summary>
        /// Creates a detector. <paramref name="hipsRightLocal"/> is the hips joint's local axis that pointed to the wearer's
        /// right at the calibration; <paramref name="standingHeight"/> the head joint's height above the ankles then.
        /// </summary>
        public RoleSwapDetector(Vector3 hipsRightLocal, float standingHeight, TrackingSettings settings)
        {
            _hipsRightLocal = hipsRightLocal;
            _standingHeight = standingHeight;
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
        }

        /// <summary>Forgets what it saw (after a swap was applied, or a new calibration).</summary>
        public void Clear()
        {
            _handsInverted = _handsMisplaced = _feetInverted = 0f;
            _handsReported = _feetReported = false;
        }

        /// <summary>
        /// Feeds one frame. <paramref name="limbs"/> holds the joint targets of the current assignment and of the swapped
        /// one, with the limbs' roots (shoulders and hips joints) and lengths. Returns the pair now known to be swapped, if
        /// any. A pair is reported once: not again while it stays swapped (devices only reported, not reassigned), only
        /// after it was put back (or <see cref="Clear"/>, as after reassigning them).
        /// </summary>
        public RoleSwap Update(float dt, RigidPose hips, Vector3 head, in SwapEvidence limbs)
        {
            float k = 1f - (float)Math.Exp(-dt / Math.Max(_settings.SwapWindowSeconds / 3f, 1e-3f)); // ~95 % of the weight within the window
            Vector3 r = Vector3.Transform(_hipsRightLocal, hips.Rotation);
            Vector3 right = Vectors.NormalizeOr(new Vector3(r.X, 0f, r.Z), Vector3.UnitX);
            // Only an upright wearer says which side is which: lying, kneeling or bending, the hips' axes do not.
            float feetY = Math.Min(limbs.LeftFoot.Y, limbs.RightFoot.Y);
            bool upright = head.Y - feetY > 0.75f * _standingHeight && Math.Abs(r.Y) < 0.5f;
            if (upright && limbs.HandsTracked)
                Observe(ref _handsInverted, ref _handsMisplaced, k, right, limbs.LeftHand, limbs.RightHand, limbs.LeftHandIfSwapped, limbs.RightHandIfSwapped,
                    limbs.LeftShoulder, limbs.RightShoulder, limbs.ArmLength);
            if (upright && limbs.FeetTracked)
            {
                // Standing, the swapped feet are as reachable as the right ones (they are a stance apart), and standing
                // with crossed legs for seconds is rare: the inversion alone decides, with half the margin.
                bool inverted = Vector3.Dot(limbs.LeftFoot - limbs.RightFoot, right) > 0.5f * _settings.SwapMargin;
                _feetInverted += k * ((inverted ? 1f : 0f) - _feetInverted);
            }
            if (_handsReported && _handsInverted < ReportAgainBelow) _handsReported = false;
            if (_feetReported && _feetInverted < ReportAgainBelow) _feetReported = false;
            if (!_handsReported && _handsInverted > 0.9f && _handsMisplaced > 0.3f)
            {
                _handsReported = true;
                return RoleSwap.Hands;
            }
            if (!_feetReported && _feetInverted > 0.9f)
            {
                _feetReported = true;
                return RoleSwap.Feet;
            }
            return RoleSwap.None;
        }

        // One pair, one frame: is the left end to the right of the right one, and is the assignment out of reach where the
        // swapped one is not?
        private void Observe(ref float inverted, ref float misplaced, float k, Vector3 right, Vector3 left, Vector3 rightEnd,
            Vector3 leftIfSwapped, Vector3 rightIfSwapped, Vector3 leftRoot, Vector3 rightRoot, float length)
        {
            bool isInverted = Vector3.Dot(left - rightEnd, right) > _settings.SwapMargin;
            float reach = length * 1.1f;
            bool outOfReach = Vector3.Distance(left, leftRoot) > reach || Vector3.Distance(rightEnd, rightRoot) > reach;
            bool swappedInReach = Vector3.Distance(leftIfSwapped, leftRoot) <= reach && Vector3.Distance(rightIfSwapped, rightRoot) <= reach;
            inverted += k * ((isInverted ? 1f : 0f) - inverted);
            misplaced += k * ((isInverted && outOfReach && swappedInReach ? 1f : 0f) - misplaced);
        }
    }
}
