using System;
using System.Globalization;
using System.IO;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Where the Unity components keep their files, and which saved file fits: the folder under the application's data
    /// folder, the calibration profile's name per avatar, recordings' time-stamped names, and how a configured path is
    /// resolved. Engine-free: the components pass <c>Application.persistentDataPath</c> in.
    /// </summary>
    public static class AvatarGoFiles
    {
        /// <summary>The folder (under the application's persistent data folder) the components write to.</summary>
        public const string FolderName = "AvatarGo";

        /// <summary>The extension of session files.</summary>
        public const string SessionExtension = ".agsession";

        /// <summary>How far (m) a saved profile's avatar eye height may be from this avatar's for the profile to fit it (1 mm).</summary>
        public const float EyeHeightTolerance = 0.001f;

        /// <summary>The folder under <paramref name="dataFolder"/> the components write to.</summary>
        public static string Folder(string dataFolder) => Path.Combine(dataFolder ?? throw new ArgumentNullException(nameof(dataFolder)), FolderName);

        /// <summary>
        /// The calibration profile's file name for an avatar: <c>calibration-&lt;name&gt;.json</c>, the name reduced to letters,
        /// digits, '-' and '_' (anything else becomes '_'), "avatar" when empty.
        /// </summary>
        public static string ProfileFileName(string avatarName) => "calibration-" + Sanitize(avatarName, "avatar") + ".json";

        /// <summary>A recording's file name: <c>&lt;prefix&gt;-yyyyMMdd-HHmmss.agsession</c> (prefix sanitised, "session" when empty).</summary>
        public static string RecordingFileName(string prefix, DateTime time) =>
            Sanitize(prefix, "session") + "-" + time.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture) + SessionExtension;

        /// <summary>
        /// The path of a new recording in <paramref name="folder"/>: <see cref="RecordingFileName"/>, or with "-2", "-3"… before
        /// the extension while <paramref name="exists"/> says the name is taken (a second recording started within the same
        /// second would otherwise replace the first when it completes).
        /// </summary>
        public static string NewRecordingPath(string folder, string prefix, DateTime time, Func<string, bool> exists)
        {
            if (folder == null) throw new ArgumentNullException(nameof(folder));
            if (exists == null) throw new ArgumentNullException(nameof(exists));
            string name = RecordingFileName(prefix, time);
            string path = Path.Combine(folder, name);
            string stem = name.Substring(0, name.Length - SessionExtension.Length);
            for (int take = 2; exists(path); take++)
                path = Path.Combine(folder, stem + "-" + take.ToString(CultureInfo.InvariantCulture) + SessionExtension);
            return path;
        }

        /// <summary>
        /// A configured path as a full path: an absolute path as it is, a relative one under <paramref name="baseFolder"/>;
        /// null for an empty path.
        /// </summary>
        public static string Resolve(string path, string baseFolder)
        {
            if (string.IsNullOrWhiteSpace(path)) return null;
            return Path.GetFullPath(Path.IsPathRooted(path) ? path : Path.Combine(baseFolder ?? throw new ArgumentNullException(nameof(baseFolder)), path));
        }

        /// <summary>
        /// True when a saved <paramref name="profile"/> was measured on this avatar: its avatar eye height (in the avatar's
        /// own units, before scaling) is this avatar's within <see cref="EyeHeightTolerance"/>. Otherwise false with the reason:
        /// its offsets belong to another avatar's joints.
        /// </summary>
        public static bool ProfileFits(CalibrationProfile profile, HumanoidMap avatar, out string reason) => ProfileFits(profile, avatar, false, out reason);

        /// <summary>
        /// As <see cref="ProfileFits(CalibrationProfile, HumanoidMap, out string)"/>, for a calibration whose avatar T-pose kept
        /// the joints between the spine bones as bound (<see cref="CalibrationSettings.SpineJointsAsBound"/>, the Animator IK
        /// driver's): the eye height is measured in the same T-pose the calibration measured it in.
        /// </summary>
        public static bool ProfileFits(CalibrationProfile profile, HumanoidMap avatar, bool spineJointsAsBound, out string reason)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            if (avatar == null) throw new ArgumentNullException(nameof(avatar));
            var pose = new SkeletonPose(avatar.Skeleton);
            TPoser.Apply(avatar, pose, RigidPose.Identity, null, spineJointsAsBound);
            float eye = TPoser.EyePosition(avatar, pose, Quaternion.Identity).Y;
            if (Math.Abs(eye - profile.AvatarEyeHeight) <= EyeHeightTolerance)
            {
                reason = null;
                return true;
            }
            reason = $"the profile was measured on an avatar with eyes at {profile.AvatarEyeHeight:0.000} m, this one has them at {eye:0.000} m";
            return false;
        }

        private static string Sanitize(string name, string fallback)
        {
            if (string.IsNullOrWhiteSpace(name)) return fallback;
            var s = new StringBuilder(name.Length);
            foreach (char c in name.Trim())
                s.Append(c < 128 && (char.IsLetterOrDigit(c) || c == '-' || c == '_') ? c : '_');
            return s.ToString();
        }
    }
}
