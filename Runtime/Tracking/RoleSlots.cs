namespace AvatarGo
{
    /// <summary>The sources that read one device per body role: which of their six per-role settings a device index is.</summary>
    internal static class RoleSlots
    {
        /// <summary>
        /// The one of six per-role values at <paramref name="slot"/>, a position in <c>BodyRoles.All</c> order (0 to 5;
        /// anything past 4 is the right foot).
        /// </summary>
        internal static T Pick<T>(int slot, T head, T leftHand, T rightHand, T pelvis, T leftFoot, T rightFoot)
        {
            switch (slot)
            {
                case 0: return head;
                case 1: return leftHand;
                case 2: return rightHand;
                case 3: return pelvis;
                case 4: return leftFoot;
                default: return rightFoot;
            }
        }
    }
}
