using System;
using System.Collections.Generic;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// Turns mocap into a complete synthetic session: the wearer stands in T-pose and presses the trigger, the
    /// avatar appears where a <see cref="Calibrator"/> places it, the wearer walks into it (with an optional
    /// misalignment) and presses again, then blends smoothly from the T-pose into the clip and performs it.
    /// Devices come from a <see cref="VirtualDeviceRig"/> with noise; the ground truth (true roles, the wearer's
    /// skeleton, every humanoid joint's world pose) is recorded. Frames are streamed to a <see cref="SessionWriter"/>.
    /// </summary>
    public sealed class SessionSimulator
    {
        /// <summary>The true role of each simulated device, in device order (ids 0 … 5).</summary>
        public static readonly DeviceRole[] DeviceRoles =
            { DeviceRole.Head, DeviceRole.RightHand, DeviceRole.LeftHand, DeviceRole.LeftFoot, DeviceRole.Pelvis, DeviceRole.RightFoot };

        private readonly BvhClip _clip;
        private readonly HumanoidMap _map;
        private readonly SimulationOptions _options;

        /// <summary>
        /// Prepares a simulation of <paramref name="clip"/> (lengths in metres) worn by its own skeleton, its humanoid bones
        /// <paramref name="map"/> or, when null, found by <see cref="HumanoidDetection"/> (the names, else the structure).
        /// </summary>
        /// <exception cref="ArgumentException">The clip has no frames or is too long to simulate, or its skeleton lacks a required humanoid bone.</exception>
        /// <exception cref="ArgumentOutOfRangeException">A rate or a phase's length that cannot make a session that calibrates (see <see cref="MinWalkInSeconds"/>).</exception>
        public SessionSimulator(BvhClip clip, SimulationOptions options = null, HumanoidMap map = null)
        {
            _clip = clip ?? throw new ArgumentNullException(nameof(clip));
            if (clip.FrameCount == 0) throw new ArgumentException("The clip has no frames (Frames: 0): there is no motion to simulate.", nameof(clip));
            _options = options ?? new SimulationOptions();
            CheckTimings(_options);
            double frames = (_options.TPoseSeconds + _options.WalkInSeconds + _options.ExerciseSeconds + _options.BlendSeconds + clip.FrameCount * (double)clip.FrameTime) * _options.Rate;
            if (!(frames < int.MaxValue)) throw new ArgumentException($"The clip is too long to simulate at {_options.Rate} Hz ({(long)Math.Min(frames, long.MaxValue)} frames).", nameof(clip));
            string note = null;
            _map = map ?? HumanoidDetection.Detect(clip, null, out note);
            if (!_map.IsComplete && note != null)
                throw new ArgumentException($"The rig lacks required humanoid bones: {string.Join(", ", _map.MissingRequired())}; {note}.", nameof(clip));
            _map.RequireComplete(nameof(clip));
            if (_options.MirrorBackwardClip && ClipConventions.LooksMirrored(clip, _map, out _, out _))
            {
                // The same joints play the same bones on the mirrored skeleton.
                Mirrored = true;
                _clip = clip = clip.Mirrored();
                _map = new HumanoidMap(clip.Skeleton, _map.Pairs());
            }
            Upright = _options.StandClipUp ? ClipConventions.UprightTurn(clip, _map) : Quaternion.Identity;
        }

        /// <summary>The shortest walk-in that calibrates (s): its last 40 %, standing still, must hold most of the averaging window.</summary>
        public const float MinWalkInSeconds = 1f;

        // Options that cannot make a session that calibrates are refused (found in review: a walk-in of 0 s threw a
        // NullReferenceException, and T-poses or walk-ins shorter than the calibrator's averaging window wrote sessions that
        // never calibrate; a NaN rate blamed the clip's length).
        private static void CheckTimings(SimulationOptions o)
        {
            if (!(o.Rate >= SessionLimits.MinRate && o.Rate <= SessionLimits.MaxRate))
                throw new ArgumentOutOfRangeException(nameof(SimulationOptions.Rate), o.Rate, $"The rate must be from {SessionLimits.MinRate} to {SessionLimits.MaxRate} Hz.");
            float window = new CalibrationSettings().WindowSeconds + 1f / o.Rate;
            if (!(o.TPoseSeconds >= window) || float.IsInfinity(o.TPoseSeconds))
                throw new ArgumentOutOfRangeException(nameof(SimulationOptions.TPoseSeconds), o.TPoseSeconds, $"The T-pose must last at least the calibration's averaging window and a frame ({window:0.###} s).");
            if (!(o.WalkInSeconds >= MinWalkInSeconds) || float.IsInfinity(o.WalkInSeconds))
                throw new ArgumentOutOfRangeException(nameof(SimulationOptions.WalkInSeconds), o.WalkInSeconds, $"The walk-in must last at least {MinWalkInSeconds} s (its last 40 % standing still for the calibration's window).");
            if (!(o.ExerciseSeconds >= 0f) || float.IsInfinity(o.ExerciseSeconds))
                throw new ArgumentOutOfRangeException(nameof(SimulationOptions.ExerciseSeconds), o.ExerciseSeconds, "The exercise lasts 0 or more (finite) seconds.");
            if (!(o.BlendSeconds >= 0f) || float.IsInfinity(o.BlendSeconds))
                throw new ArgumentOutOfRangeException(nameof(SimulationOptions.BlendSeconds), o.BlendSeconds, "The blend lasts 0 or more (finite) seconds.");
        }

        /// <summary>
        /// The wearer as simulated: the clip's skeleton (mirrored when <see cref="Mirrored"/>) and its humanoid bones. Solved
        /// poses and the session's ground truth are of this skeleton, not the one passed in when the clip was mirrored.
        /// </summary>
        public HumanoidMap Wearer => _map;

        /// <summary>
        /// Whether the clip was mirrored left to right (<see cref="BvhClip.Mirrored"/>) before anything else: its knees bent
        /// backward (<see cref="ClipConventions.LooksMirrored"/>). That is a clip written in a left-handed frame or with its
        /// sides named the wrong way round (its joints named Left on the body's right): worn as it is, its wearer's knees
        /// would bend backward. <see cref="SimulationOptions.MirrorBackwardClip"/> false keeps every clip as it is.
        /// </summary>
        public bool Mirrored { get; }

        /// <summary>
        /// The turn that stands the clip's motion up (applied to its roots before anything else): the identity for a clip
        /// whose up is +Y, as BVH defines it; for a clip recorded with another axis up (Z-up exports), the quarter or half
        /// turn that takes that axis to +Y. The up is the mean of the unit vectors from the feet to the head over the clip:
        /// +Y is kept whenever that mean leans toward it (Y at least 0.5) or the frames disagree (the mean shorter than
        /// 0.8: a clip that lies down or stands on its hands a good part of the time), and another axis is taken only when
        /// the mean lies within 25° of it. <see cref="SimulationOptions.StandClipUp"/> false keeps every clip as it is.
        /// </summary>
        public Quaternion Upright { get; }

        private void StandUp(RigidPose[] local)
        {
            if (Upright == Quaternion.Identity) return;
            Skeleton s = _map.Skeleton;
            for (int j = 0; j < local.Length; j++)
                if (s.GetParent(j) < 0) local[j] = new RigidPose(Vector3.Transform(local[j].Position, Upright), Quaternion.Normalize(Upright * local[j].Rotation));
        }

        /// <summary>The devices of the simulated session.</summary>
        public static DeviceInfo[] Devices()
        {
            var devices = new DeviceInfo[DeviceRoles.Length];
            for (int i = 0; i < devices.Length; i++)
            {
                DeviceClass c = DeviceRoles[i] == DeviceRole.Head ? DeviceClass.Hmd
                    : DeviceRoles[i] == DeviceRole.LeftHand || DeviceRoles[i] == DeviceRole.RightHand ? DeviceClass.Controller : DeviceClass.Tracker;
                devices[i] = new DeviceInfo(i, c, "SIM-" + c.ToString().ToUpperInvariant() + "-" + i);
            }
            return devices;
        }

        /// <summary>The session header (devices, true roles, the wearer's skeleton).</summary>
        public SessionHeader CreateHeader() => new SessionHeader(_options.Rate, Devices(), DeviceRoles, _map);

        /// <summary>The number of frames <see cref="Run"/> writes.</summary>
        public int FrameCount => (int)Math.Round((_options.TPoseSeconds + _options.WalkInSeconds + _options.ExerciseSeconds + _options.BlendSeconds + _clip.FrameCount * _clip.FrameTime) * _options.Rate);

        /// <summary>Writes the whole session. <paramref name="progress"/> (optional) gets the fraction done.</summary>
        public void Run(SessionWriter writer, Action<float> progress = null)
        {
            if (writer == null) throw new ArgumentNullException(nameof(writer));
            Skeleton s = _map.Skeleton;
            var rng = new Random(_options.Seed);
            DeviceMountings mountings = _options.Mountings ?? DeviceMountings.Sample(rng);
            // The wearer's T-pose takes the twists no landmark fixes (about single-child bones) from the clip's first frame:
            // the way its feet and hands are turned is the wearer's own, and the T-pose and the motion share them whatever
            // local axes the clip's skeleton uses (a rest-pose twist would differ between rest conventions).
            var twistReference = new RigidPose[s.JointCount];
            if (_clip.FrameCount > 0) _clip.GetLocalPoses(0, twistReference); else s.GetRestLocal(twistReference);
            StandUp(twistReference);
            var rig = new VirtualDeviceRig(_map, mountings, _options.Controller, twistReference);
            DeviceInfo[] devices = Devices();
            var calibrator = new Calibrator(devices, _map);
            var frame = new SessionFrame(writer.Header);
            var pose = new SkeletonPose(s);
            var devicePoses = new RigidPose[6];
            float dt = 1f / _options.Rate;

            // Where the wearer starts: somewhere in a 2 m × 2 m area, facing anywhere.
            var start = new RigidPose(new Vector3((float)rng.NextDouble() * 2 - 1, 0, (float)rng.NextDouble() * 2 - 1),
                Rotations.AngleAxis((float)rng.NextDouble() * 360f, Vector3.UnitY));
            var tposeStart = new RigidPose[s.JointCount];
            TPoser.Apply(_map, pose, start, twistReference);
            Array.Copy(pose.Local, tposeStart, s.JointCount);

            // The clip's local poses, moved so that its first frame stands where the walk-in ends; filled after step 1.
            var clipLocal = new RigidPose[_clip.FrameCount][];
            for (int f = 0; f < clipLocal.Length; f++)
            {
                clipLocal[f] = new RigidPose[s.JointCount];
                _clip.GetLocalPoses(f, clipLocal[f]);
                StandUp(clipLocal[f]);
            }

            int total = FrameCount;
            int tposeFrames = (int)Math.Round(_options.TPoseSeconds * _options.Rate);
            int walkFrames = (int)Math.Round(_options.WalkInSeconds * _options.Rate);
            int exerciseFrames = (int)Math.Round(_options.ExerciseSeconds * _options.Rate);
            int blendFrames = Math.Max(1, (int)Math.Round(_options.BlendSeconds * _options.Rate));
            RigidPose[] tposeTarget = null;
            RigidPose target = start;
            var none = new List<DeviceEvent>();

            for (int i = 0; i < total; i++)
            {
                double time = i * (double)dt;
                frame.Clear();
                frame.Time = time;
                if (i < tposeFrames)
                {
                    Array.Copy(tposeStart, pose.Local, s.JointCount);
                    if (i == tposeFrames - 1) frame.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerPressed));
                }
                else if (i < tposeFrames + walkFrames)
                {
                    if (tposeTarget == null)
                    {
                        // The avatar appeared where the calibrator placed it: walk there (plus the misalignment).
                        RigidPose placement = calibrator.State == CalibrationState.WalkIn ? calibrator.Profile.Placement : start;
                        target = placement * new RigidPose(_options.Misalignment, Rotations.AngleAxis(_options.MisalignmentYawDegrees, Vector3.UnitY));
                        target = new RigidPose(new Vector3(target.Position.X, 0f, target.Position.Z), target.Rotation);
                        TPoser.Apply(_map, pose, target, twistReference);
                        tposeTarget = (RigidPose[])pose.Local.Clone();
                        AlignClip(clipLocal, target);
                    }
                    int k = i - tposeFrames;
                    float walk = Smooth(Math.Min(1f, k / (0.6f * walkFrames)));
                    Blend(tposeStart, tposeTarget, walk, pose.Local);
                    if (i == tposeFrames + walkFrames - 1) frame.Events.Add(new DeviceEvent(2, DeviceEventKind.TriggerPressed));
                    if (i == tposeFrames) frame.Events.Add(new DeviceEvent(1, DeviceEventKind.TriggerReleased));
                }
                else if (i < tposeFrames + walkFrames + exerciseFrames)
                {
                    RefinementExercise.Pose(_map, tposeTarget, (i - tposeFrames - walkFrames) / (float)Math.Max(1, exerciseFrames - 1), pose);
                    if (i == tposeFrames + walkFrames) frame.Events.Add(new DeviceEvent(2, DeviceEventKind.TriggerReleased));
                }
                else if (i < tposeFrames + walkFrames + exerciseFrames + blendFrames)
                {
                    float b = Smooth((i - tposeFrames - walkFrames - exerciseFrames) / (float)blendFrames);
                    Blend(tposeTarget, clipLocal[0], b, pose.Local);
                    if (exerciseFrames == 0 && i == tposeFrames + walkFrames) frame.Events.Add(new DeviceEvent(2, DeviceEventKind.TriggerReleased));
                }
                else
                {
                    double clipTime = (i - tposeFrames - walkFrames - exerciseFrames - blendFrames) * (double)dt;
                    double f = Math.Min(clipTime / _clip.FrameTime, _clip.FrameCount - 1);
                    int f0 = (int)Math.Floor(f);
                    int f1 = Math.Min(f0 + 1, _clip.FrameCount - 1);
                    Blend(clipLocal[f0], clipLocal[f1], (float)(f - f0), pose.Local);
                }
                pose.UpdateWorld();

                rig.Compute(pose.World, devicePoses);
                VirtualDeviceRig.AddNoise(devicePoses, rng, _options.PositionNoise, _options.RotationNoiseDegrees);
                for (int d = 0; d < devices.Length; d++)
                    frame.Samples[d] = new DeviceSample(devicePoses[BodyRoles.IndexOf(DeviceRoles[d])], true);
                for (int b = 0; b < HumanoidBones.Count; b++)
                {
                    int joint = _map[(HumanoidBone)b];
                    if (joint < 0) continue;
                    frame.Truth[b] = pose.World[joint];
                    frame.HasTruth[b] = true;
                }
                calibrator.Update(time, frame.Samples, frame.Events);
                writer.WriteFrame(frame);
                if (progress != null && (i % 256 == 0 || i == total - 1)) progress((i + 1) / (float)total);
            }
        }

        // Moves every clip frame so the first one stands where the T-pose stands (same facing), the clip's lowest leg joint
        // over all frames on the floor (y = 0). For a rig without toes the T-pose stands its ankles at their anatomical
        // height instead, so such a clip's feet may sit a couple of centimetres higher than the T-pose's (MocapBank 21 mm,
        // measured in review): the truth stays consistent, the blend from the T-pose lifts them.
        private void AlignClip(RigidPose[][] clipLocal, RigidPose target)
        {
            Skeleton s = _map.Skeleton;
            var world = new RigidPose[s.JointCount];
            int hips = _map[HumanoidBone.Hips];
            int leftLeg = _map[HumanoidBone.LeftUpperLeg], rightLeg = _map[HumanoidBone.RightUpperLeg];
            float floor = float.MaxValue;
            for (int f = 0; f < clipLocal.Length; f++)
            {
                s.ComputeWorld(clipLocal[f], world);
                for (int j = 0; j < s.JointCount; j++)
                    if (s.IsAncestorOrSelf(leftLeg, j) || s.IsAncestorOrSelf(rightLeg, j)) floor = Math.Min(floor, world[j].Position.Y);
            }
            s.ComputeWorld(clipLocal[0], world);
            Vector3 right = world[rightLeg].Position - world[leftLeg].Position;
            Vector3 facing = Vector3.Cross(right, Vector3.UnitY);
            facing.Y = 0;
            Quaternion clipYaw = Rotations.LookRotation(Vectors.NormalizeOr(facing, Vector3.UnitZ), Vector3.UnitY);
            Vector3 hips0 = world[hips].Position;
            Quaternion turn = target.Rotation * Quaternion.Conjugate(clipYaw);
            Vector3 pivot = new Vector3(hips0.X, floor, hips0.Z);
            for (int f = 0; f < clipLocal.Length; f++)
                for (int j = 0; j < s.JointCount; j++)
                {
                    if (s.GetParent(j) >= 0) continue;
                    RigidPose p = clipLocal[f][j];
                    clipLocal[f][j] = new RigidPose(target.Position + Vector3.Transform(p.Position - pivot, turn), Quaternion.Normalize(turn * p.Rotation));
                }
        }

        private static void Blend(RigidPose[] a, RigidPose[] b, float t, RigidPose[] result)
        {
            for (int j = 0; j < result.Length; j++) result[j] = RigidPose.Lerp(a[j], b[j], t);
        }

        private static float Smooth(float t) => t * t * (3f - 2f * t);
    }
}
