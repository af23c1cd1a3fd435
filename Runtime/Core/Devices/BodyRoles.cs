using System;

namespace AvatarGo.Core
{
    /// <summary>The six body roles the system tracks and the humanoid joint each one drives.</summary>
    public static class BodyRoles
    {
        /// <summary>The number of body roles (6).</summary>
        public const int Count = 6;

        /// <summary>The six roles in <see cref="IndexOf"/> order: head, hands, pelvis, feet.</summary>
        public static readonly DeviceRole[] All =
        {
            DeviceRole.Head, DeviceRole.LeftHand, DeviceRole.RightHand, DeviceRole.Pelvis, DeviceRole.LeftFoot, DeviceRole.RightFoot,
        };

        /// <summary>The position of <paramref name="role"/> in <see cref="All"/> (0 to 5), the index of per-role arrays.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="role"/> is <see cref="DeviceRole.None"/> or not a role.</exception>
        public static int IndexOf(DeviceRole role)
        {
            int i = (int)role - 1; // the enum's values 1 to 6 are All's order
            if ((uint)i >= Count) throw new ArgumentOutOfRangeException(nameof(role), role, "Not a body role.");
            return i;
        }

        /// <summary>The controller role of a hand.</summary>
        public static DeviceRole Hand(BodySide side) => side == BodySide.Left ? DeviceRole.LeftHand : DeviceRole.RightHand;

        /// <summary>The tracker role of a foot.</summary>
        public static DeviceRole Foot(BodySide side) => side == BodySide.Left ? DeviceRole.LeftFoot : DeviceRole.RightFoot;

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
