using System;

namespace AvatarGo.Core
{
    /// <summary>The six body roles the system tracks and the humanoid joint each one drives.</summary>
    public static class BodyRoles
    {
        /// <summary>The six roles, in the order per-role arrays use: head, hands, pelvis, feet.</summary>
        public static readonly DeviceRole[] All =
        {
            DeviceRole.Head, DeviceRole.LeftHand, DeviceRole.RightHand, DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot,
        };

        /// <summary>The humanoid joint a role's device drives (head, wrists, hips, ankles).</summary>
        public static HumanBone JointOf(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Head: return HumanBone.Head;
                case DeviceRole.LeftHand: return HumanBone.LeftHand;
                case DeviceRole.RightHand: return HumanBone.RightHand;
                case DeviceRole.Pelvis: return HumanBone.Hips;
                case DeviceRole.LeftFoot: return HumanBone.LeftFoot;
                case DeviceRole.RightFoot: return HumanBone.RightFoot;
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "No joint for this role.");
            }
        }
    }
}
