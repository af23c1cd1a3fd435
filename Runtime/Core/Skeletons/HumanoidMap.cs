using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Which joint of a <see cref="Skeleton"/> plays each <see cref="HumanoidBone"/>. Built by
    /// <c>HumanoidNaming</c> from joint names, or by hand; immutable once built.
    /// </summary>
    public sealed class HumanoidMap
    {
        private readonly int[] _jointByBone;

        /// <summary>The skeleton this map refers to.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Creates a map from bone → joint-name pairs; names must exist in <paramref name="skeleton"/>.</summary>
        /// <exception cref="ArgumentException">A name is not a joint of the skeleton, or one joint is given two bones.</exception>
        public HumanoidMap(Skeleton skeleton, IEnumerable<KeyValuePair<HumanoidBone, string>> bones)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            _jointByBone = new int[HumanoidBones.Count];
            for (int i = 0; i < _jointByBone.Length; i++) _jointByBone[i] = -1;
            var boneByJoint = new Dictionary<int, HumanoidBone>();
            foreach (var pair in bones ?? throw new ArgumentNullException(nameof(bones)))
            {
                if (!HumanoidBones.IsValid(pair.Key)) throw new ArgumentException($"'{pair.Key}' is not a humanoid bone.", nameof(bones));
                int joint = skeleton.IndexOf(pair.Value);
                if (joint < 0) throw new ArgumentException($"The skeleton has no joint named '{pair.Value}' (for {pair.Key}).", nameof(bones));
                if (boneByJoint.TryGetValue(joint, out HumanoidBone other) && other != pair.Key)
                    throw new ArgumentException($"Joint '{pair.Value}' is mapped to both {other} and {pair.Key}.", nameof(bones));
                boneByJoint[joint] = pair.Key;
                _jointByBone[(int)pair.Key] = joint;
            }
        }

        /// <summary>The joint index of <paramref name="bone"/>, or -1 when the rig does not have it.</summary>
        public int this[HumanoidBone bone] => HumanoidBones.IsValid(bone) ? _jointByBone[(int)bone] : -1;

        /// <summary>True when the rig has <paramref name="bone"/>.</summary>
        public bool Has(HumanoidBone bone) => this[bone] >= 0;

        /// <summary>The joint name of <paramref name="bone"/>, or null.</summary>
        public string NameOf(HumanoidBone bone)
        {
            int joint = this[bone];
            return joint >= 0 ? Skeleton.GetName(joint) : null;
        }

        /// <summary>The humanoid bone played by <paramref name="joint"/>, or <see cref="HumanoidBone.LastBone"/> for none.</summary>
        public HumanoidBone BoneOf(int joint)
        {
            for (int b = 0; b < _jointByBone.Length; b++)
                if (_jointByBone[b] == joint) return (HumanoidBone)b;
            return HumanoidBone.LastBone;
        }

        /// <summary>The required bones (<see cref="HumanoidBones.Required"/>) the rig lacks; empty for a complete humanoid.</summary>
        public IReadOnlyList<HumanoidBone> MissingRequired()
        {
            var missing = new List<HumanoidBone>();
            foreach (HumanoidBone bone in HumanoidBones.Required)
                if (!Has(bone)) missing.Add(bone);
            return missing;
        }

        /// <summary>
        /// Throws unless every required bone is mapped: the one guard of the types that need a complete humanoid
        /// (calibration, the T-pose, the body IK, the simulator).
        /// </summary>
        /// <param name="parameterName">The caller's parameter that holds this map, for the exception.</param>
        /// <exception cref="ArgumentException">A required bone is missing; the message lists them.</exception>
        public void RequireComplete(string parameterName)
        {
            IReadOnlyList<HumanoidBone> missing = MissingRequired();
            if (missing.Count > 0)
                throw new ArgumentException($"The rig lacks required humanoid bones: {string.Join(", ", missing)}.", parameterName);
        }

        /// <summary>True when every required bone is mapped.</summary>
        public bool IsComplete => MissingRequired().Count == 0;

        /// <summary>The number of mapped bones.</summary>
        public int Count
        {
            get
            {
                int n = 0;
                foreach (int j in _jointByBone) if (j >= 0) n++;
                return n;
            }
        }

        /// <summary>The mapped bones and their joint names, in <see cref="HumanoidBone"/> order.</summary>
        public IEnumerable<KeyValuePair<HumanoidBone, string>> Pairs()
        {
            for (int b = 0; b < _jointByBone.Length; b++)
                if (_jointByBone[b] >= 0)
                    yield return new KeyValuePair<HumanoidBone, string>((HumanoidBone)b, Skeleton.GetName(_jointByBone[b]));
        }
    }
}
