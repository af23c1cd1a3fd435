namespace AvatarGo.Core
{
    /// <summary>The primitive a <see cref="SdfShape"/> is.</summary>
    public enum SdfShapeKind
    {
        /// <summary>A segment from A to B swept by a radius (the paper's controller model).</summary>
        Capsule = 0,

        /// <summary>A ball around a centre.</summary>
        Sphere = 1,

        /// <summary>An axis-aligned box (in the shape's frame) with half extents.</summary>
        Box = 2,

        /// <summary>A box with rounded edges: half extents shrunk by the radius, then swept by it.</summary>
        RoundedBox = 3,
    }
}
