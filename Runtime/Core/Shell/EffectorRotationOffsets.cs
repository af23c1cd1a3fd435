using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Converts the world rotation a wrist or ankle bone should take into the rotation of Unity's humanoid IK goal for it.
    /// A humanoid goal is expressed in the avatar's normalised effector frame, not in the bone's own axes: the two differ
    /// by a rotation that is constant for a given avatar and limb (the humanoid's pre/post rotations). It is measured from
    /// what happened: a goal rotation set with full weight in one IK pass and the bone's world rotation the Animator
    /// produced from it (read in the next pass) give the effector in the bone's frame. Three consistent measurements (within
    /// <see cref="ConsistencyDegrees"/>) make it known; their average is used from then on. Engine-free and allocation-free.
    /// </summary>
    public sealed class EffectorRotationOffsets
    {
        /// <summary>How many consistent measurements make an offset known.</summary>
        public const int SamplesNeeded = 3;

        /// <summary>How far apart (°) the measurements may be and still count as consistent.</summary>
        public const float ConsistencyDegrees = 0.5f;

        private readonly Quaternion[] _offset = new Quaternion[4];
        private readonly Quaternion[] _first = new Quaternion[4];
        private readonly Vector4[] _sum = new Vector4[4];
        private readonly int[] _count = new int[4];
        private readonly bool[] _known = new bool[4];

        /// <summary>Creates offsets that are all unknown.</summary>
        public EffectorRotationOffsets() => Reset();

        /// <summary>True once <paramref name="goal"/>'s offset is known.</summary>
        public bool IsKnown(IkGoal goal) => _known[Index(goal)];

        /// <summary>The goal's effector frame in its bone's frame (identity until known).</summary>
        public Quaternion EffectorInBone(IkGoal goal) => _offset[Index(goal)];

        /// <summary>
        /// Records one frame: the goal rotation that was set with full weight and the bone's world rotation the Animator
        /// produced. A measurement that disagrees with the first by more than <see cref="ConsistencyDegrees"/> starts the
        /// count again from it. Non-finite rotations are ignored. Returns true when the offset is known after it.
        /// </summary>
        public bool Observe(IkGoal goal, Quaternion goalSet, Quaternion boneResult) => Observe(goal, goalSet, 1f, boneResult);

        /// <summary>
        /// As <see cref="Observe(IkGoal, Quaternion, Quaternion)"/>, for a goal rotation set with <paramref name="rotationWeight"/>:
        /// a frame set with less than full weight is ignored (the bone's rotation is then a blend with where the limb's own
        /// pose carried it, not the goal's effector frame; found in review: a driver at half weight measured that blend).
        /// </summary>
        public bool Observe(IkGoal goal, Quaternion goalSet, float rotationWeight, Quaternion boneResult)
        {
            if (!(rotationWeight >= 1f)) return IsKnown(goal);
            int g = Index(goal);
            if (_known[g]) return true;
            if (!Rotations.IsUnit(goalSet) || !Rotations.IsUnit(boneResult)) return false;
            Quaternion sample = Rotations.Canonical(Quaternion.Normalize(Quaternion.Conjugate(Quaternion.Normalize(boneResult)) * Quaternion.Normalize(goalSet)));
            if (_count[g] == 0 || Rotations.AngleDegrees(_first[g], sample) > ConsistencyDegrees)
            {
                _first[g] = sample;
                _sum[g] = Vector4.Zero;
                _count[g] = 0;
            }
            if (Quaternion.Dot(_first[g], sample) < 0f) sample = new Quaternion(-sample.X, -sample.Y, -sample.Z, -sample.W);
            _sum[g] += new Vector4(sample.X, sample.Y, sample.Z, sample.W);
            _count[g]++;
            if (_count[g] < SamplesNeeded) return false;
            Vector4 s = Vector4.Normalize(_sum[g]);
            _offset[g] = new Quaternion(s.X, s.Y, s.Z, s.W);
            _known[g] = true;
            return true;
        }

        /// <summary>The goal rotation that puts the bone at <paramref name="boneRotation"/> (the bone's rotation itself until known).</summary>
        public Quaternion EffectorFor(IkGoal goal, Quaternion boneRotation) => Quaternion.Normalize(boneRotation * _offset[Index(goal)]);

        /// <summary>Forgets every offset (a new avatar).</summary>
        public void Reset()
        {
            for (int g = 0; g < 4; g++)
            {
                _offset[g] = Quaternion.Identity;
                _first[g] = Quaternion.Identity;
                _sum[g] = Vector4.Zero;
                _count[g] = 0;
                _known[g] = false;
            }
        }

        private static int Index(IkGoal goal) =>
            (uint)goal <= 3u ? (int)goal : throw new ArgumentOutOfRangeException(nameof(goal), goal, "Not an IK goal.");
    }
}
