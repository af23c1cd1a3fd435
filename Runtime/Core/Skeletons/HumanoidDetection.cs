using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// The humanoid map of a clip: from its joints' names (<see cref="HumanoidNaming"/>), and when the names leave a required
    /// bone unfound, from its hierarchy and motion (<see cref="HumanoidStructure"/>). Bones given explicitly win either way.
    /// </summary>
    public static class HumanoidDetection
    {
        /// <summary>
        /// Detects the humanoid map of <paramref name="clip"/>'s skeleton. <paramref name="note"/> is null when the names
        /// found every required bone; otherwise it says which way the map was found (the structure, and how few bones the
        /// names gave) or why neither way found it. When neither does, the map returned is incomplete: the names' when the
        /// structure refused, the structure's with the bones given explicitly when those take a required bone's place.
        /// </summary>
        /// <exception cref="ArgumentException">An override names a joint the skeleton does not have.</exception>
        public static HumanoidMap Detect(BvhClip clip, IReadOnlyDictionary<string, HumanoidBone> overrides, out string note)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            note = null;
            HumanoidMap byNames = HumanoidNaming.Detect(clip.Skeleton, overrides);
            if (byNames.IsComplete) return byNames;
            HumanoidMap byStructure = HumanoidStructure.Detect(clip, out string failure);
            if (byStructure == null)
            {
                note = $"{Given(byNames.Count, overrides)}, and the hierarchy does not read as a humanoid either: {failure}";
                return byNames;
            }
            HumanoidMap merged = WithOverrides(byStructure, overrides);
            note = merged.IsComplete
                ? $"{Given(byNames.Count, overrides)}: all were found from the hierarchy and the motion instead (Documentation~/skeletons.md)"
                : $"{Given(byNames.Count, overrides)}; the hierarchy gives them all, but the bones given explicitly take the place of {string.Join(", ", merged.MissingRequired())}";
            // Incomplete or not, the structure with the bones given: what is missing and the note agree.
            return merged;
        }

        // How many bones the names found, the bones given explicitly counted apart.
        private static string Given(int found, IReadOnlyDictionary<string, HumanoidBone> overrides)
        {
            int given = overrides?.Count ?? 0;
            string names = $"the names give {Bones(found - given)}";
            return given == 0 ? names : $"{names} (and {Bones(given)} given explicitly)";
        }

        private static string Bones(int count) => count == 1 ? "1 humanoid bone" : $"{count} humanoid bones";

        /// <summary><paramref name="map"/> with the bones of <paramref name="overrides"/> (joint name → bone) in place of its own for those joints and bones.</summary>
        private static HumanoidMap WithOverrides(HumanoidMap map, IReadOnlyDictionary<string, HumanoidBone> overrides)
        {
            if (overrides == null || overrides.Count == 0) return map;
            var givenBones = new HashSet<HumanoidBone>(overrides.Values);
            var pairs = new List<KeyValuePair<HumanoidBone, string>>();
            foreach (var pair in map.Pairs())
                if (!givenBones.Contains(pair.Key) && !overrides.ContainsKey(pair.Value)) pairs.Add(pair);
            foreach (var given in overrides)
            {
                if (map.Skeleton.IndexOf(given.Key) < 0) throw new ArgumentException($"The skeleton has no joint named '{given.Key}' (for {given.Value}).", nameof(overrides));
                pairs.Add(new KeyValuePair<HumanoidBone, string>(given.Value, given.Key));
            }
            return new HumanoidMap(map.Skeleton, pairs);
        }
    }
}
