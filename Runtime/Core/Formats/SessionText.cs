using System;

namespace AvatarGo.Core
{
    /// <summary>Shared vocabulary of the session text format: keywords and the names of enum values.</summary>
    internal static class SessionText
    {
        public const string Magic = "avatargo-session";

        public static string ClassName(DeviceClass c) =>
            c == DeviceClass.Hmd ? "hmd" : c == DeviceClass.Controller ? "controller" : "tracker";

        public static bool TryClass(ReadOnlySpan<char> s, out DeviceClass c)
        {
            if (s.SequenceEqual("hmd".AsSpan())) { c = DeviceClass.Hmd; return true; }
            if (s.SequenceEqual("controller".AsSpan())) { c = DeviceClass.Controller; return true; }
            if (s.SequenceEqual("tracker".AsSpan())) { c = DeviceClass.Tracker; return true; }
            c = default;
            return false;
        }

        private static readonly string[] RoleNames = { "none", "head", "left-hand", "right-hand", "pelvis", "left-foot", "right-foot" };

        public static string RoleName(DeviceRole r) => RoleNames[(int)r];

        public static bool TryRole(ReadOnlySpan<char> s, out DeviceRole r)
        {
            for (int i = 0; i < RoleNames.Length; i++)
                if (s.SequenceEqual(RoleNames[i].AsSpan())) { r = (DeviceRole)i; return true; }
            r = default;
            return false;
        }

        public static string EventName(DeviceEventKind k) => k == DeviceEventKind.TriggerPressed ? "trigger-pressed" : "trigger-released";

        public static bool TryEvent(ReadOnlySpan<char> s, out DeviceEventKind k)
        {
            if (s.SequenceEqual("trigger-pressed".AsSpan())) { k = DeviceEventKind.TriggerPressed; return true; }
            if (s.SequenceEqual("trigger-released".AsSpan())) { k = DeviceEventKind.TriggerReleased; return true; }
            k = default;
            return false;
        }

        private static readonly string[] BoneNames = BuildBoneNames();

        private static string[] BuildBoneNames()
        {
            var names = new string[HumanoidBones.Count];
            for (int b = 0; b < names.Length; b++) names[b] = ((HumanoidBone)b).ToString();
            return names;
        }

        /// <summary>The Unity HumanBodyBones name of a bone, without allocating.</summary>
        public static string BoneName(HumanoidBone bone) => BoneNames[(int)bone];

        public static bool TryBone(ReadOnlySpan<char> s, out HumanoidBone bone)
        {
            for (int b = 0; b < BoneNames.Length; b++)
                if (s.SequenceEqual(BoneNames[b].AsSpan())) { bone = (HumanoidBone)b; return true; }
            bone = HumanoidBone.LastBone;
            return false;
        }

        /// <summary>
        /// A serial as the format can write it: each white-space character as '_', and "-" (the format's "no serial") as
        /// "_". Any other serial, the empty one included, is returned as it is.
        /// </summary>
        public static string WritableSerial(string serial)
        {
            if (serial == "-") return "_";
            if (string.IsNullOrEmpty(serial) || IsToken(serial)) return serial;
            char[] c = serial.ToCharArray();
            for (int i = 0; i < c.Length; i++) if (char.IsWhiteSpace(c[i])) c[i] = '_';
            return new string(c);
        }

        /// <summary>True when <paramref name="s"/> can stand as one token (non-empty, no white space).</summary>
        public static bool IsToken(string s)
        {
            if (string.IsNullOrEmpty(s)) return false;
            foreach (char c in s) if (char.IsWhiteSpace(c)) return false;
            return true;
        }
    }
}
