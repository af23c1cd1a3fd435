namespace AvatarGo.Core
{
    /// <summary>What an inspector's fix button does for a <see cref="SetupFinding"/>.</summary>
    public enum SetupFix
    {
        /// <summary>No automatic fix; the message says what to do.</summary>
        None,
        /// <summary>Set the Animator's culling mode to Always Animate (IK stops when the avatar is culled otherwise).</summary>
        CullAlwaysAnimate,
        /// <summary>Turn the Animator's Apply Root Motion off (the hips follow the pelvis tracker, not the animation).</summary>
        DisableRootMotion,
        /// <summary>Make the avatar's scale uniform (x = y = z), keeping its height.</summary>
        MakeScaleUniform,
        /// <summary>
        /// Connect the tracking source to the scene's XR Origin: add an XR Origin Tracking Setup, which sets the source's
        /// tracking-space origin to the origin's camera offset (needs XR Core Utilities).
        /// </summary>
        ConnectXROrigin,
    }
}
