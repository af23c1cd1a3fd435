using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Which joint of a <see cref="Skeleton"/> plays each <see cref="HumanBone"/>. Built by
    /// <c>HumanoidNaming</c> from joint names, or by hand; immutable once built.
    /// </summary>
    public sealed class HumanoidMap
    {
        private readonly int[] _jointByBone;

        /// <summary>The skeleton this map refers to.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Creates a map from bone → joint-name pairs; names must exist in <paramref name="skeleton"/>.</summary>
        /// <exception cref="ArgumentException">A name is not a joint of the skeleton, or one joint is given two bones.</exception>
        public HumanoidMap(Skeleton skeleton, IEnumerable<KeyValuePair<HumanBone, string>> bones)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            _jointByBone = new int[HumanBones.Count];
            for (int i = 0; i < _jointByBone.Length; i++) _jointByBone[i] = -1;
            var boneByJoint = new Dictionary<int, HumanBone>();
            foreach (var pair in bones ?? throw new ArgumentNullException(nameof(bones)))
            {
                if (!HumanBones.IsValid(pair.Key)) throw new ArgumentException($"'{pair.Key}' is not a humanoid bone.", nameof(bones));
                int joint = skeleton.IndexOf(pair.Value);
                if (joint < 0) throw new ArgumentException($"The skeleton has no joint named '{pair.Value}' (for {pair.Key}).", nameof(bones));
                if (boneByJoint.TryGetValue(joint, out HumanBone other) && other != pair.Key)
                    throw new ArgumentException($"Joint '{pair.Value}' is mapped to both {other} and {pair.Key}.", nameof(bones));
                boneByJoint[joint] = pair.Key;
                _jointByBone[(int)pair.Key] = joint;
            }
        }

        /// <summary>The joint index of <paramref name="bone"/>, or -1 when the rig does not have it.</summary>
        public int this[HumanBone bone] => HumanBones.IsValid(bone) ? _jointByBone[(int)bone] : -1;

        /// <summary>True when the rig has <paramref name="bone"/>.</summary>
        public bool Has(HumanBone bone) => this[bone] >= 0;

        /// <summary>The joint name of <paramref name="bone"/>, or null.</summary>
        public string NameOf(HumanBone bone)
        {
            int joint = this[bone];
            return joint >= 0 ? Skeleton.GetName(joint) : null;
        }

        /// <summary>The humanoid bone played by <paramref name="joint"/>, or <see cref="HumanBone.LastBone"/> for none.</summary>
        public HumanBone BoneOf(int joint)
        {
            for (int b = 0; b < _jointByBone.Length; b++)
                if (_jointByBone[b] == joint) return (HumanBone)b;
            return HumanBone.LastBone;
        }

        /// <summary>The required bones (<see cref="HumanBones.Required"/>) the rig lacks; empty for a complete humanoid.</summary>
        public IReadOnlyList<HumanBone> MissingRequired()
        {
            var missing = new List<HumanBone>();
            foreach (HumanBone bone in HumanBones.Required)
                if (!Has(bone)) missing.Add(bone);
            return missing;
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

        /// <summary>The mapped bones and their joint names, in <see cref="HumanBone"/> order.</summary>
        public IEnumerable<KeyValuePair<HumanBone, string>> Pairs()
        {
            for (int b = 0; b < _jointByBone.Length; b++)
                if (_jointByBone[b] >= 0)
                    yield return new KeyValuePair<HumanBone, string>((HumanBone)b, Skeleton.GetName(_jointByBone[b]));
        }
    }
}
