using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>What an inspector reads from the assigned avatar's Animator, for <see cref="AvatarSetupCheck"/>.</summary>
    public sealed class AvatarFacts
    {
        /// <summary>The object has an Animator.</summary>
        public bool HasAnimator { get; set; }

        /// <summary>The Animator has an Avatar asset.</summary>
        public bool HasAvatar { get; set; }

        /// <summary>The Avatar is valid (<c>Avatar.isValid</c>).</summary>
        public bool AvatarIsValid { get; set; }

        /// <summary>The Avatar is a humanoid (<c>Avatar.isHuman</c>).</summary>
        public bool AvatarIsHuman { get; set; }

        /// <summary>The humanoid bones the Animator returns a transform for (<c>Animator.GetBoneTransform</c>).</summary>
        public ISet<HumanoidBone> Bones { get; set; } = new HashSet<HumanoidBone>();

        /// <summary>The avatar root's world scale (<c>Transform.lossyScale</c>).</summary>
        public Vector3 LossyScale { get; set; } = Vector3.One;

        /// <summary>The head bone's height above the lower foot bone, in metres, as the avatar stands in the scene.</summary>
        public float HeadAboveFeet { get; set; }

        /// <summary>The Animator's culling mode is Always Animate.</summary>
        public bool CullsAlwaysAnimate { get; set; } = true;

        /// <summary>The Animator applies root motion.</summary>
        public bool AppliesRootMotion { get; set; }

        /// <summary>
        /// Why the calibrator cannot bind the avatar when it starts (the reason <c>HumanoidBinding.TryBind</c> gives: a bone
        /// or the Animator's own transform with a non-uniform scale, a bone outside the Animator's hierarchy...), or null when
        /// it can or this was not asked.
        /// </summary>
        public string BindError { get; set; }
    }
}
