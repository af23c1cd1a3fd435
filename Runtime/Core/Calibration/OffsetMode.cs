namespace AvatarGo.Core
{
    /// <summary>How device-to-joint offsets are obtained.</summary>
    public enum OffsetMode
    {
        /// <summary>The paper's method: measured per wearer after walking into the avatar.</summary>
        Exact = 0,

        /// <summary>The paper's baseline: constant, ad-hoc position offsets (see <see cref="CalibrationProfile.WithFixedOffsets"/>).</summary>
        Fixed = 1,
    }
}
