using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// How AvatarGo recognises the controllers of an XR rig (an XR Interaction Toolkit <c>XROrigin</c>) when they were not
    /// assigned: from the binding path of the pose driver that moves an object, or, as a last resort, from an object's name
    /// (XRI named them "LeftHand Controller" in 2.0-2.3, "Left Controller" from 2.5, and its samples "LeftHand (Smooth
    /// locomotion)"; hand-tracking objects "Left Hand" sit beside them). Scores rank candidates; 0 is no candidate.
    /// </summary>
    public static class XrRigRules
    {
        /// <summary>
        /// How surely a pose binding path is a controller's: 2 for an <c>&lt;XRController&gt;</c> with a hand usage
        /// (<c>&lt;XRController&gt;{LeftHand}/devicePosition</c>), 1 for any other device with a hand usage (a hand-tracking
        /// device), 0 otherwise; <paramref name="side"/> says which hand. Input System names are case-insensitive.
        /// </summary>
        public static int BindingScore(string bindingPath, out BodySide side)
        {
            side = BodySide.Left;
            if (string.IsNullOrEmpty(bindingPath)) return 0;
            bool left = Contains(bindingPath, "{LeftHand}"), right = Contains(bindingPath, "{RightHand}");
            if (left == right) return 0;
            side = left ? BodySide.Left : BodySide.Right;
            return Contains(bindingPath, "<XRController>") ? 2 : 1;
        }

        /// <summary>
        /// How surely an object's name is a controller's: 2 when it names one side and "controller", 1 when it names one side
        /// and "hand" (the XRI 2.x sample rigs' "LeftHand (Smooth locomotion)", but also a hand-tracking "Left Hand"), else 0.
        /// </summary>
        public static int NameScore(string name, out BodySide side)
        {
            side = BodySide.Left;
            if (string.IsNullOrEmpty(name)) return 0;
            bool left = Contains(name, "left"), right = Contains(name, "right");
            if (left == right) return 0;
            side = left ? BodySide.Left : BodySide.Right;
            return Contains(name, "controller") ? 2 : Contains(name, "hand") ? 1 : 0;
        }

        private static bool Contains(string text, string part) => text.IndexOf(part, StringComparison.OrdinalIgnoreCase) >= 0;
    }
}
