using System;
using System.Collections.Generic;
using System.IO;
using System.Globalization;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// Saves and loads <see cref="CalibrationProfile"/>s as versioned JSON. Saving is atomic
    /// (<see cref="AtomicFileWriter"/>): the text goes to a temporary file beside the target, is flushed to disk, then
    /// replaces the target in one rename, so a crash mid-save leaves either the old profile or the new one, never a torn
    /// file, and concurrent saves of one profile never fail on each other.
    /// </summary>
    /// <remarks>
    /// Loading checks every number where it is read, so that a profile that loads can be restored, solved and saved
    /// again: the avatar scale within <see cref="MinAvatarScale"/>…<see cref="MaxAvatarScale"/>, eye heights from 0
    /// (unknown) to <see cref="MaxHeight"/>, every position (floor height included) within ±<see cref="MaxPosition"/>,
    /// unit quaternions, device ids that fit an int; and the text at most <see cref="MaxFileLength"/> characters.
    /// </remarks>
    public static class CalibrationProfileStore
    {
        /// <summary>The <c>format</c> member every profile file carries.</summary>
        public const string FormatName = "avatargo-calibration-profile";

        /// <summary>
        /// The longest profile text read, in characters (64 Ki; a saved profile is about 3 KB). JSON builds a node per
        /// value, so this also bounds the parse: the largest accepted text parses in milliseconds.
        /// </summary>
        public const int MaxFileLength = 64 << 10;

        /// <summary>The smallest avatar scale a profile may hold: 1e-4 (an avatar modelled in millimetres is about 0.001, a
        /// wearer a third shorter than it 0.0007).</summary>
        public const float MinAvatarScale = 1e-4f;

        /// <summary>The largest avatar scale a profile may hold.</summary>
        public const float MaxAvatarScale = 1e4f;

        /// <summary>The largest eye height (wearer's or unscaled avatar's) a profile may hold, in metres or the avatar's units.</summary>
        public const float MaxHeight = 1e4f;

        /// <summary>
        /// The largest coordinate of a position (and the floor height) a profile may hold, in metres: 10 km, where a
        /// float's resolution is still about a millimetre. Tracking spaces are tens of metres.
        /// </summary>
        public const float MaxPosition = 1e4f;

        /// <summary>The profile as JSON text.</summary>
        public static string ToJson(CalibrationProfile profile)
        {
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            var w = new JsonWriter();
            w.BeginObject();
            w.Name("format").Value(FormatName);
            w.Name("version").Value(CalibrationProfile.Version);
            w.Name("mode").Value(profile.Mode == OffsetMode.Exact ? "exact" : "fixed");
            w.Name("avatarScale").Value(profile.AvatarScale);
            w.Name("wearerEyeHeight").Value(profile.WearerEyeHeight);
            w.Name("avatarEyeHeight").Value(profile.AvatarEyeHeight);
            w.Name("floorHeight").Value(profile.FloorHeight);
            w.Name("placement"); WritePose(w, profile.Placement);
            w.Name("rootToHead").Values(profile.RootToHead.X, profile.RootToHead.Y, profile.RootToHead.Z);
            w.Name("scaleMode").Value(profile.ScaleMode == ScaleMode.Fitted ? "fitted" : "uniform");
            BodyProportions pr = profile.Proportions;
            w.Name("proportions").BeginObject();
            w.Name("leftLeg").Value(pr.LeftLeg).Name("rightLeg").Value(pr.RightLeg).Name("leftArm").Value(pr.LeftArm).Name("rightArm").Value(pr.RightArm);
            w.EndObject();
            if (profile.Measurements != null)
            {
                w.Name("measurements").BeginObject();
                w.Name("windows").Value(profile.Measurements.Windows);
                foreach (var (name, m) in profile.Measurements.All()) w.Name(name).Values(m.Value, m.Uncertainty);
                w.EndObject();
            }
            w.Name("roles").BeginObject();
            foreach (DeviceRole role in BodyRoles.All)
            {
                w.Name(RoleKey(role)).BeginObject();
                w.Name("deviceId").Value(profile.DeviceId(role));
                w.Name("serial").Value(profile.Serial(role));
                w.Name("deviceAtCalibration"); WritePose(w, profile.DeviceAtCalibration(role));
                w.Name("jointAtCalibration"); WritePose(w, profile.JointAtCalibration(role));
                w.Name("jointInDevice"); WritePose(w, profile.JointInDevice(role));
                w.EndObject();
            }
            w.EndObject();
            w.EndObject();
            return w.ToString() + "\n";
        }

        /// <summary>Reads a profile from JSON text.</summary>
        /// <exception cref="FormatException">Not a profile, an unknown version, or a missing, malformed or out-of-range member.</exception>
        public static CalibrationProfile FromJson(string json) => FromJson(json, null);

        /// <summary>
        /// Reads a profile from JSON text read from <paramref name="sourceName"/> (a file name): every error reads
        /// <c>SOURCE:LINE: problem</c>.
        /// </summary>
        /// <exception cref="FormatException">Not a profile, an unknown version, or a missing, malformed or out-of-range member.</exception>
        public static CalibrationProfile FromJson(string json, string sourceName)
        {
            if (json == null) throw new ArgumentNullException(nameof(json));
            if (json.Length > MaxFileLength)
                throw new FormatException($"{(sourceName == null ? "" : sourceName + ":1: ")}{json.Length} characters is more than a calibration profile holds (at most {MaxFileLength})");
            JsonNode root = JsonNode.Parse(json, sourceName);
            if (root.Kind != JsonKind.Object || root["format"]?.String != FormatName) throw root.Error($"Not an AvatarGo calibration profile (no \"format\": \"{FormatName}\").");
            double version = root.GetNumber("version");
            if (version != 1 && version != CalibrationProfile.Version)
                throw root["version"].Error($"Calibration profile version {version.ToString(CultureInfo.InvariantCulture)} is not supported (this package reads versions 1 to {CalibrationProfile.Version}).");
            var p = new CalibrationProfile
            {
                AvatarScale = Number(root, "avatarScale", MinAvatarScale, MaxAvatarScale),
                WearerEyeHeight = Number(root, "wearerEyeHeight", 0f, MaxHeight),
                AvatarEyeHeight = Number(root, "avatarEyeHeight", 0f, MaxHeight),
                FloorHeight = Number(root, "floorHeight", -MaxPosition, MaxPosition),
                Placement = ReadPose(root, "placement"),
                RootToHead = ReadPosition(root, "rootToHead"),
            };
            if (version >= 2) ReadProportions(root, p);
            string mode = root.GetString("mode");
            if (mode != "exact" && mode != "fixed") throw root["mode"].Error($"'mode' must be exact or fixed, not '{JsonNode.Printable(mode)}'.");
            JsonNode roles = root["roles"];
            if (roles == null || roles.Kind != JsonKind.Object) throw (roles ?? root).Error("'roles' must be an object.");
            foreach (DeviceRole role in BodyRoles.All)
            {
                string key = RoleKey(role);
                JsonNode r = roles[key] ?? throw roles.Error($"'roles' has no '{key}'.");
                if (r.Kind != JsonKind.Object) throw r.Error($"'{key}' must be an object.");
                double id = r.GetNumber("deviceId");
                if (!(id >= 0 && id <= int.MaxValue) || id != Math.Floor(id)) throw r["deviceId"].Error($"{key}.deviceId must be an integer from 0 to {int.MaxValue}.");
                p.SetDevice(role, new DeviceInfo((int)id, DeviceClass.Tracker, r.GetString("serial")));
                p.SetOffsets(role, ReadPose(r, "deviceAtCalibration", key + "."), ReadPose(r, "jointAtCalibration", key + "."));
            }
            return mode == "fixed" ? p.WithFixedOffsets() : p;
        }

        /// <summary>
        /// Saves atomically (see the class remarks and <see cref="AtomicFileWriter"/>), creating the folder if needed. A
        /// save that fails leaves the previous file as it was and no temporary file behind.
        /// </summary>
        /// <exception cref="ArgumentException">The profile holds a value <see cref="Load"/> would refuse (it is not written).</exception>
        /// <exception cref="IOException">The file cannot be written.</exception>
        public static void Save(CalibrationProfile profile, string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            string json = ToJson(profile);
            // Before anything is touched: a profile that would not load back (a scale out of range) is refused here.
            try { FromJson(json); }
            catch (FormatException e) { throw new ArgumentException("The profile cannot be saved: it would not load back: " + e.Message, nameof(profile), e); }
            // A root ("/", "C:\") has no folder to create: the writer then says it is a folder (found in review: null was
            // passed on, and an ArgumentNullException came out where the docs promise an IOException).
            string folder = Path.GetDirectoryName(Path.GetFullPath(path));
            if (!string.IsNullOrEmpty(folder)) Directory.CreateDirectory(folder);
            AtomicFileWriter.WriteAllText(path, json);
        }

        /// <summary>Loads a profile saved by <see cref="Save"/>.</summary>
        /// <exception cref="FormatException">The file is not a valid profile; the message (<c>FILE:LINE: problem</c>) names the problem.</exception>
        /// <exception cref="IOException">The file cannot be read, or the path is a folder.</exception>
        public static CalibrationProfile Load(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            InputFiles.ThrowIfFolder(path);
            string name = Path.GetFileName(path);
            // Refuse a huge file before reading it into memory.
            long length = new FileInfo(path).Length;
            if (length > MaxFileLength * 4L) throw new FormatException($"{name}:1: {length} bytes is more than a calibration profile holds (at most {MaxFileLength} characters)");
            return FromJson(File.ReadAllText(path), name);
        }

        /// <summary>The largest limb ratio (relative to the overall scale) a profile may hold, and the inverse the smallest.</summary>
        public const float MaxProportion = 4f;

        // Version 2: the scale mode, the proportions (required) and the measurements (optional: a profile whose fit was not
        // measured has none).
        private static void ReadProportions(JsonNode root, CalibrationProfile p)
        {
            string scaleMode = root.GetString("scaleMode");
            if (scaleMode != "uniform" && scaleMode != "fitted") throw root["scaleMode"].Error($"'scaleMode' must be uniform or fitted, not '{JsonNode.Printable(scaleMode)}'.");
            p.ScaleMode = scaleMode == "fitted" ? ScaleMode.Fitted : ScaleMode.Uniform;
            JsonNode pr = root["proportions"];
            if (pr == null || pr.Kind != JsonKind.Object) throw (pr ?? root).Error("'proportions' must be an object with leftLeg, rightLeg, leftArm and rightArm.");
            p.Proportions = new BodyProportions(Number(pr, "leftLeg", 1f / MaxProportion, MaxProportion), Number(pr, "rightLeg", 1f / MaxProportion, MaxProportion),
                Number(pr, "leftArm", 1f / MaxProportion, MaxProportion), Number(pr, "rightArm", 1f / MaxProportion, MaxProportion));
            JsonNode m = root["measurements"];
            if (m == null) return;
            if (m.Kind != JsonKind.Object) throw m.Error("'measurements' must be an object.");
            var measurements = new BodyMeasurements();
            double windows = m.GetNumber("windows");
            if (!(windows >= 1 && windows <= 2) || windows != Math.Floor(windows)) throw m["windows"].Error("'measurements.windows' must be 1 or 2.");
            measurements.Windows = (int)windows;
            foreach (var (name, _) in measurements.All())
            {
                double[] v = m.GetNumbers(name, 2);
                if (!(v[0] >= 0 && v[0] <= MaxHeight) || !(v[1] >= 0 && v[1] <= MaxHeight))
                    throw m[name].Error($"'measurements.{name}' must be [value, uncertainty], each from 0 to {MaxHeight.ToString(CultureInfo.InvariantCulture)} m.");
                measurements.Set(name, new Measurement((float)v[0], (float)v[1]));
            }
            p.Measurements = measurements;
        }

        private static string RoleKey(DeviceRole role)
        {
            switch (role)
            {
                case DeviceRole.Head: return "head";
                case DeviceRole.LeftHand: return "leftHand";
                case DeviceRole.RightHand: return "rightHand";
                case DeviceRole.Pelvis: return "pelvis";
                case DeviceRole.LeftFoot: return "leftFoot";
                default: return "rightFoot";
            }
        }

        private static void WritePose(JsonWriter w, RigidPose p)
        {
            w.BeginObject();
            w.Name("position").Values(p.Position.X, p.Position.Y, p.Position.Z);
            w.Name("rotation").Values(p.Rotation.X, p.Rotation.Y, p.Rotation.Z, p.Rotation.W);
            w.EndObject();
        }

        private static RigidPose ReadPose(JsonNode parent, string name, string prefix = "")
        {
            JsonNode node = parent[name];
            if (node == null || node.Kind != JsonKind.Object) throw (node ?? parent).Error($"'{prefix}{name}' must be an object with position and rotation.");
            Vector3 position = ReadPosition(node, "position", prefix + name + ".");
            double[] q = node.GetNumbers("rotation", 4);
            var rotation = new Quaternion((float)q[0], (float)q[1], (float)q[2], (float)q[3]);
            if (!Rotations.IsUnit(rotation)) throw node["rotation"].Error($"'{prefix}{name}.rotation' is not a unit quaternion (length within 1e-3 of 1).");
            return new RigidPose(position, Quaternion.Normalize(rotation));
        }

        private static Vector3 ReadPosition(JsonNode node, string name, string prefix = "")
        {
            double[] v = node.GetNumbers(name, 3);
            foreach (double x in v)
                if (!(Math.Abs((float)x) <= MaxPosition)) throw node[name].Error($"'{prefix}{name}' has a coordinate of {x.ToString("R", CultureInfo.InvariantCulture)}; positions are within ±{MaxPosition.ToString(CultureInfo.InvariantCulture)} m.");
            return new Vector3((float)v[0], (float)v[1], (float)v[2]);
        }

        private static float Number(JsonNode node, string name, float min, float max)
        {
            double v = node.GetNumber(name);
            float f = (float)v; // compared as stored, so that every float in range round-trips
            if (!(f >= min && f <= max))
                throw node[name].Error($"'{name}' is {v.ToString("R", CultureInfo.InvariantCulture)}; it must be from {min.ToString(CultureInfo.InvariantCulture)} to {max.ToString(CultureInfo.InvariantCulture)}.");
            return (float)v;
        }
    }
}
