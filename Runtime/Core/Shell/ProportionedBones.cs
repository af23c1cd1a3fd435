using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// What a Unity shell writes to a bound avatar's bone transforms so that the avatar has the calibration's fitted
    /// proportions (<see cref="BodyProportions"/>): the knees, ankles, elbows and wrists and the joints between them and the
    /// joint above, such as twist joints along a limb (the only joints whose factor is not the overall scale, which the
    /// root's <c>localScale</c> carries) each get its bind local position times its
    /// factor (<see cref="BodyProportions.LocalPositionFactors(HumanoidMap, float, Span{float})"/> with overall scale 1),
    /// and their bind positions back when the proportions become uniform, the calibration is reset, or the shell is
    /// disabled. The shell only copies <see cref="LocalPosition"/> of each <see cref="Joint"/> to its transform.
    /// Allocation-free after construction.
    /// </summary>
    public sealed class ProportionedBones
    {
        private readonly HumanoidMap _map;
        private readonly int[] _joints;
        private readonly Vector3[] _bind, _positions;
        private readonly float[] _factors;

        /// <summary>
        /// For the joints of <paramref name="map"/> (a bound hierarchy's map) whose bind local positions, in the engine's
        /// local units, are <paramref name="bindLocalPositions"/> (one per joint).
        /// </summary>
        /// <exception cref="ArgumentException">The positions are not one per joint, or one of the managed joints' is not finite.</exception>
        public ProportionedBones(HumanoidMap map, ReadOnlySpan<Vector3> bindLocalPositions)
        {
            _map = map ?? throw new ArgumentNullException(nameof(map));
            int n = map.Skeleton.JointCount;
            if (bindLocalPositions.Length != n) throw new ArgumentException($"Expected {n} bind positions, got {bindLocalPositions.Length}.", nameof(bindLocalPositions));
            _factors = new float[n];
            // The joints whose factor is not the overall scale's under some proportions: found with every ratio 2.
            new BodyProportions(2f, 2f, 2f, 2f).LocalPositionFactors(map, 1f, _factors);
            var managed = new int[n];
            int count = 0;
            for (int j = 1; j < n; j++) // not the root, whose scale is the overall scale's
            {
                if (_factors[j] == 1f) continue;
                if (!Vectors.IsFinite(bindLocalPositions[j])) throw new ArgumentException($"The bind position of {map.Skeleton.GetName(j)} is not finite.", nameof(bindLocalPositions));
                managed[count++] = j;
            }
            _joints = new int[count];
            _bind = new Vector3[count];
            _positions = new Vector3[count];
            for (int i = 0; i < count; i++)
            {
                _joints[i] = managed[i];
                _bind[i] = _positions[i] = bindLocalPositions[managed[i]];
            }
            Applied = BodyProportions.Uniform;
        }

        /// <summary>The proportions the positions are for (uniform: the bind positions).</summary>
        public BodyProportions Applied { get; private set; }

        /// <summary>How many transforms this manages: both knees, ankles, elbows and wrists that the rig has, and the joints between them and the joint above (twist joints along the limbs).</summary>
        public int Count => _joints.Length;

        /// <summary>The joint (of the map, so of the binding) of the <paramref name="index"/>-th managed transform.</summary>
        public int Joint(int index) => _joints[index];

        /// <summary>The local position (engine units) the <paramref name="index"/>-th managed transform gets.</summary>
        public Vector3 LocalPosition(int index) => _positions[index];

        /// <summary>Its bind local position.</summary>
        public Vector3 BindLocalPosition(int index) => _bind[index];

        /// <summary>
        /// The proportions the bones should show: those of <paramref name="profile"/> (the calibration the pipeline poses the
        /// avatar with, from the walk-in on; it says uniform for a uniform calibration) while <paramref name="active"/>;
        /// uniform, so the bind pose, without a profile, with invalid proportions, or when not active (the shell disabled).
        /// </summary>
        public static BodyProportions Wanted(CalibrationProfile profile, bool active) =>
            active && profile != null && profile.Proportions.IsValid ? profile.Proportions : BodyProportions.Uniform;

        /// <summary>
        /// Moves to the proportions <see cref="Wanted"/> gives; true when they differ from <see cref="Applied"/>, so the
        /// positions changed and must be copied. Allocation-free.
        /// </summary>
        public bool Update(CalibrationProfile profile, bool active) => Set(Wanted(profile, active));

        /// <summary>Back to the bind positions; true when they were not (copy them). Allocation-free.</summary>
        public bool Restore() => Set(BodyProportions.Uniform);

        private bool Set(BodyProportions p)
        {
            if (p.Equals(Applied)) return false;
            p.LocalPositionFactors(_map, 1f, _factors);
            for (int i = 0; i < _joints.Length; i++) _positions[i] = _bind[i] * _factors[_joints[i]];
            Applied = p;
            return true;
        }
    }
}
