using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Builds a humanoid stand-in avatar in the scene from a <see cref="MannequinBlueprint"/>: one transform per joint in
    /// the T-pose, a Unity primitive per part, and a humanoid Avatar made with <c>AvatarBuilder.BuildHumanAvatar</c>, so
    /// the package's components drive it like any imported humanoid. Every decision (which joints, where the parts go,
    /// how big) is the blueprint's; this only creates objects. The headset-free sample and the play-mode tests build their
    /// avatar with it; any skeleton a <see cref="HumanoidMap"/> describes (a BVH clip's, a session's wearer) can be one.
    /// </summary>
    public static class MannequinBuilder
    {
        /// <summary>
        /// Creates the mannequin under <paramref name="parent"/> (null: the scene root) and returns its Animator, or null
        /// (with the reason logged against <paramref name="context"/>) when Unity refuses the humanoid description.
        /// </summary>
        public static Animator Build(MannequinBlueprint blueprint, Transform parent, Object context)
        {
            var root = new GameObject(blueprint.RootName);
            root.transform.SetParent(parent, false);
            var transforms = new Transform[blueprint.Joints.Count];
            for (int i = 0; i < transforms.Length; i++)
            {
                MannequinJoint joint = blueprint.Joints[i];
                var go = new GameObject(joint.Name);
                transforms[i] = go.transform;
                go.transform.SetParent(joint.Parent < 0 ? root.transform : transforms[joint.Parent], false);
                go.transform.SetLocalPose(joint.Local);
            }
            foreach (MannequinPart part in blueprint.Parts)
            {
                GameObject shape = GameObject.CreatePrimitive(part.Shape == MannequinShape.Sphere ? PrimitiveType.Sphere : PrimitiveType.Capsule);
                shape.name = "Mesh";
                Object.Destroy(shape.GetComponent<Collider>()); // a picture of a body, not a physical one
                shape.transform.SetParent(transforms[part.Joint], false);
                shape.transform.localPosition = part.Centre.ToUnity();
                shape.transform.localRotation = part.Rotation.ToUnity();
                shape.transform.localScale = part.PrimitiveScale.ToUnity();
            }

            Avatar avatar = AvatarBuilder.BuildHumanAvatar(root, Describe(blueprint));
            if (avatar == null || !avatar.isValid || !avatar.isHuman)
            {
                Debug.LogError("The mannequin's humanoid Avatar could not be built (Unity logged why above).", context);
                // Nothing half-built is left in the scene (found in review).
                if (avatar != null) Object.Destroy(avatar);
                Object.Destroy(root);
                return null;
            }
            avatar.name = blueprint.RootName;
            Animator animator = root.AddComponent<Animator>();
            animator.avatar = avatar;
            return animator;
        }

        // The humanoid description: the blueprint's joints as the skeleton (the root first, local T-pose values) and its
        // humanoid bones under Unity's human names, with the importer's usual twist and stretch (set explicitly: a new
        // HumanDescription has them all at 0).
        private static HumanDescription Describe(MannequinBlueprint blueprint)
        {
            var skeleton = new List<SkeletonBone>(blueprint.Joints.Count + 1)
            {
                new SkeletonBone { name = blueprint.RootName, position = new Vector3(0f, 0f, 0f), rotation = new Quaternion(0f, 0f, 0f, 1f), scale = new Vector3(1f, 1f, 1f) },
            };
            foreach (MannequinJoint joint in blueprint.Joints)
                skeleton.Add(new SkeletonBone { name = joint.Name, position = joint.Local.Position.ToUnity(), rotation = joint.Local.Rotation.ToUnity(), scale = new Vector3(1f, 1f, 1f) });
            string[] humanNames = HumanTrait.BoneName;
            var human = new List<HumanBone>(blueprint.HumanBones.Count);
            foreach (KeyValuePair<HumanoidBone, string> bone in blueprint.HumanBones)
            {
                var limit = new HumanLimit { useDefaultValues = true };
                human.Add(new HumanBone { boneName = bone.Value, humanName = humanNames[(int)bone.Key], limit = limit });
            }
            return new HumanDescription
            {
                skeleton = skeleton.ToArray(),
                human = human.ToArray(),
                upperArmTwist = 0.5f,
                lowerArmTwist = 0.5f,
                upperLegTwist = 0.5f,
                lowerLegTwist = 0.5f,
                armStretch = 0.05f,
                legStretch = 0.05f,
                feetSpacing = 0f,
                hasTranslationDoF = false,
            };
        }
    }
}
