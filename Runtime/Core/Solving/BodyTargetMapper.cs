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
    /// (<see cref="KneeHintModel"/>, <see cref="ElbowHintModel"/>) come from the pelvis, foot and hand devices. The same
    /// code runs exact and fixed profiles. Allocation-free per frame.
    /// </summary>
    /// <remarks>
    /// <para>w is measured between the hips and head joints the devices give (rather than between the devices
    /// themselves, as the paper writes it): the same vector up to the constant device offsets, but without the
    /// HMD's lever arm, so that nodding does not bend the back.</para>
    /// <para>A hint is the end joint plus one limb length along a bend direction; only its part square to the limb's axis
    /// matters to <see cref="TwoBoneIk"/>. The directions are functions of this frame's devices only (continuous, no
    /// state, frame-rate independent) and of landmarks of the calibration pose carried by the devices' turns since then,
    /// never of a bone's local axis. While the pelvis tracker or the HMD is lost, the hints use their last pose.</para>
    /// </remarks>
    public sealed class BodyTargetMapper
    {
        /// <summary>
        /// The weight of the fallback direction in the elbow hint (and the toes' knee hint), against the hand's (toes')
        /// weight, which is the size of its component off the limb's axis (1 when square to it); within 15° of the limb's
        /// axis the fallback fades with its own component off the axis, so that it does not turn round where the limb passes
        /// through it. 0.26 = sin 15°, the typical angle between the forearm and the hand (wrist flexion and deviation in
        /// everyday tasks): the hand decides wherever it points farther than that off the arm's axis, the fallback where it
        /// points along it and says nothing.
        /// </summary>
        public const float FallbackWeight = 0.26f;

        /// <summary>
        /// How strongly the default knee hint (<see cref="KneeHintModel.OuterOfPelvisAndFoot"/>) favours the more outward of
        /// the pelvis's and the foot's flexion directions: they weigh 2σ(±g·Δ), σ the logistic function and Δ how much
        /// further out (along the hip line, away from the body) the pelvis's direction points than the foot's. Two
        /// directions 15° either side of forward (Δ = 2 sin 15° ≈ 0.52) weigh about 5 : 1; equally far out, they are added.
        /// 3 was chosen from the measured curve (Documentation~/solver.md, "Knees and elbows").
        /// </summary>
        public const float OuterPlaneGain = 3f;


        private readonly PerRole<int> _deviceIndex = new PerRole<int>(-1);
        private readonly PerRole<RigidPose> _jointInDevice = new PerRole<RigidPose>();
        private readonly Vector3 _rootToHead0;
        private readonly Quaternion _hipsRotation0;
        private readonly KneeHintModel _kneeModel;
        private readonly ElbowHintModel _elbowModel;
        private readonly Vector3[] _kneeInFoot = new Vector3[2];        // CalibrationFrame: the pushed knee in the foot's frame
        private readonly Vector3[] _elbowInHand = new Vector3[2];       // CalibrationFrame: the pushed elbow in the hand's frame
        private readonly Vector3[] _hipInHips = new Vector3[2];         // each leg's root in the hips' frame
        private readonly Vector3[] _toesInFoot = new Vector3[2];        // unit, ankle toward the toes, in the foot's frame
        private readonly Vector3 _hipLineInHips;                        // unit, left to right hip joint, in the hips' frame
        private readonly Vector3[] _lateralInFoot = new Vector3[2];     // unit, the T-pose's right (the ankle's flexion axis), in the foot's frame
        private readonly Vector3 _forwardInHips;                        // unit, the body's facing at calibration, in the hips' frame
        private readonly Vector3[] _shoulderFromHips = new Vector3[2];  // each arm's root from the hips joint, world, at calibration
        private readonly Vector3[] _handInHand = new Vector3[2];        // unit, wrist toward the knuckles, in the hand's frame
        private readonly Vector3 _right0;                               // the hip line at calibration (world)
        private readonly float[] _legLength = new float[2], _armLength = new float[2];
        private readonly float[] _thigh = new float[2], _shin = new float[2];

        private RigidPose _lastHips, _lastHead;                         // for hints while the pelvis tracker or HMD is lost

        /// <summary>
        /// Prepares the mapping for a calibration, with the default knee and elbow hints. <paramref name="devices"/> is the
        /// device list whose order the per-frame samples follow; <paramref name="avatar"/> and <paramref name="calibrationPose"/>
        /// are the scaled avatar and its T-pose at the walk-in (<see cref="Calibrator.ScaledAvatar"/>, <see cref="Calibrator.AvatarPose"/>).
        /// </summary>
        public BodyTargetMapper(CalibrationProfile profile, IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, SkeletonPose calibrationPose)
            : this(profile, devices, avatar, calibrationPose, KneeHintModel.OuterOfPelvisAndFoot, ElbowHintModel.HandAxis)
        {
        }

        /// <summary>As the other constructor, with the models that choose the knees' and elbows' bend directions.</summary>
        public BodyTargetMapper(CalibrationProfile profile, IReadOnlyList<DeviceInfo> devices, HumanoidMap avatar, SkeletonPose calibrationPose,
            KneeHintModel knees, ElbowHintModel elbows)
        {
            Profile = profile ?? throw new ArgumentNullException(nameof(profile));
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            if (calibrationPose == null) throw new ArgumentNullException(nameof(calibrationPose));
            _kneeModel = knees;
            _elbowModel = elbows;
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
            _lastHips = hips;
            _lastHead = w[avatar[HumanoidBone.Head]];
            _rootToHead0 = w[avatar[HumanoidBone.Head]].Position - hips.Position;
            Vector3 forward = Vector3.Transform(Vector3.UnitZ, profile.Placement.Rotation);
            Vector3 down = -Vector3.UnitY;
            _right0 = Vectors.NormalizeOr(w[avatar[HumanoidBone.RightUpperLeg]].Position - w[avatar[HumanoidBone.LeftUpperLeg]].Position, Vector3.Cross(Vector3.UnitY, forward));
            _hipLineInHips = hips.InverseTransformDirection(_right0);
            _forwardInHips = hips.InverseTransformDirection(forward);
            foreach (BodySide side in new[] { BodySide.Left, BodySide.Right })
            {
                int s = (int)side;
                RigidPose foot = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftFoot, side)]];
                RigidPose hand = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftHand, side)]];
                Vector3 hip = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftUpperLeg, side)]].Position;
                Vector3 knee = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftLowerLeg, side)]].Position;
                Vector3 shoulder = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftUpperArm, side)]].Position;
                Vector3 elbow = w[avatar[HumanoidBones.OnSide(HumanoidBone.LeftLowerArm, side)]].Position;
                float leg = Vector3.Distance(knee, foot.Position), arm = Vector3.Distance(elbow, hand.Position);
                _thigh[s] = Vector3.Distance(hip, knee);
                _shin[s] = leg;
                _legLength[s] = _thigh[s] + leg;
                _armLength[s] = Vector3.Distance(shoulder, elbow) + arm;
                _hipInHips[s] = hips.InverseTransformPoint(hip);
                _shoulderFromHips[s] = shoulder - hips.Position;
                // Landmarks carried by the foot and hand: toward the toes (the T-pose's forward for a foot without them),
                // toward the knuckles (the forearm's direction for a hand without a landmark).
                int toe = TPoser.ToeLandmark(avatar, side);
                Vector3 toes = toe >= 0 ? w[toe].Position - foot.Position : forward;
                _toesInFoot[s] = foot.InverseTransformDirection(Vectors.NormalizeOr(toes, forward));
                _lateralInFoot[s] = foot.InverseTransformDirection(_right0);
                int knuckles = TPoser.HandLandmark(avatar, side);
                Vector3 along = knuckles >= 0 ? w[knuckles].Position - hand.Position : hand.Position - elbow;
                _handInHand[s] = hand.InverseTransformDirection(Vectors.NormalizeOr(along, hand.Position - elbow));
                // The first implementation's hints: where the knee (elbow) was relative to the foot (hand) at calibration,
                // pushed the way it bends (knees forward; elbows back and down).
                _kneeInFoot[s] = foot.InverseTransformPoint(knee + forward * leg);
                _elbowInHand[s] = hand.InverseTransformPoint(elbow + Vector3.Normalize(-forward + 0.5f * down) * arm);
            }
        }

        /// <summary>The calibration used.</summary>
        public CalibrationProfile Profile { get; }

        /// <summary>The knee hint model.</summary>
        public KneeHintModel KneeHints => _kneeModel;

        /// <summary>The elbow hint model.</summary>
        public ElbowHintModel ElbowHints => _elbowModel;

        /// <summary>Computes this frame's targets from the device samples (in the constructor's device order). Allocation-free.</summary>
        public void Compute(ReadOnlySpan<DeviceSample> samples, ref BodyTargets targets)
        {
            targets.HipsActive = Joint(samples, DeviceRole.Pelvis, out targets.Hips);
            targets.HeadActive = Joint(samples, DeviceRole.Head, out targets.Head);
            if (targets.HipsActive) _lastHips = targets.Hips;
            if (targets.HeadActive) _lastHead = targets.Head;
            targets.SpineBend = Quaternion.Identity;
            Quaternion rootTurn = Quaternion.Normalize(_lastHips.Rotation * Quaternion.Conjugate(_hipsRotation0));
            if (targets.HipsActive && targets.HeadActive)
            {
                Vector3 w0 = Vector3.Transform(_rootToHead0, rootTurn);
                targets.SpineBend = Rotations.FromTo(w0, targets.Head.Position - targets.Hips.Position);
            }
            Quaternion torso = Rotations.FromTo(Vector3.Transform(_rootToHead0, rootTurn), _lastHead.Position - _lastHips.Position) * rootTurn;
            Leg(samples, BodySide.Left, ref targets.LeftFoot);
            Leg(samples, BodySide.Right, ref targets.RightFoot);
            Arm(samples, BodySide.Left, torso, ref targets.LeftHand);
            Arm(samples, BodySide.Right, torso, ref targets.RightHand);
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

        // The knee's hint: the ankle plus one leg length along the chosen bend direction (only its part off the hip-ankle
        // axis matters to the IK).
        private void Leg(ReadOnlySpan<DeviceSample> samples, BodySide side, ref LimbTarget target)
        {
            int s = (int)side;
            target.IsActive = Joint(samples, BodyRoles.Foot(side), out target.Goal);
            if (!target.IsActive) return;
            if (_kneeModel == KneeHintModel.CalibrationFrame)
            {
                target.Hint = target.Goal.TransformPoint(_kneeInFoot[s]);
                return;
            }
            Vector3 hip = _lastHips.TransformPoint(_hipInHips[s]);
            Vector3 axis = Vectors.NormalizeOr(target.Goal.Position - hip, -Vector3.UnitY);
            // The hip's flexion direction: square to the leg's axis, in the plane square to the hip line.
            Vector3 hipLine = _lastHips.TransformDirection(_hipLineInHips);
            Vector3 pelvis = Vector3.Cross(axis, hipLine);
            Vector3 foot = Vector3.Cross(axis, target.Goal.TransformDirection(_lateralInFoot[s]));
            Vector3 direction;
            switch (_kneeModel)
            {
                case KneeHintModel.Pelvis: direction = pelvis; break;
                case KneeHintModel.Foot: direction = foot; break;
                case KneeHintModel.Toes:
                    direction = Vectors.ProjectOnPlane(target.Goal.TransformDirection(_toesInFoot[s]), axis) + FallbackWeight * Faded(pelvis);
                    break;
                case KneeHintModel.AnkleHinge: direction = AnkleHinge(hip, target.Goal, axis, pelvis, s); break;
                case KneeHintModel.PelvisAndFoot: direction = pelvis + foot; break;
                case KneeHintModel.OuterOfPelvisAndFoot:
                default: direction = OuterOf(pelvis, foot, side == BodySide.Left ? -hipLine : hipLine); break;
            }
            // A leg along the hip line (the splits) with the toes along it too: the body's forward.
            Vector3 fallback = Vectors.ProjectOnPlane(_lastHips.TransformDirection(_forwardInHips), axis);
            target.Hint = target.Goal.Position + Vectors.NormalizeOr(direction, Vectors.NormalizeOr(fallback, Vector3.UnitZ)) * _legLength[s];
        }

        // The pelvis's and the foot's flexion directions, the one that puts the knee further out weighted most. Where they
        // disagree, either the hip has turned the thigh (the foot's is right) or the shin has turned against the foot (the
        // pelvis's is right), and the knee kneeling, squatting or lunging is the outer of the two, not knock-kneed between
        // them. Equally far out (most of walking), their sum; each keeps its length (how square its axis is to the leg), and
        // the weights are smooth in the devices, so the hint is as continuous as the sum.
        private static Vector3 OuterOf(Vector3 pelvis, Vector3 foot, Vector3 outward)
        {
            float towardPelvis = 1f / (1f + MathF.Exp(-OuterPlaneGain * Vector3.Dot(pelvis - foot, outward)));
            return 2f * (towardPelvis * pelvis + (1f - towardPelvis) * foot);
        }

        // The knee where the foot's sagittal plane (through the ankle, square to the foot's lateral axis) meets the circle of
        // knees the bone lengths allow; of the two, the one nearer the pelvis's flexion plane; the circle's point nearest
        // the plane where they do not meet. The pelvis's plane where the lateral axis lies along the leg.
        private Vector3 AnkleHinge(Vector3 hip, RigidPose ankle, Vector3 axis, Vector3 pelvis, int s)
        {
            Vector3 e1 = Vectors.NormalizeOr(pelvis, Vector3.Zero);
            if (e1 == Vector3.Zero) return pelvis;
            Vector3 e2 = Vector3.Cross(axis, e1);
            Vector3 lateral = ankle.TransformDirection(_lateralInFoot[s]);
            float q1 = Vector3.Dot(e1, lateral), q2 = Vector3.Dot(e2, lateral);
            float m = MathF.Sqrt(q1 * q1 + q2 * q2);       // the lateral axis's part square to the leg
            if (m < 0.2f) return e1;
            float d = Vector3.Distance(hip, ankle.Position);
            float l1 = _thigh[s], l2 = _shin[s];
            float along = Math.Max(-l1, Math.Min(l1, (l1 * l1 - l2 * l2 + d * d) / (2f * Math.Max(d, 1e-6f))));
            float r = MathF.Sqrt(Math.Max(0f, l1 * l1 - along * along));
            if (!(r > 1e-5f)) return e1;                      // a straight leg: any plane
            Vector3 centre = hip + axis * along;
            float p = Vector3.Dot(centre - ankle.Position, lateral);
            float c = -p / (r * m);
            float phi = MathF.Atan2(q2, q1);
            float theta;
            if (c >= 1f) theta = phi;
            else if (c <= -1f) theta = phi + MathF.PI;
            else
            {
                float spread = MathF.Acos(c);
                float a = phi + spread, b = phi - spread;
                theta = MathF.Cos(a) >= MathF.Cos(b) ? a : b;  // nearer the pelvis's plane (θ = 0)
            }
            Vector3 hinge = e1 * MathF.Cos(theta) + e2 * MathF.Sin(theta);
            // Fade to the pelvis's plane as the lateral axis turns along the leg (m from 0.4 down to 0.2).
            float w = Math.Min(1f, (m - 0.2f) / 0.2f);
            return Vectors.NormalizeOr(hinge * w + e1 * (1f - w), e1);
        }

        // A fallback direction's part square to a limb's axis (as long as the sine of its angle to the axis), normalised
        // except within 15° of the axis (sin 15° = FallbackWeight, the angle within which a hand counts as along it), where
        // it fades to nothing: normalised there too, it turns round in the one frame the limb passes through it, and a hand
        // or toes that weigh no more turn the limb with it (a 30° bent elbow by up to 123° and 11 cm in a frame).
        private static Vector3 Faded(Vector3 squareToAxis) => squareToAxis / Math.Max(squareToAxis.Length(), FallbackWeight);

        // The elbow's hint: the wrist plus one arm length along the chosen bend direction.
        private void Arm(ReadOnlySpan<DeviceSample> samples, BodySide side, Quaternion torso, ref LimbTarget target)
        {
            int s = (int)side;
            target.IsActive = Joint(samples, BodyRoles.Hand(side), out target.Goal);
            if (!target.IsActive) return;
            if (_elbowModel == ElbowHintModel.CalibrationFrame)
            {
                target.Hint = target.Goal.TransformPoint(_elbowInHand[s]);
                return;
            }
            // The shoulder where the torso carries it (the IK places the real one; this only sets the axis).
            Vector3 shoulder = _lastHips.Position + Vector3.Transform(_shoulderFromHips[s], torso);
            Vector3 axis = Vectors.NormalizeOr(target.Goal.Position - shoulder, -Vector3.UnitY);
            Vector3 up = Vectors.NormalizeOr(_lastHead.Position - _lastHips.Position, Vector3.UnitY);
            Vector3 outward = Vector3.Transform(_right0, torso) * (side == BodySide.Left ? -1f : 1f);
            Vector3 back = Vector3.Cross(outward, up) * (side == BodySide.Left ? 1f : -1f);
            // With the hands held forward (controllers), the upper arm hangs and the elbow falls down, out and back.
            Vector3 downOutBack = Faded(Vectors.ProjectOnPlane(Vectors.NormalizeOr(outward - up + back, Vector3.Zero), axis));
            Vector3 direction = _elbowModel == ElbowHintModel.DownOutBack
                ? downOutBack
                : Vectors.ProjectOnPlane(-target.Goal.TransformDirection(_handInHand[s]), axis) + FallbackWeight * downOutBack;
            Vector3 fallback = Vectors.ProjectOnPlane(-up, axis);
            target.Hint = target.Goal.Position + Vectors.NormalizeOr(direction, Vectors.NormalizeOr(fallback, -Vector3.UnitZ)) * _armLength[s];
        }
    }
}
