// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    // Fields, not properties; the internal parentName and the obsolete transformModified are left out.
    public struct SkeletonBone
    {
        public string name;

        public Vector3 position;

        public Quaternion rotation;

        public Vector3 scale;
    }
}
