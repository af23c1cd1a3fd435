using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// The checks the settings classes' setters make, so that a bad value fails where it is set, naming the setting
    /// (<c>Owner.Name</c>), not in a later frame or calibration step. Positive infinity passes where it turns a limit off.
    /// </summary>
    internal static class SettingChecks
    {
        public static float Positive(float value, string owner, string name) =>
            value > 0f ? value : throw new ArgumentOutOfRangeException(name, value, $"{owner}.{name} must be more than 0 (or infinity).");

        public static float NotNegative(float value, string owner, string name) =>
            value >= 0f ? value : throw new ArgumentOutOfRangeException(name, value, $"{owner}.{name} must be 0 or more (or infinity).");

        public static float PositiveFinite(float value, string owner, string name) =>
            value > 0f && !float.IsInfinity(value) ? value : throw new ArgumentOutOfRangeException(name, value, $"{owner}.{name} must be a finite number more than 0.");

        public static float NotNegativeFinite(float value, string owner, string name) =>
            value >= 0f && !float.IsInfinity(value) ? value : throw new ArgumentOutOfRangeException(name, value, $"{owner}.{name} must be a finite number, 0 or more.");

        public static float Finite(float value, string owner, string name) =>
            !float.IsNaN(value) && !float.IsInfinity(value) ? value : throw new ArgumentOutOfRangeException(name, value, $"{owner}.{name} must be a finite number.");
    }
}
