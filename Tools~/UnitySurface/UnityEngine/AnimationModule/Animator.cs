// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial class Animator : Behaviour
    {
        public bool applyRootMotion { get => throw null; set => throw null; }

        public AnimatorUpdateMode updateMode { get => throw null; set => throw null; }

        // The humanoid's centre of mass and body orientation, not the hips; IK pass only.
        public Vector3 bodyPosition { get => throw null; set => throw null; }

        public Quaternion bodyRotation { get => throw null; set => throw null; }

        public Quaternion GetIKRotation(AvatarIKGoal goal) => throw null;

        public void SetIKPosition(AvatarIKGoal goal, Vector3 goalPosition) => throw null;

        public void SetIKRotation(AvatarIKGoal goal, Quaternion goalRotation) => throw null;

        public void SetIKPositionWeight(AvatarIKGoal goal, float value) => throw null;

        public void SetIKRotationWeight(AvatarIKGoal goal, float value) => throw null;

        public void SetIKHintPosition(AvatarIKHint hint, Vector3 hintPosition) => throw null;

        public void SetIKHintPositionWeight(AvatarIKHint hint, float value) => throw null;

        public void SetBoneLocalRotation(HumanBodyBones humanBoneId, Quaternion rotation) => throw null;

        public float feetPivotActive { get => throw null; set => throw null; }

        // Throws InvalidOperationException from 2022.1 when the avatar is missing, invalid or not humanoid: trap T3.
        public Transform GetBoneTransform(HumanBodyBones humanBoneId) => throw null;

        public AnimatorCullingMode cullingMode { get => throw null; set => throw null; }

        public RuntimeAnimatorController runtimeAnimatorController { get => throw null; set => throw null; }

        public Avatar avatar { get => throw null; set => throw null; }

        public float leftFeetBottomHeight => throw null;

        public float rightFeetBottomHeight => throw null;
    }
}
