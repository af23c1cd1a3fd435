using System.Collections.Generic;
using AvatarGo.Core;
using UnityEditor;
using UnityEngine;

namespace AvatarGo.Editor
{
    /// <summary>
    /// The calibrator's inspector: the assigned avatar checked by <see cref="AvatarSetupCheck"/> (from the Animator:
    /// humanoid, bones, fingers, scale, culling, root motion, whether the calibrator can bind it) and the tracking setup by <see cref="TrackingSetupCheck"/>,
    /// each finding a help box with a Fix button where one is possible (applied with Undo); the default inspector below.
    /// </summary>
    [CustomEditor(typeof(AvatarGoCalibrator))]
    internal sealed class AvatarGoCalibratorEditor : UnityEditor.Editor
    {
        private const string FixUndo = "AvatarGo Fix";

        public override void OnInspectorGUI()
        {
            var calibrator = target as AvatarGoCalibrator;
            if (calibrator != null)
            {
                Animator animator = calibrator.Animator;
                if (animator == null && calibrator.AvatarRoot != null)
                    EditorGUILayout.HelpBox("The avatar is given by its root transform: its bones are found from their names when it starts (no humanoid Avatar is checked here).", MessageType.Info);
                else
                    Draw(AvatarSetupCheck.Check(ReadAvatar(animator)), calibrator);
                Draw(TrackingSetupCheck.Check(ReadTracking(calibrator.Source)), calibrator);
            }
            DrawDefaultInspector();
        }

        /// <summary>What <see cref="AvatarSetupCheck"/> needs, read from <paramref name="animator"/> (null: no Animator).</summary>
        internal static AvatarFacts ReadAvatar(Animator animator)
        {
            var facts = new AvatarFacts { HasAnimator = animator != null };
            if (animator == null) return facts;
            Avatar avatar = animator.avatar;
            facts.HasAvatar = avatar != null;
            facts.AvatarIsValid = avatar != null && avatar.isValid;
            facts.AvatarIsHuman = avatar != null && avatar.isHuman;
            facts.CullsAlwaysAnimate = animator.cullingMode == AnimatorCullingMode.AlwaysAnimate;
            facts.AppliesRootMotion = animator.applyRootMotion;
            Vector3 scale = animator.transform.lossyScale;
            facts.LossyScale = new System.Numerics.Vector3(scale.x, scale.y, scale.z);
            // GetBoneTransform throws from 2022.1 on an Animator without a valid humanoid Avatar.
            if (!facts.AvatarIsValid || !facts.AvatarIsHuman) return facts;
            for (int b = 0; b < (int)HumanBodyBones.LastBone; b++)
                if (animator.GetBoneTransform((HumanBodyBones)b) != null) facts.Bones.Add((HumanoidBone)b);
            Transform head = animator.GetBoneTransform(HumanBodyBones.Head);
            Transform left = animator.GetBoneTransform(HumanBodyBones.LeftFoot);
            Transform right = animator.GetBoneTransform(HumanBodyBones.RightFoot);
            if (head != null && (left != null || right != null))
            {
                float feet = left == null ? right.position.y : right == null ? left.position.y : System.Math.Min(left.position.y, right.position.y);
                facts.HeadAboveFeet = head.position.y - feet;
            }
            // What Start will do with it: the binding's own checks (every bone's scale within 0.1 %, bones below the Animator).
            if (!HumanoidBinding.TryBind(animator, out _, out string bindError)) facts.BindError = bindError;
            return facts;
        }

        /// <summary>What <see cref="TrackingSetupCheck"/> needs, read from <paramref name="source"/> and the open scenes.</summary>
        internal static TrackingSetupFacts ReadTracking(AvatarGoTrackingSource source)
        {
            var facts = new TrackingSetupFacts { HasSource = source != null };
            if (source == null) return facts;
            facts.HasTrackingSpaceOrigin = source.TrackingSpaceOrigin != null;
#if AVATARGO_XR_CORE_UTILS
            facts.SceneHasXROrigin = XROriginConnector.SceneHasXROrigin();
            facts.HasXROriginTrackingSetup = XROriginConnector.HasTrackingSetup(source);
#endif
            return facts;
        }

        private static void Draw(IReadOnlyList<SetupFinding> findings, AvatarGoCalibrator calibrator)
        {
            foreach (SetupFinding finding in findings)
            {
                EditorGUILayout.HelpBox(finding.Message, TypeOf(finding.Severity));
                string label = ButtonLabel(finding.Fix);
                if (label != null && GUILayout.Button(label))
                {
                    Apply(finding.Fix, calibrator);
                    GUIUtility.ExitGUI(); // the scene changed: end this GUI event rather than lay out the rest against the old state
                }
            }
        }

        private static MessageType TypeOf(SetupSeverity severity) =>
            severity == SetupSeverity.Error ? MessageType.Error : severity == SetupSeverity.Warning ? MessageType.Warning : MessageType.Info;

        private static string ButtonLabel(SetupFix fix)
        {
            switch (fix)
            {
                case SetupFix.CullAlwaysAnimate: return "Fix: set Culling Mode to Always Animate";
                case SetupFix.DisableRootMotion: return "Fix: turn Apply Root Motion off";
                case SetupFix.MakeScaleUniform: return "Fix: make the scale uniform (keep the height)";
#if AVATARGO_XR_CORE_UTILS
                case SetupFix.ConnectXROrigin: return "Fix: connect to the XR Origin";
#endif
                default: return null;
            }
        }

        private static void Apply(SetupFix fix, AvatarGoCalibrator calibrator)
        {
            Animator animator = calibrator.Animator;
            switch (fix)
            {
                case SetupFix.CullAlwaysAnimate when animator != null:
                    Undo.RecordObject(animator, FixUndo);
                    animator.cullingMode = AnimatorCullingMode.AlwaysAnimate;
                    break;
                case SetupFix.DisableRootMotion when animator != null:
                    Undo.RecordObject(animator, FixUndo);
                    animator.applyRootMotion = false;
                    break;
                case SetupFix.MakeScaleUniform when animator != null:
                    MakeScaleUniform(animator.transform);
                    break;
#if AVATARGO_XR_CORE_UTILS
                case SetupFix.ConnectXROrigin when calibrator.Source != null:
                    if (!XROriginConnector.Connect(calibrator.Source, FixUndo))
                        Debug.LogError("AvatarGo: the tracking source could not be connected: no XR Origin was found in the open scenes.", calibrator);
                    break;
#endif
            }
        }

        // The world scale becomes (y, y, y): the local scale's x and z are rescaled by y / x and y / z, so the height stays.
        private static void MakeScaleUniform(Transform transform)
        {
            Vector3 lossy = transform.lossyScale;
            if (lossy.x == 0f || lossy.z == 0f) return;
            Undo.RecordObject(transform, FixUndo);
            Vector3 local = transform.localScale;
            transform.localScale = new Vector3(local.x * lossy.y / lossy.x, local.y, local.z * lossy.y / lossy.z);
        }
    }
}
