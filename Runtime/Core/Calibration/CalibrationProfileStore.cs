using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Saves and loads <see cref="CalibrationProfile"/>s as versioned JSON. Saving is atomic: the text goes to a
    /// temporary file beside the target, is flushed to disk, then replaces the target in one rename, so a crash
    /// mid-save leaves either the old profile or the new one, never a torn file.
    /// </summary>
    public static class CalibrationProfileStore
    {
        /// <summary>The <c>format</c> member every profile file carries.</summary>
        public const string FormatName = "avatargo-calibration-profile";

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
        /// <exception cref="FormatException">Not a profile, an unknown version, or a missing or malformed member.</exception>
        public static CalibrationProfile FromJson(string json)
        {
            JsonNode root = JsonNode.Parse(json);
            if (root.Kind != JsonKind.Object || root["format"]?.String != FormatName) throw new FormatException($"Not an AvatarGo calibration profile (no \"format\": \"{FormatName}\").");
            double version = root.GetNumber("version");
            if (version != CalibrationProfile.Version) throw new FormatException($"Calibration profile version {version} is not supported (this package reads version {CalibrationProfile.Version}).");
            var p = new CalibrationProfile
            {
                AvatarScale = Positive(root.GetNumber("avatarScale"), "avatarScale"),
                WearerEyeHeight = (float)root.GetNumber("wearerEyeHeight"),
                AvatarEyeHeight = (float)root.GetNumber("avatarEyeHeight"),
                FloorHeight = (float)root.GetNumber("floorHeight"),
                Placement = ReadPose(root["placement"], "placement"),
                RootToHead = ReadVector(root, "rootToHead"),
            };
            string mode = root.GetString("mode");
            if (mode != "exact" && mode != "fixed") throw new FormatException($"'mode' must be exact or fixed, not '{mode}'.");
            JsonNode roles = root["roles"];
            if (roles == null || roles.Kind != JsonKind.Object) throw new FormatException("'roles' must be an object.");
            foreach (DeviceRole role in BodyRoles.All)
            {
                JsonNode r = roles[RoleKey(role)] ?? throw new FormatException($"'roles' has no '{RoleKey(role)}'.");
                double id = r.GetNumber("deviceId");
                if (id < 0 || id != Math.Floor(id)) throw new FormatException($"{RoleKey(role)}.deviceId must be a non-negative integer.");
                p.SetDevice(role, new DeviceInfo((int)id, DeviceClass.Tracker, r.GetString("serial")));
                p.SetOffsets(role, ReadPose(r["deviceAtCalibration"], RoleKey(role) + ".deviceAtCalibration"), ReadPose(r["jointAtCalibration"], RoleKey(role) + ".jointAtCalibration"));
            }
            return mode == "fixed" ? p.WithFixedOffsets() : p;
        }

        /// <summary>Saves atomically (see the class remarks), creating the folder if needed.</summary>
        public static void Save(CalibrationProfile profile, string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            string full = Path.GetFullPath(path);
            string dir = Path.GetDirectoryName(full);
            Directory.CreateDirectory(dir);
            string temp = Path.Combine(dir, "." + Path.GetFileName(full) + "." + Guid.NewGuid().ToString("N") + ".tmp");
            try
            {
                byte[] bytes = new UTF8Encoding(false).GetBytes(ToJson(profile));
                using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
                {
                    stream.Write(bytes, 0, bytes.Length);
                    stream.Flush(true);
                }
                if (File.Exists(full)) File.Replace(temp, full, null);
                else File.Move(temp, full);
            }
            finally
            {
                if (File.Exists(temp)) File.Delete(temp);
            }
        }

        /// <summary>Loads a profile saved by <see cref="Save"/>.</summary>
        /// <exception cref="FormatException">The file is not a valid profile; the message names the problem.</exception>
        public static CalibrationProfile Load(string path)
        {
            string text = File.ReadAllText(path);
            try
            {
                return FromJson(text);
            }
            catch (FormatException e)
            {
                throw new FormatException($"{Path.GetFileName(path)}: {e.Message}", e);
            }
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

        private static RigidPose ReadPose(JsonNode node, string what)
        {
            if (node == null || node.Kind != JsonKind.Object) throw new FormatException($"'{what}' must be an object with position and rotation.");
            Vector3 position = ReadVector(node, "position");
            double[] q = node.GetNumbers("rotation", 4);
            var rotation = new Quaternion((float)q[0], (float)q[1], (float)q[2], (float)q[3]);
            var pose = new RigidPose(position, rotation);
            if (!pose.IsValid) throw new FormatException($"'{what}' is not a valid pose (finite position, unit quaternion).");
            return new RigidPose(position, Quaternion.Normalize(rotation));
        }

        private static Vector3 ReadVector(JsonNode node, string name) => node.GetVector3(name);

        private static float Positive(double v, string name)
        {
            if (!(v > 0) || double.IsInfinity(v)) throw new FormatException($"'{name}' must be positive.");
            return (float)v;
        }
    }
}
