namespace AvatarGo.Core
{
    /// <summary>One BVH motion channel: a translation or a rotation (degrees) about a BVH axis.</summary>
    public enum BvhChannel : byte
    {
        /// <summary>Translation along BVH's X axis.</summary>
        Xposition = 0,

        /// <summary>Translation along BVH's Y axis.</summary>
        Yposition = 1,

        /// <summary>Translation along BVH's Z axis.</summary>
        Zposition = 2,

        /// <summary>Rotation about BVH's X axis, in degrees.</summary>
        Xrotation = 3,

        /// <summary>Rotation about BVH's Y axis, in degrees.</summary>
        Yrotation = 4,

        /// <summary>Rotation about BVH's Z axis, in degrees.</summary>
        Zrotation = 5,
    }
}
