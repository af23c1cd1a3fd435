// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    // human and skeleton are fields, the rest properties; a new HumanDescription has every twist and stretch at 0.
    public struct HumanDescription
    {
        public HumanBone[] human;

        public SkeletonBone[] skeleton;

        public float upperArmTwist { get => throw null; set => throw null; }

        public float lowerArmTwist { get => throw null; set => throw null; }

        public float upperLegTwist { get => throw null; set => throw null; }

        public float lowerLegTwist { get => throw null; set => throw null; }

        public float armStretch { get => throw null; set => throw null; }

        public float legStretch { get => throw null; set => throw null; }

        public float feetSpacing { get => throw null; set => throw null; }

        public bool hasTranslationDoF { get => throw null; set => throw null; }
    }
}
