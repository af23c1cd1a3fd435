using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Poses a whole humanoid skeleton from <see cref="BodyTargets"/>: the hips at their target, the spine bent
    /// toward the head target, the head turned like the HMD, then both legs and both arms by <see cref="TwoBoneIk"/>.
    /// Built once per avatar; solving allocates nothing. A clavicle keeps for a while the shrug its hand needed (<see cref="ShrugReleaseSeconds"/>).
    /// </summary>
    /// <remarks>
    /// Spine: the bend <see cref="BodyTargets.SpineBend"/> (the paper's angle α between w0 and wt, with its axis) is
    /// shared equally by the spine joints (Spine, Chest, UpperChest, Neck as present): starting from the reference
    /// pose each frame, every joint turns by α/n about the bend's axis, which curves the back instead of folding it at
    /// one joint. Where the head is nearer the first spine joint than that curve puts it, every joint above the first
    /// also flexes by the same φ about the hip line (left to right hip joint; forward where the back is straight), φ
    /// chosen by damped least squares (one-variable Levenberg–Marquardt) so that the chord matches the target's distance
    /// with a stiffness (<see cref="ChordNoiseMetres"/>):
    /// near a straight back the chord changes with the square of φ, so the devices' noise alone would flex the back
    /// back and forth by centimetres; a stiff back leaves the head up to that noise short instead. One swing at the
    /// first spine joint then aims the head at its target.
    /// When the spine ends in a neck below other spine joints, the neck is then moved part of the way
    /// (<see cref="NeckFollowsHead"/>) to where it would be if it had turned with the head, the joints below it are bent
    /// again the same way to reach it, and the neck aims the head at its target. Clavicles that hang from that neck (3ds
    /// Max Biped hangs them from its Neck bone) are turned in the frame of the joint below it, as clavicles that hang from
    /// the chest are, so the neck's following the head does not swing the shoulders.
    /// </remarks>
    public sealed class FullBodyIk
    {
        private const int SpineIterations = 12;
        private const float SpineTolerance = 1e-4f;
        private const float MaxSpineJointRadians = 1.2f;
        private const float MaxSpineStepRadians = 0.3f;
        private const float SpineStepTolerance = 1e-5f;
        private const float SlopeStepRadians = 1e-3f;
        private const int SpinePolishPasses = 4;
        private readonly int _hips;
        private readonly int _head;
        private readonly int[] _spine;
        private readonly LimbChain _leftLeg, _rightLeg, _leftArm, _rightArm;
        private readonly Quaternion[] _spineReference;
        private readonly Shoulder _leftShoulder, _rightShoulder;
        private const float MaxClavicleDegrees = 20f;

        // The straight arm's steadying (StraightArmCutoffHz): the clavicle's largest turn for it (3° moves a 15 cm clavicle's
        // shoulder by 8 mm), and the shares of the shoulder's move that change its distance from the hand's goal below which
        // it does nothing and from which it does all (the shoulder then moves at most 4 and 2 times what the distance changes).
        private const float MaxSteadyingDegrees = 3f;
        private const float SteadyingNoEfficiency = 0.25f;
        private const float SteadyingFullEfficiency = 0.5f;

        // A shrug that reached its goal is held; one whose goal needed more than the shoulder's range, or lay beyond any
        // reach (counted as the shoulder's arc that distance would be: ShrugToward), says less about the shoulder the
        // further it is (a longer reach than the avatar's, then a glitch or swapped controllers): held in part,
        // fading from all of it at MaxClavicleDegrees to none at HoldFadeEndDegrees, so that the held shrug is a continuous
        // function of the goals (held whole or not at all, a goal either side of the 20° line held 20° or nothing for seconds).
        private const float HoldFadeEndDegrees = 30f;

        private static float HoldWeight(float neededDegrees) =>
            Math.Clamp((HoldFadeEndDegrees - neededDegrees) / (HoldFadeEndDegrees - MaxClavicleDegrees), 0f, 1f);
        private readonly int[] _spinePath;
        private readonly int[] _spineIndexOnPath;     // each path joint's index in _spine, -1 for a joint between them
        private readonly int[] _spineOnPath;          // each spine joint's index in _spinePath
        // What a frame's solve reads before its final forward kinematics, the joints it updates on the way (parents
        // first): the joints above the hips (before they are placed: a floor-level root, when the origin moved); the
        // spine's first joint and the legs' roots, which the spine's bend axis reads, and every joint above them (after the
        // hips are placed); where each arm starts (its clavicle, else its upper arm), the legs' roots and every joint above
        // them (after the spine and head: a rig may hang its thighs from a spine joint). Nothing the solve reads is left
        // from an earlier frame's world poses or from before a joint above it moved.
        private readonly int[] _aboveHips, _beforeSpineAndLegs, _beforeLimbs;
        // The final forward kinematics of a frame that solved every part (the spine to the head, both feet, both hands): every
        // joint but those the solve left up to date (the joints updated before the limbs, the spine's path below the head,
        // whose rotation is set after the spine's last update, each limb's chain, each clavicle down to its upper arm), parents
        // first. A frame that left a part out updates the whole skeleton.
        private readonly int[] _afterFullSolve;
        private readonly int _neck = -1;              // the neck, when it is the last spine joint and more come before it
        private readonly Vector3 _neckInHead;         // the neck joint in the head's frame, in the reference pose
        private float _spineFlex;                     // the last spine solve's flexion per joint (radians)
        private readonly Vector3 _hipLineInHips;      // unit, left to right hip joint, in the hips' frame, in the reference pose
        private readonly float _chordCurvature;       // k in chord(φ) ≈ L − kφ², the straight calibration back's (metres per radian²)
        private float _flexStiffnessSquared;          // λ² = 2 ChordNoiseMetres k (metres² per radian²)
        private float _chordNoiseMetres = DefaultChordNoiseMetres;
        // The first solve's start, forward of a straight back (whose chord is even in φ: the start decides which way the back
        // curls): 0.01 rad, where the chord's slope is well above its float rounding (at 0.001 rad the chord changed by a few
        // roundings over the slope's step, and a straight back curled whichever way they fell). Where the bend's share
        // arches the back backward (the head behind the hips), the start is forward of that arch too, up to
        // MaxStraightenedArch (0.05 rad, 3°) a joint, so that a slouched back does not flip to arched as the head passes over
        // the hips; a back arched further, by a lean back, keeps its arch (Documentation~/solver.md, "The back's flexion").
        private const float FirstFlex = 0.01f;
        private const float MaxStraightenedArch = 0.05f;

        /// <summary>
        /// The default <see cref="ChordNoiseMetres"/>: 1.4 mm, the noise in the distance between two devices of 1 mm noise
        /// each (current trackers', and the simulator's), the pelvis tracker and the HMD.
        /// </summary>
        public const float DefaultChordNoiseMetres = 0.0014f;

        /// <summary>
        /// The change in the hips-to-head distance that the back does not flex for (metres, <see cref="DefaultChordNoiseMetres"/>).
        /// Near a straight back the distance changes with the square of the flexion, so the devices' noise alone would flex
        /// the back to and fro by centimetres a frame. The flexion φ minimises (chord(φ) − target distance)² + λ²φ², with
        /// λ² = 2 × this × k and k the curvature of the avatar's straight calibration back (chord ≈ L − kφ²): a reach shorter
        /// than the straight back by less than this leaves the back straight and the head that much short of its target,
        /// a shorter one flexes it and leaves the head about this much short. 0 flexes the back until the head is on its
        /// target (noise-free targets). See Documentation~/solver.md ("The back's flexion").
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float ChordNoiseMetres
        {
            get => _chordNoiseMetres;
            set
            {
                _chordNoiseMetres = SettingChecks.NotNegativeFinite(value, nameof(FullBodyIk), nameof(ChordNoiseMetres));
                _flexStiffnessSquared = 2f * value * _chordCurvature;
            }
        }

        // The back's chords (the first spine joint to the head, and to the neck for the second solve) through their filters.
        private readonly DistanceFilter _headChord = new DistanceFilter(), _neckChord = new DistanceFilter();
        private float _chordCutoffHz = DefaultChordCutoffHz;

        /// <summary>The default <see cref="ChordCutoffHz"/>: 1 Hz.</summary>
        public const float DefaultChordCutoffHz = 1f;

        /// <summary>
        /// The cutoff (Hz, for a still back; <see cref="DefaultChordCutoffHz"/>) of the filter on the distance the back bends
        /// for. Near a straight back the hips-to-head distance changes with the square of the flexion, so the devices' noise
        /// in it (the pelvis tracker's and the HMD's, their turns on the levers to the joints included) flexed the back to
        /// and fro, the chest moving by a centimetre or more a frame where the hips and head moved 3–4 mm;
        /// <see cref="ChordNoiseMetres"/> only damps it. Each frame the back bends for that distance (and the neck's) through a One Euro filter, its cutoff rising
        /// 20 Hz per m/s of the distance's speed, so a bow lags little; the head is left what the filter took out off its
        /// target (a millimetre or two standing, up to about 4 mm more in a bow), which the polish does not take up (that
        /// would swing the top joints and the shoulders by the noise). Only the frame-by-frame
        /// <see cref="Solve(in BodyTargets, SkeletonPose, float)"/> filters; a lost head restarts it; 0 turns it off. See
        /// Documentation~/solver.md ("The chord's filter").
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float ChordCutoffHz
        {
            get => _chordCutoffHz;
            set
            {
                _chordCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(FullBodyIk), nameof(ChordCutoffHz));
                _headChord.Reset();
                _neckChord.Reset();
            }
        }

        private readonly LimbReachFilter _leftLegReach, _rightLegReach, _leftArmReach, _rightArmReach;
        private float _straightLegCutoffHz = DefaultStraightLegCutoffHz;

        /// <summary>The default <see cref="StraightLegCutoffHz"/>: 1 Hz.</summary>
        public const float DefaultStraightLegCutoffHz = 1f;

        /// <summary>
        /// The cutoff (Hz, for a still leg; <see cref="DefaultStraightLegCutoffHz"/>) of the filter that steadies a leg held
        /// straight: near full reach the knee's distance from the hip-to-ankle line grows with the square root of the slack,
        /// so the devices' noise in that distance alone moved a straight knee by centimetres a frame. Within 2.5 % of its
        /// reach of full reach a leg bends for the hip-to-ankle distance through a One Euro filter (its cutoff rising with the
        /// distance's speed), with a soft reach 1/450 of the reach either side of full reach (2 mm for a 0.9 m leg: a
        /// straight leg bent by 4°, its foot at most 0.5 mm short), the foot then that filter's lag (a millimetre or so) from
        /// its target. Only the frame-by-frame
        /// <see cref="Solve(in BodyTargets, SkeletonPose, float)"/> filters; 0 turns the filter off. See
        /// Documentation~/solver.md ("A straight limb shivers").
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float StraightLegCutoffHz
        {
            get => _straightLegCutoffHz;
            set
            {
                _straightLegCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(FullBodyIk), nameof(StraightLegCutoffHz));
                _leftLegReach.Reset();
                _rightLegReach.Reset();
            }
        }

        private float _straightArmCutoffHz = DefaultStraightArmCutoffHz;

        /// <summary>The default <see cref="StraightArmCutoffHz"/>: 1 Hz.</summary>
        public const float DefaultStraightArmCutoffHz = 1f;

        /// <summary>
        /// The cutoff (Hz, for a still arm; <see cref="DefaultStraightArmCutoffHz"/>) of the filter that steadies an arm held
        /// straight, as <see cref="StraightLegCutoffHz"/> does a leg, without moving the hand off its goal: within 5 % of its
        /// reach of full reach (twice the leg's zone: the hand does not lag) the clavicle turns (for this frame only, not held
        /// like the shrug) by the least angle, at most 3°, that puts the shoulder the filtered distance from the hand's goal,
        /// and the arm is solved exactly from there, so the elbow bends for the filtered distance and the hand is where the
        /// exact solve puts it. The shoulder then moves by the noise the filter takes out (about a millimetre; at most twice
        /// that where the turn is used in full, the arm within 60° of the way the turn moves the shoulder), and the clavicle
        /// does nothing where the arm points along it (arms out sideways, as in the T-pose), whose elbow still shivers. Only
        /// the frame-by-frame <see cref="Solve(in BodyTargets, SkeletonPose, float)"/> steadies, and only an arm with a
        /// clavicle; 0 turns it off. See Documentation~/solver.md ("A straight limb shivers").
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float StraightArmCutoffHz
        {
            get => _straightArmCutoffHz;
            set
            {
                _straightArmCutoffHz = SettingChecks.NotNegativeFinite(value, nameof(FullBodyIk), nameof(StraightArmCutoffHz));
                _leftArmReach.Reset();
                _rightArmReach.Reset();
            }
        }

        // A setting that is a non-negative finite number (0 turns its feature off); else the setter throws.
        /// <summary>
        /// How far the neck follows the head's orientation (0: the neck lies where the evenly bent spine puts it;
        /// 1: the neck bone turns with the head): a nodding or tilted head carries the neck part of the way, as the
        /// cervical spine does. 0.5 lowered the mean joint error of the shared Rigify and MocapBank clips by 1.2–1.7
        /// mm and raised the Mixamo clip's by 0.4 mm (seeds 1 and 2); see Documentation~/solver.md.
        /// </summary>
        public const float NeckFollowsHead = 0.5f;

        /// <summary>
        /// Precomputes the chains of <paramref name="map"/>'s skeleton. <paramref name="reference"/> is the pose the
        /// spine is bent from every frame (the avatar's calibration T-pose); null uses the skeleton's rest pose.
        /// </summary>
        /// <exception cref="ArgumentException">The map lacks a required bone, or a joint of <paramref name="reference"/> is not
        /// a pose (<see cref="RigidPose.IsValid"/>: a finite position, a unit rotation).</exception>
        public FullBodyIk(HumanoidMap map, SkeletonPose reference = null)
        {
            Map = map ?? throw new ArgumentNullException(nameof(map));
            map.RequireComplete(nameof(map));
            Skeleton s = map.Skeleton;
            _hips = map[HumanoidBone.Hips];
            _head = map[HumanoidBone.Head];
            var spine = new List<int>();
            foreach (HumanoidBone b in new[] { HumanoidBone.Spine, HumanoidBone.Chest, HumanoidBone.UpperChest, HumanoidBone.Neck })
                if (map.Has(b) && s.IsAncestorOrSelf(map[b], _head)) spine.Add(map[b]);
            _spine = spine.ToArray();
            var path = new List<int>();
            if (_spine.Length > 0)
                for (int j = _head; j != _spine[0]; j = s.GetParent(j)) path.Insert(0, j);
            if (_spine.Length > 0) path.Insert(0, _spine[0]);
            _spinePath = path.ToArray();
            _spineIndexOnPath = new int[_spinePath.Length];
            for (int k = 0; k < _spinePath.Length; k++) _spineIndexOnPath[k] = Array.IndexOf(_spine, _spinePath[k]);
            _spineOnPath = new int[_spine.Length];
            for (int i = 0; i < _spine.Length; i++) _spineOnPath[i] = Array.IndexOf(_spinePath, _spine[i]);
            _spineReference = new Quaternion[_spine.Length];
            for (int i = 0; i < _spine.Length; i++)
                _spineReference[i] = reference != null ? reference.Local[_spine[i]].Rotation : s.GetRestLocal(_spine[i]).Rotation;
            var refLocal = new RigidPose[s.JointCount];
            if (reference != null) Array.Copy(reference.Local, refLocal, refLocal.Length); else s.GetRestLocal(refLocal);
            for (int j = 0; j < refLocal.Length; j++)
                if (!refLocal[j].IsValid)
                    throw new ArgumentException($"Joint '{s.GetName(j)}' of the reference pose is not a pose (a finite position, a unit rotation): {refLocal[j]}.", nameof(reference));
            var refWorld = new RigidPose[s.JointCount];
            s.ComputeWorld(refLocal, refWorld);
            if (_spine.Length >= 2 && _spine[_spine.Length - 1] == map[HumanoidBone.Neck])
            {
                _neck = _spine[_spine.Length - 1];
                _neckInHead = refWorld[_head].InverseTransformPoint(refWorld[_neck].Position);
            }
            _leftLeg = new LimbChain(s, map[HumanoidBone.LeftUpperLeg], map[HumanoidBone.LeftLowerLeg], map[HumanoidBone.LeftFoot]);
            _rightLeg = new LimbChain(s, map[HumanoidBone.RightUpperLeg], map[HumanoidBone.RightLowerLeg], map[HumanoidBone.RightFoot]);
            _leftLegReach = new LimbReachFilter(Reach(refWorld, _leftLeg), LimbReachFilter.LegGateOfReach);
            _rightLegReach = new LimbReachFilter(Reach(refWorld, _rightLeg), LimbReachFilter.LegGateOfReach);
            _leftArm = new LimbChain(s, map[HumanoidBone.LeftUpperArm], map[HumanoidBone.LeftLowerArm], map[HumanoidBone.LeftHand]);
            _rightArm = new LimbChain(s, map[HumanoidBone.RightUpperArm], map[HumanoidBone.RightLowerArm], map[HumanoidBone.RightHand]);
            _leftArmReach = new LimbReachFilter(Reach(refWorld, _leftArm), LimbReachFilter.ArmGateOfReach);
            _rightArmReach = new LimbReachFilter(Reach(refWorld, _rightArm), LimbReachFilter.ArmGateOfReach);
            Vector3 hipLine = Vectors.NormalizeOr(refWorld[_rightLeg.Root].Position - refWorld[_leftLeg.Root].Position, Vector3.UnitX);
            _hipLineInHips = Vector3.Normalize(Vector3.Transform(hipLine, Quaternion.Conjugate(refWorld[_hips].Rotation)));
            _chordCurvature = ChordCurvature(refWorld, hipLine);
            ChordNoiseMetres = DefaultChordNoiseMetres; // and the stiffness with it
            _leftShoulder = new Shoulder(s, map[HumanoidBone.LeftShoulder], _leftArm.Root, _neck, refLocal, refWorld);
            _rightShoulder = new Shoulder(s, map[HumanoidBone.RightShoulder], _rightArm.Root, _neck, refLocal, refWorld);
            _aboveHips = AncestorsOrSelf(s, -1, s.GetParent(_hips));
            _beforeSpineAndLegs = AncestorsOrSelf(s, -1, _spine.Length > 0 ? _spine[0] : _head, _leftLeg.Root, _rightLeg.Root);
            _beforeLimbs = AncestorsOrSelf(s, -1, ArmStart(_leftShoulder, _leftArm), ArmStart(_rightShoulder, _rightArm), _leftLeg.Root, _rightLeg.Root);
            var upToDate = new HashSet<int>(_aboveHips);
            upToDate.UnionWith(_beforeLimbs);
            upToDate.UnionWith(_spinePath);
            upToDate.Remove(_head);
            foreach (LimbChain limb in new[] { _leftLeg, _rightLeg, _leftArm, _rightArm }) upToDate.UnionWith(limb.Path);
            _leftShoulder.AddPosedJoints(upToDate);
            _rightShoulder.AddPosedJoints(upToDate);
            var afterFullSolve = new List<int>();
            for (int j = 0; j < s.JointCount; j++)
                if (!upToDate.Contains(j)) afterFullSolve.Add(j);
            _afterFullSolve = afterFullSolve.ToArray();
        }

        /// <summary>
        /// How slowly a shrug is released (time constant, seconds): 3 s. The six devices see the clavicles only through the
        /// hands' reach: a hand beyond its arm's reach needs its clavicle turned toward it, and a wearer whose shoulders sit
        /// lower or further forward than in the T-pose (arms hanging: most of the time) keeps needing it. So the shrug a
        /// hand needed is held, and moves the shoulder on the frames in between too, where the hand is in reach and says
        /// nothing; eased back toward the calibration pose's clavicle, a shrug one reach needed does not stay for good.
        /// Measured in Documentation~/solver.md; not fitted to the shared clips (3 s was chosen first, a posture's time scale,
        /// 1.5 s and 3 s do better than no hold on each of them; longer holds trade the Rigify clip for MocapBank).
        /// </summary>
        public const float DefaultShrugReleaseSeconds = 3f;

        private float _shrugReleaseSeconds = DefaultShrugReleaseSeconds;

        /// <summary>
        /// How slowly a held shrug is released (time constant, seconds; <see cref="DefaultShrugReleaseSeconds"/>); 0 holds
        /// none: every frame's clavicles start from the calibration pose, as a single-frame solve does.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative, infinite or NaN.</exception>
        public float ShrugReleaseSeconds
        {
            get => _shrugReleaseSeconds;
            set
            {
                _shrugReleaseSeconds = SettingChecks.NotNegativeFinite(value, nameof(FullBodyIk), nameof(ShrugReleaseSeconds));
                if (value == 0f) _leftShoulder.Held = _rightShoulder.Held = Quaternion.Identity;
            }
        }

        /// <summary>The avatar's humanoid map.</summary>
        public HumanoidMap Map { get; }

        /// <summary>
        /// Poses <paramref name="pose"/> (its local transforms are the starting point and what inactive parts keep; its
        /// world transforms are recomputed where they are read, never taken from earlier), as a single frame: no shrug is
        /// held from earlier frames or kept for later ones. On return <see cref="SkeletonPose.World"/> is up to date.
        /// </summary>
        public IkReport Solve(in BodyTargets targets, SkeletonPose pose) => Solve(in targets, pose, 0f, false, false);

        /// <summary>
        /// Poses <paramref name="pose"/> as the frame <paramref name="deltaSeconds"/> after the previous one: the clavicles
        /// start from the shrug held from earlier frames, released by that much time (<see cref="ShrugReleaseSeconds"/>),
        /// and keep the one this frame needs. 0 (or a time that is not finite and positive: a repeated or paused frame)
        /// releases nothing. Allocates nothing.
        /// </summary>
        public IkReport Solve(in BodyTargets targets, SkeletonPose pose, float deltaSeconds) => Solve(in targets, pose, deltaSeconds, _shrugReleaseSeconds > 0f, true);

        private IkReport Solve(in BodyTargets targets, SkeletonPose pose, float deltaSeconds, bool holdShrugs, bool continuous)
        {
            if (pose == null) throw new ArgumentNullException(nameof(pose));
            var report = new IkReport();
            RigidPose[] w = pose.World;
            pose.UpdateWorld(_aboveHips);
            if (targets.HipsActive && targets.Hips.IsValid) pose.SetWorldPose(_hips, targets.Hips);
            pose.UpdateWorld(_beforeSpineAndLegs);

            bool chordFiltered = continuous && _chordCutoffHz > 0f;
            if (targets.HeadActive && targets.Head.IsValid)
            {
                if (_spine.Length > 0)
                {
                    SolveSpine(pose, targets.SpineBend, targets.Head, false, default, chordFiltered ? _headChord : null, deltaSeconds);
                    if (_neck >= 0)
                    {
                        // The neck part of the way to where it would be if it turned with the head; then the spine
                        // below it is bent again to put the neck there, and the neck aims the head at its target.
                        Vector3 bent = w[_neck].Position, followed = targets.Head.TransformPoint(_neckInHead);
                        Vector3 toNeck = Vector3.Lerp(bent, followed, NeckFollowsHead) - targets.Head.Position;
                        if (toNeck.LengthSquared() > 1e-12f)
                            SolveSpine(pose, targets.SpineBend, targets.Head, true, targets.Head.Position + Vector3.Normalize(toNeck) * _neckInHead.Length(),
                                chordFiltered ? _neckChord : null, deltaSeconds);
                    }
                }
                report.HeadDistanceLeft = Vector3.Distance(w[_head].Position, targets.Head.Position);
                pose.SetWorldRotation(_head, targets.Head.Rotation);
            }
            if (!chordFiltered || !targets.HeadActive || !targets.Head.IsValid)
            {
                // Without a head (or a frame that does not filter) the chords' history is stale by the time it comes back.
                _headChord.Reset();
                _neckChord.Reset();
            }
            pose.UpdateWorld(_beforeLimbs);

            report.LeftFoot = SolveLeg(pose, _leftLeg, _leftLegReach, in targets.LeftFoot, continuous, deltaSeconds);
            report.RightFoot = SolveLeg(pose, _rightLeg, _rightLegReach, in targets.RightFoot, continuous, deltaSeconds);
            // The held shrugs: released by the time passed, then the start of each arm's solve (an inactive hand's arm keeps its
            // pose, its shrug released all the same).
            if (holdShrugs && deltaSeconds > 0f && deltaSeconds < float.PositiveInfinity)
            {
                float release = 1f - MathF.Exp(-deltaSeconds / _shrugReleaseSeconds);
                _leftShoulder.Held = Quaternion.Normalize(Quaternion.Slerp(_leftShoulder.Held, Quaternion.Identity, release));
                _rightShoulder.Held = Quaternion.Normalize(Quaternion.Slerp(_rightShoulder.Held, Quaternion.Identity, release));
            }
            if (targets.LeftHand.IsActive) report.LeftHand = SolveArm(pose, _leftArm, _leftShoulder, _leftArmReach, in targets.LeftHand, holdShrugs, continuous, deltaSeconds);
            else { _leftShoulder.KeepStill(pose, holdShrugs); _leftArmReach.Reset(); }
            if (targets.RightHand.IsActive) report.RightHand = SolveArm(pose, _rightArm, _rightShoulder, _rightArmReach, in targets.RightHand, holdShrugs, continuous, deltaSeconds);
            else { _rightShoulder.KeepStill(pose, holdShrugs); _rightArmReach.Reset(); }
            bool solvedAll = targets.HeadActive && targets.Head.IsValid && targets.LeftFoot.IsActive && targets.RightFoot.IsActive
                && targets.LeftHand.IsActive && targets.RightHand.IsActive;
            if (solvedAll) pose.UpdateWorld(_afterFullSolve);
            else pose.UpdateWorld();
            return report;
        }

        // The spine: every spine joint takes the same share α/n of the bend about its axis and the same flexion φ about the
        // hip line, on top of its reference rotation (a smooth curve rather than a fold at one joint); φ by one-variable
        // Levenberg–Marquardt on (chord − wanted)² + λ²φ² (the chord: the first spine joint to the end joint); then one swing at
        // the first spine joint aims the end joint at its target.
        private void SolveSpine(SkeletonPose pose, Quaternion spineBend, RigidPose head, bool toNeck, Vector3 neckTarget, DistanceFilter chordFilter, float deltaSeconds)
        {
            RigidPose[] w = pose.World;
            Vector3 headTarget = head.Position;
            int count = _spine.Length, end = _head, endOnPath = _spinePath.Length - 1;
            Vector3 endTarget = headTarget;
            if (toNeck)
            {
                count--;
                end = _neck;
                endOnPath = _spineOnPath[count];
                endTarget = neckTarget;
            }
            Quaternion bend = Rotations.IsUnit(spineBend) ? Quaternion.Normalize(spineBend) : Quaternion.Identity;
            if (bend.W < 0f) bend = new Quaternion(-bend.X, -bend.Y, -bend.Z, -bend.W);
            float sinHalf = new Vector3(bend.X, bend.Y, bend.Z).Length();
            float alpha = 2f * MathF.Atan2(sinHalf, bend.W);
            Quaternion share = alpha > 1e-6f
                ? Quaternion.CreateFromAxisAngle(new Vector3(bend.X, bend.Y, bend.Z) / sinHalf, alpha / _spine.Length)
                : Quaternion.Identity;
            // The hip line (left to right hip joint, not a local axis of the hips, which differs between rigs), carried by
            // the hips from the calibration pose: a rig may hang the thighs from the first spine joint, whose world pose
            // is still last frame's here. Positive φ bends the head forward.
            Vector3 flexAxis = Vector3.Transform(_hipLineInHips, w[_hips].Rotation);
            Vector3 origin = w[_spine[0]].Position;
            float wanted = Vector3.Distance(origin, endTarget);
            // Frame by frame the back bends for the distance through its filter (ChordCutoffHz), and the end is left what
            // the filter took out short or long of its target: the polish below does not take it up again.
            float filtered = chordFilter != null ? chordFilter.Filter(wanted, deltaSeconds, _chordCutoffHz) : wanted;
            float filterShift = Math.Abs(filtered - wanted);
            wanted = filtered;

            // The second solve (to the neck) starts from the first's answer: the joints below the neck bend about as much; the
            // first starts FirstFlex forward of the straight back, which the bend's share may have arched (its turn about the
            // hip line, backward).
            // Levenberg–Marquardt on one variable: a step that does not lower the cost is taken again with more damping
            // (a target beyond a straight back's reach, where the slope is 0, with no stiffness would otherwise send φ as
            // far as a step goes).
            float phi = _spineFlex;
            if (!toNeck)
            {
                float backwardArch = alpha > 1e-6f ? -alpha / _spine.Length * Vector3.Dot(new Vector3(bend.X, bend.Y, bend.Z) / sinHalf, flexAxis) : 0f;
                phi = FirstFlex + Math.Clamp(backwardArch, 0f, MaxStraightenedArch);
            }
            int firstFlexed = PoseUnflexed(pose, share, count, endOnPath);
            float chord = BendSpine(pose, share, flexAxis, phi, count, firstFlexed, endOnPath);
            float slope = ChordSlope(pose, share, flexAxis, phi, count, firstFlexed, endOnPath, chord), posedPhi = phi + SlopeStepRadians;
            float cost = FlexCost(chord - wanted, phi), extraDamping = 0f;
            for (int i = 0; i < SpineIterations; i++)
            {
                float curvature = slope * slope + _flexStiffnessSquared + extraDamping;
                if (!(curvature > 0f)) break;
                float step = -((chord - wanted) * slope + _flexStiffnessSquared * phi) / curvature;
                float next = Math.Clamp(phi + Math.Clamp(step, -MaxSpineStepRadians, MaxSpineStepRadians), -MaxSpineJointRadians, MaxSpineJointRadians);
                if (!Vectors.IsFinite(next) || Math.Abs(next - phi) < SpineStepTolerance) break;
                float nextChord = BendSpine(pose, share, flexAxis, next, count, firstFlexed, endOnPath);
                posedPhi = next;
                float nextCost = FlexCost(nextChord - wanted, next);
                if (nextCost <= cost)
                {
                    // The slope from the step just taken (a secant): one pose per step, not two.
                    float secant = (nextChord - chord) / (next - phi);
                    phi = next;
                    chord = nextChord;
                    cost = nextCost;
                    if (Vectors.IsFinite(secant)) slope = secant;
                    extraDamping *= 0.1f;
                }
                else extraDamping = Math.Max(10f * extraDamping, curvature);
            }
            if (posedPhi != phi) BendSpine(pose, share, flexAxis, phi, count, firstFlexed, endOnPath); // the pose is a function of φ alone
            _spineFlex = phi;
            Quaternion aim = Rotations.FromTo(w[end].Position - origin, endTarget - origin);
            pose.RotateWorld(_spine[0], aim);
            pose.UpdateWorld(_spinePath); // the whole path: BendSpine stopped at the chord's end, and the aim turned the first joint
            if (end != _head)
            {
                pose.RotateWorld(_neck, Rotations.FromTo(w[_head].Position - w[_neck].Position, headTarget - w[_neck].Position));
                pose.UpdateWorld(_spinePath);
            }
            // What the one-axis curve cannot reach (a target that needs the back's reference curve undone in another
            // plane) is polished by cyclic coordinate descent, top joint first.
            // Not what the back's stiffness leaves on purpose, up to about the chord noise, nor what the chord's filter took
            // out (polishing either away would flex the back by the noise again, the top joints and the shoulders with it).
            // The neck's second solve leaves more (the whole spine's λ on a shorter chain), and that is polished
            // (Documentation~/solver.md).
            float polishBeyond = SpineTolerance + _chordNoiseMetres + filterShift;
            for (int pass = 0; pass < SpinePolishPasses && Vector3.Distance(w[_head].Position, headTarget) > polishBeyond; pass++)
                for (int i = _spine.Length - 1; i >= 0; i--)
                {
                    Vector3 pivot = w[_spine[i]].Position;
                    pose.RotateWorld(_spine[i], Rotations.FromTo(w[_head].Position - pivot, headTarget - pivot));
                    pose.UpdateWorld(_spinePath);
                }
        }

        private float FlexCost(float chordError, float phi) => chordError * chordError + _flexStiffnessSquared * phi * phi;

        // The chord's rate of change with φ, by a forward difference (each joint's turn is applied in the world frame on
        // top of the turns below it, so the joints' flexion axes are the hip line turned by the bend's share below them:
        // no simple closed form); leaves the spine posed at phi + SlopeStepRadians.
        private float ChordSlope(SkeletonPose pose, Quaternion share, Vector3 flexAxis, float phi, int count, int firstFlexed, int endOnPath, float chord) =>
            (BendSpine(pose, share, flexAxis, phi + SlopeStepRadians, count, firstFlexed, endOnPath) - chord) / SlopeStepRadians;

        // Poses the start of the spine's path that φ does not move, the same for every φ of one solve: the first spine joint
        // (turned by the bend's share alone) and the path up to the first joint that flexes (the path's index of which is
        // returned; past endOnPath when none does). BendSpine poses the rest, from there.
        private int PoseUnflexed(SkeletonPose pose, Quaternion share, int count, int endOnPath)
        {
            int firstFlexed = 0;
            while (firstFlexed <= endOnPath && !(_spineIndexOnPath[firstFlexed] >= 1 && _spineIndexOnPath[firstFlexed] < count)) firstFlexed++;
            PosePath(pose, share, share, count, 0, firstFlexed); // no joint there flexes: the second turn is not used
            return firstFlexed;
        }

        // Sets the spine to its reference with each of its first count joints turned by the bend's share and, above the
        // first (whose flexion would not change the chord, only swing what hangs from it: 3ds Max Biped's thighs), by phi
        // about the flexion axis (the others keep their reference); returns the distance from the first spine joint
        // to the path's joint endOnPath. The path before firstFlexed is as PoseUnflexed left it (φ does not move it), and
        // the path beyond endOnPath (the head, for the chord to the neck) is left for the update after the aim.
        private float BendSpine(SkeletonPose pose, Quaternion share, Vector3 flexAxis, float phi, int count, int firstFlexed, int endOnPath)
        {
            Quaternion turn = Quaternion.Normalize(Quaternion.CreateFromAxisAngle(flexAxis, phi) * share);
            PosePath(pose, share, turn, count, firstFlexed, endOnPath + 1);
            return Vector3.Distance(pose.World[_spine[0]].Position, pose.World[_spinePath[endOnPath]].Position);
        }

        // The spine's path from index `from` up to (not including) `to`, in one pass down it: each joint's world pose from its
        // parent's, then, for one of the first count spine joints, its turn (the first one's `share`, the others' `turn`)
        // applied about its own position (which it does not move), as turning the joints one by one from the bottom and
        // updating the path after each would give, at a path's cost instead of one per turned joint.
        private void PosePath(SkeletonPose pose, Quaternion share, Quaternion turn, int count, int from, int to)
        {
            RigidPose[] local = pose.Local, world = pose.World;
            Skeleton s = pose.Skeleton;
            for (int k = from; k < to; k++)
            {
                int j = _spinePath[k], spineIndex = _spineIndexOnPath[k];
                int parent = s.GetParent(j);
                RigidPose parentWorld = parent < 0 ? pose.Origin : world[parent];
                if (spineIndex >= 0) local[j] = local[j].WithRotation(_spineReference[spineIndex]);
                RigidPose placed = parentWorld * local[j];
                if (spineIndex >= 0 && spineIndex < count)
                {
                    Quaternion turned = Quaternion.Normalize((spineIndex == 0 ? share : turn) * placed.Rotation);
                    local[j] = local[j].WithRotation(Quaternion.Normalize(Quaternion.Conjugate(parentWorld.Rotation) * turned));
                    // parentWorld * local[j], whose position is the one placed already: the turn is about the joint itself.
                    placed = new RigidPose(placed.Position, Quaternion.Normalize(parentWorld.Rotation * local[j].Rotation));
                }
                world[j] = placed;
            }
        }

        // k in chord(φ) ≈ L − kφ² for the whole spine (every spine joint flexed by φ about axis) in the calibration pose,
        // from the chord at φ = 0 and ±0.05 rad (the segments' directions turned about the axis by as many φ as there are
        // turned joints below them); 0 for a spine that flexing does not shorten (one joint; a reference curved so far
        // that flexing lengthens it).
        private float ChordCurvature(RigidPose[] refWorld, Vector3 axis)
        {
            if (_spinePath.Length < 2) return 0f;
            const float h = 0.05f;
            double Chord(float phi)
            {
                Vector3 chord = Vector3.Zero;
                int turned = 0;
                for (int k = 0; k + 1 < _spinePath.Length; k++) // the path runs from the first spine joint to the head
                {
                    if (_spineIndexOnPath[k] >= 0) turned++;
                    Vector3 segment = refWorld[_spinePath[k + 1]].Position - refWorld[_spinePath[k]].Position;
                    chord += Vector3.Transform(segment, Quaternion.CreateFromAxisAngle(axis, turned * phi));
                }
                return chord.Length();
            }
            double k2 = (2.0 * Chord(0f) - Chord(h) - Chord(-h)) / (2.0 * h * h);
            return k2 > 0.0 && double.IsFinite(k2) ? (float)k2 : 0f;
        }

        // A leg; frame by frame (continuous), held straight, it bends for its filtered hip-to-ankle distance (LimbReachFilter):
        // the goal moved along the hip-to-goal line to that distance, its rotation kept. A lost foot restarts the filter.
        private LimbResult SolveLeg(SkeletonPose pose, LimbChain leg, LimbReachFilter filter, in LimbTarget target, bool continuous, float deltaSeconds)
        {
            if (!target.IsActive)
            {
                filter.Reset();
                return default;
            }
            RigidPose goal = target.Goal;
            if (continuous && _straightLegCutoffHz > 0f && Vectors.IsFinite(goal.Position))
            {
                Vector3 hip = pose.World[leg.Root].Position;
                Vector3 toGoal = goal.Position - hip;
                float distance = toGoal.Length();
                float bendFor = filter.Filter(distance, deltaSeconds, _straightLegCutoffHz);
                if (distance > 1e-6f && bendFor != distance) goal = new RigidPose(hip + toGoal * (bendFor / distance), goal.Rotation);
            }
            LimbResult result = TwoBoneIk.Solve(pose, leg, goal, target.Hint);
            if (goal.Position == target.Goal.Position) return result;
            // Reported against the foot's own target, not the one moved for the filter.
            float left = Vector3.Distance(pose.World[leg.End].Position, target.Goal.Position);
            return new LimbResult(left <= TwoBoneIk.ReachedTolerance, left);
        }

        private static float Reach(RigidPose[] world, LimbChain limb) =>
            Vector3.Distance(world[limb.Root].Position, world[limb.Middle].Position) + Vector3.Distance(world[limb.Middle].Position, world[limb.End].Position);

        // An arm starts from its clavicle's held shrug (the calibration pose's clavicle when none is held); if its hand still
        // cannot reach the goal, the clavicle turns toward it by the least angle that brings the goal within the arm's reach,
        // the whole shrug at most MaxClavicleDegrees from the calibration pose (as a shoulder shrugs), the arm is solved
        // again, and the shrug is held (whole if it was enough, in part a little beyond: HoldWeight): a goal out of any
        // shoulder's reach (swapped controllers, a glitch) says nothing about where the wearer's shoulder is. What is still
        // out of reach is reported. Frame by frame (continuous), an arm held straight is then steadied (Steady).
        private LimbResult SolveArm(SkeletonPose pose, LimbChain arm, Shoulder shoulder, LimbReachFilter filter, in LimbTarget target, bool hold, bool continuous, float deltaSeconds)
        {
            if (shoulder.Clavicle < 0) return TwoBoneIk.Solve(pose, arm, target.Goal, target.Hint);
            Quaternion frameRotation = shoulder.FrameRotation(pose);
            Quaternion start = hold ? shoulder.Held : Quaternion.Identity;
            shoulder.Set(pose, frameRotation, Quaternion.Normalize(start * shoulder.Reference));
            LimbResult result = TwoBoneIk.Solve(pose, arm, target.Goal, target.Hint);
            if (result.Reached || !(result.DistanceLeft > 1e-4f))
                return continuous ? Steady(pose, arm, shoulder, filter, in target, frameRotation, start, result, deltaSeconds) : result;

            Quaternion turn = ShrugToward(pose.World[shoulder.Clavicle].Position, pose.World[arm.Root].Position, pose.World[arm.End].Position,
                target.Goal.Position, out float beyondDegrees);
            Quaternion shrug = Quaternion.Normalize(Quaternion.Conjugate(frameRotation) * turn * frameRotation * start); // in the frame joint's frame
            if (!Rotations.IsFinite(shrug)) return result;
            float angle = Rotations.AngleDegrees(Quaternion.Identity, shrug);
            float needed = angle + beyondDegrees;
            if (angle > MaxClavicleDegrees) shrug = Quaternion.Normalize(Quaternion.Slerp(Quaternion.Identity, shrug, MaxClavicleDegrees / angle));
            shoulder.Set(pose, frameRotation, Quaternion.Normalize(shrug * shoulder.Reference));
            if (hold) shoulder.Held = Quaternion.Normalize(Quaternion.Slerp(shoulder.Held, shrug, HoldWeight(needed)));
            result = TwoBoneIk.Solve(pose, arm, target.Goal, target.Hint);
            return continuous ? Steady(pose, arm, shoulder, filter, in target, frameRotation, shrug, result, deltaSeconds) : result;
        }

        // An arm held straight (StraightArmCutoffHz): its shoulder-to-goal distance through the limb's filter, and the
        // clavicle turned, for this frame only, by the least angle (at most MaxSteadyingDegrees) that puts the shoulder that
        // filtered distance from the goal, weighed by how much of the shoulder's arc changes that distance (SteadyingTurn);
        // then the arm is solved again, exactly. Runs every frame of the continuous solve, so that the filter has the history.
        private LimbResult Steady(SkeletonPose pose, LimbChain arm, Shoulder shoulder, LimbReachFilter filter, in LimbTarget target,
            Quaternion frameRotation, Quaternion clavicleInFrame, LimbResult result, float deltaSeconds)
        {
            if (!(_straightArmCutoffHz > 0f) || !Vectors.IsFinite(target.Goal.Position)) return result;
            RigidPose[] w = pose.World;
            Vector3 root = w[arm.Root].Position, goal = target.Goal.Position;
            float distance = Vector3.Distance(root, goal);
            float wanted = filter.Filter(distance, deltaSeconds, _straightArmCutoffHz);
            if (!result.Reached || wanted == distance) return result;
            float theta = SteadyingTurn(w[shoulder.Clavicle].Position, root, goal, wanted, out Vector3 axis);
            if (theta == 0f) return result;
            Quaternion turn = Quaternion.CreateFromAxisAngle(axis, theta);
            Quaternion steadied = Quaternion.Normalize(Quaternion.Conjugate(frameRotation) * turn * frameRotation * clavicleInFrame);
            if (!Rotations.IsFinite(steadied)) return result;
            // Within the shoulder's range, as the shrug is: a clavicle at its limit is not turned past it.
            float angle = Rotations.AngleDegrees(Quaternion.Identity, steadied);
            if (angle > MaxClavicleDegrees && angle > Rotations.AngleDegrees(Quaternion.Identity, clavicleInFrame))
                steadied = Quaternion.Normalize(Quaternion.Slerp(Quaternion.Identity, steadied, MaxClavicleDegrees / angle));
            shoulder.Set(pose, frameRotation, Quaternion.Normalize(steadied * shoulder.Reference));
            return TwoBoneIk.Solve(pose, arm, target.Goal, target.Hint);
        }

        // The clavicle's turn about `axis` (positive: the shoulder toward the goal) that puts the shoulder `wanted` from the
        // goal, by the law of cosines in the plane of pivot, shoulder and goal, at most MaxSteadyingDegrees either way, and
        // weighed by the share of the shoulder's move along its arc that changes its distance from the goal: none below
        // SteadyingNoEfficiency (an arm along the clavicle: the shoulder would move sideways by far more than the distance
        // changes), all from SteadyingFullEfficiency (the shoulder moves at most twice what the distance changes), smoothly.
        private static float SteadyingTurn(Vector3 pivot, Vector3 shoulder, Vector3 goal, float wanted, out Vector3 axis)
        {
            Vector3 toShoulder = shoulder - pivot, toGoal = goal - pivot, fromGoal = shoulder - goal;
            float c = toShoulder.Length(), d = toGoal.Length(), distance = fromGoal.Length();
            axis = Vector3.Cross(toShoulder, toGoal);
            if (!(c > 1e-6f) || !(d > 1e-6f) || !(distance > 1e-6f) || !(axis.LengthSquared() > 1e-14f)) return 0f;
            axis = Vector3.Normalize(axis);
            Vector3 along = Vector3.Normalize(Vector3.Cross(axis, toShoulder)); // the shoulder's way on its arc
            float efficiency = Math.Abs(Vector3.Dot(along, fromGoal / distance));
            float weight = Math.Clamp((efficiency - SteadyingNoEfficiency) / (SteadyingFullEfficiency - SteadyingNoEfficiency), 0f, 1f);
            if (weight == 0f) return 0f;
            weight = weight * weight * (3f - 2f * weight);
            float alpha = MathF.Acos(Math.Clamp(Vector3.Dot(toShoulder, toGoal) / (c * d), -1f, 1f));
            float beta = MathF.Acos(Math.Clamp((c * c + d * d - wanted * wanted) / (2f * c * d), -1f, 1f));
            const float max = MaxSteadyingDegrees * MathF.PI / 180f;
            return weight * Math.Clamp(alpha - beta, -max, max);
        }

        // The joint `self` (unless -1), each of the others (-1: none) and every joint above them, each once, parents first.
        private static int[] AncestorsOrSelf(Skeleton s, int self, params int[] below)
        {
            var joints = new SortedSet<int>();
            if (self >= 0) joints.Add(self);
            foreach (int joint in below)
                for (int j = joint; j >= 0; j = s.GetParent(j)) joints.Add(j);
            var list = new int[joints.Count];
            joints.CopyTo(list);
            return list;
        }

        private static int ArmStart(Shoulder shoulder, LimbChain arm) => shoulder.Clavicle >= 0 ? shoulder.Clavicle : arm.Root;

        // One side's shoulder: the clavicle (-1: the rig has none), the joint whose frame its rotation and shrug are kept in
        // (its parent; the joint below the neck when it hangs from a neck that follows the head, as 3ds Max Biped's do, so
        // that a nod does not swing the shoulders), its calibration rotation in that frame, the joints between it and the
        // upper arm that are no humanoid bone (MakeHuman's shoulder01), and the shrug held from earlier frames (in the frame
        // joint's frame).
        private sealed class Shoulder
        {
            public readonly int Clavicle = -1;
            private readonly int _parent = -1, _frameJoint = -1;
            public readonly Quaternion Reference = Quaternion.Identity;
            private readonly int[] _toUpperArm = Array.Empty<int>();
            public Quaternion Held = Quaternion.Identity;

            public Shoulder(Skeleton s, int clavicle, int upperArm, int neck, RigidPose[] refLocal, RigidPose[] refWorld)
            {
                if (clavicle < 0 || !s.IsAncestorOrSelf(clavicle, upperArm) || clavicle == upperArm) return;
                Clavicle = clavicle;
                _parent = s.GetParent(clavicle);
                _frameJoint = neck >= 0 && _parent == neck ? s.GetParent(neck) : _parent;
                Reference = _frameJoint == _parent
                    ? refLocal[clavicle].Rotation
                    : Quaternion.Normalize(Quaternion.Conjugate(_frameJoint < 0 ? Quaternion.Identity : refWorld[_frameJoint].Rotation) * refWorld[clavicle].Rotation);
                var between = new List<int>();
                for (int j = s.GetParent(upperArm); j != clavicle; j = s.GetParent(j)) between.Insert(0, j);
                _toUpperArm = between.ToArray();
            }

            // The joints Set poses (none without a clavicle).
            public void AddPosedJoints(HashSet<int> joints)
            {
                if (Clavicle < 0) return;
                joints.Add(Clavicle);
                joints.UnionWith(_toUpperArm);
            }

            public Quaternion FrameRotation(SkeletonPose pose) => _frameJoint < 0 ? pose.Origin.Rotation : pose.World[_frameJoint].Rotation;

            // Turns the clavicle to `rotation` in its frame joint's frame and updates the world poses down to the upper arm's
            // parent (the arm's solve starts from it).
            public void Set(SkeletonPose pose, Quaternion frameRotation, Quaternion rotation)
            {
                RigidPose parentWorld = _parent < 0 ? pose.Origin : pose.World[_parent];
                Quaternion local = _frameJoint == _parent ? rotation : Quaternion.Normalize(Quaternion.Conjugate(parentWorld.Rotation) * frameRotation * rotation);
                pose.Local[Clavicle] = pose.Local[Clavicle].WithRotation(local);
                pose.World[Clavicle] = parentWorld * pose.Local[Clavicle];
                pose.UpdateWorld(_toUpperArm);
            }

            // A lost hand's arm keeps its pose; a clavicle kept in another joint's frame than its parent's keeps its place in
            // that frame too (with the shrug held, as it is released), or the neck's following the head would swing it.
            public void KeepStill(SkeletonPose pose, bool hold)
            {
                if (Clavicle < 0 || _frameJoint == _parent) return;
                Set(pose, FrameRotation(pose), Quaternion.Normalize((hold ? Held : Quaternion.Identity) * Reference));
            }
        }

        // The least turn of the clavicle about its pivot that brings the goal within reach of the stretched arm: the shoulder
        // moves on the sphere about the pivot, in the plane of pivot, shoulder and goal, until its distance from the goal is
        // the arm's reach (the law of cosines); toward the goal as far as it goes when no turn is enough. beyondDegrees is then
        // how far the goal lies beyond the farthest reach (clavicle plus arm, along the line from the pivot), as the angle
        // that much of the shoulder's arc would be (0 when a turn is enough): what the hold weighs on top of the turn, so
        // that a goal out of any reach within the shrug's range is not held whole, and the hold stays continuous across
        // the farthest reach.
        private static Quaternion ShrugToward(Vector3 pivot, Vector3 shoulder, Vector3 hand, Vector3 goal, out float beyondDegrees)
        {
            beyondDegrees = 0f;
            float reach = Vector3.Distance(shoulder, hand) * (1f - 1e-4f);
            Vector3 toShoulder = shoulder - pivot, toGoal = goal - pivot;
            float c = toShoulder.Length(), d = toGoal.Length();
            Vector3 axis = Vector3.Cross(toShoulder, toGoal);
            if (!(c > 1e-6f) || !(d > 1e-6f) || !(axis.LengthSquared() > 1e-14f)) return Quaternion.Identity;
            if (d > c + reach) beyondDegrees = (d - c - reach) / c * (180f / MathF.PI);
            float alpha = MathF.Acos(Math.Clamp(Vector3.Dot(toShoulder, toGoal) / (c * d), -1f, 1f));
            float cosNeeded = (c * c + d * d - reach * reach) / (2f * c * d);
            float theta = alpha - MathF.Acos(Math.Clamp(cosNeeded, -1f, 1f));
            return theta > 0f ? Quaternion.CreateFromAxisAngle(Vector3.Normalize(axis), theta) : Quaternion.Identity;
        }
    }
}
