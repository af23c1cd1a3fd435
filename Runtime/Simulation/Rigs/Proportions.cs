using System;
using System.Collections.Generic;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>Makes avatars with other proportions than a given skeleton (longer legs, shorter arms), for tests and evaluation.</summary>
    public static class Proportions
    {
        /// <summary>
        /// A copy of <paramref name="map"/>'s skeleton whose legs (hip → knee → ankle) are <paramref name="legScale"/> times
        /// as long and whose arms (shoulder → elbow → wrist) <paramref name="armScale"/> times, with the same humanoid map.
        /// </summary>
        public static HumanoidMap ScaleLimbs(HumanoidMap map, float legScale, float armScale)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            if (!(legScale > 0f) || !(armScale > 0f)) throw new ArgumentOutOfRangeException(nameof(legScale), "Scales must be positive.");
            Skeleton s = map.Skeleton;
            var rest = new RigidPose[s.JointCount];
            for (int j = 0; j < rest.Length; j++) rest[j] = s.GetRestLocal(j);
            void Scale(HumanoidBone bone, float factor)
            {
                int j = map[bone];
                if (j >= 0) rest[j] = rest[j].WithPosition(rest[j].Position * factor);
            }
            foreach (bool left in new[] { true, false })
            {
                Scale(left ? HumanoidBone.LeftLowerLeg : HumanoidBone.RightLowerLeg, legScale);
                Scale(left ? HumanoidBone.LeftFoot : HumanoidBone.RightFoot, legScale);
                Scale(left ? HumanoidBone.LeftLowerArm : HumanoidBone.RightLowerArm, armScale);
                Scale(left ? HumanoidBone.LeftHand : HumanoidBone.RightHand, armScale);
            }
            var parents = new int[s.JointCount];
            var ends = new bool[s.JointCount];
            for (int j = 0; j < parents.Length; j++)
            {
                parents[j] = s.GetParent(j);
                ends[j] = s.IsEndSite(j);
            }
            return new HumanoidMap(new Skeleton(s.Names, parents, rest, ends), new List<KeyValuePair<HumanoidBone, string>>(map.Pairs()));
        }
    }
}
