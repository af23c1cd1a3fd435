namespace AvatarGo.Core
{
    /// <summary>What a file imported by the Editor's Import Session or BVH menu holds.</summary>
    public enum RecordingFileKind
    {
        /// <summary>A recorded session, format v1 (<c>.agsession</c>; Documentation~/session-format.md).</summary>
        Session,
        /// <summary>A BVH motion clip (<c>.bvh</c>).</summary>
        Bvh,
    }
}
