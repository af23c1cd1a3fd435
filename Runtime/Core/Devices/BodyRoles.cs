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
        public static HumanoidBone JointOf(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Head: return HumanoidBone.Head;
                case DeviceRole.LeftHand: return HumanoidBone.LeftHand;
                case DeviceRole.RightHand: return HumanoidBone.RightHand;
                case DeviceRole.Pelvis: return HumanoidBone.Hips;
                case DeviceRole.LeftFoot: return HumanoidBone.LeftFoot;
                case DeviceRole.RightFoot: return HumanoidBone.RightFoot;
                default: throw new ArgumentOutOfRangeException(nameof(role), role, "No joint for this role.");
            }
        }
    }
}
