using System;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>Makes avatars with other proportions than a given skeleton (longer legs, shorter arms), for tests and evaluation.</summary>
    public static class Proportions
    {
        /// <summary>
        /// A copy of <paramref name="map"/>'s skeleton whose legs (hip → knee → ankle) are <paramref name="legScale"/> times
        /// as long and whose arms (shoulder → elbow → wrist) <paramref name="armScale"/> times, with the same humanoid map
        /// (<see cref="BodyProportions.Apply"/>: twist joints along a limb move with it).
        /// </summary>
        public static HumanoidMap ScaleLimbs(HumanoidMap map, float legScale, float armScale)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (!(legScale > 0f) || !(armScale > 0f)) throw new ArgumentOutOfRangeException(nameof(legScale), "Scales must be positive.");
            return new BodyProportions(legScale, legScale, armScale, armScale).Apply(map, 1f);
        }
    }
}
