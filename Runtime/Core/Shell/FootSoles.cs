using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// The soles of an Animator avatar's feet and the floor. Unity's humanoid foot goal is at the ankle and its sole lies
    /// <c>Animator.left/rightFeetBottomHeight</c> below it along the goal's own down axis (the script reference's example for
    /// <c>leftFeetBottomHeight</c>): the sole is <c>goal + goalRotation × (0, −height, 0)</c>. Engine-free.
    /// </summary>
    public static class FootSoles
    {
        /// <summary>Where the sole is for an ankle goal at <paramref name="ankle"/> turned by <paramref name="goalRotation"/>.</summary>
        public static Vector3 Sole(Vector3 ankle, Quaternion goalRotation, float soleHeight) =>
            ankle + Vector3.Transform(new Vector3(0f, -soleHeight, 0f), goalRotation);

        /// <summary>
        /// The ankle goal raised (straight up, +Y) just enough that its sole is not below <paramref name="floorHeight"/>;
        /// unchanged when the sole is on or above the floor. Positions in a space whose +Y is up (tracking space).
        /// </summary>
        public static Vector3 KeepAboveFloor(Vector3 ankle, Quaternion goalRotation, float soleHeight, float floorHeight)
        {
            float below = floorHeight - Sole(ankle, goalRotation, soleHeight).Y;
            return below > 0f ? ankle + new Vector3(0f, below, 0f) : ankle;
        }
    }
}
