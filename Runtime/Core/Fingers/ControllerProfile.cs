using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A controller's grip as data: its shape as signed-distance primitives and the points the hand cares about,
    /// in the controller's frame (x right, y up along the handle, z forward toward the trigger; origin on the
    /// handle axis where the palm centre holds it). Parsed from JSON (<see cref="Parse(string, string)"/>): adding a controller
    /// needs a file, not code. See Documentation~/fingers.md for the bundled profiles and their measurements.
    /// </summary>
    /// <remarks>
    /// Parsing checks every number where it is read, so that a profile that parses gives a finite surface everywhere:
    /// points (shape ends and centres, trigger, thumb rest) within ±<see cref="MaxCoordinate"/> of the origin, radii and
    /// half extents from 0 to <see cref="MaxCoordinate"/>, Euler angles within ±360°, 1 to <see cref="MaxShapes"/> shapes,
    /// and the text at most <see cref="MaxFileLength"/> characters.
    /// </remarks>
    public sealed class ControllerProfile
    {
        /// <summary>The <c>format</c> member every profile file carries.</summary>
        public const string FormatName = "avatargo-controller-profile";

        /// <summary>The longest profile text read, in characters (64 KiB; the bundled profiles are under 1 KB).</summary>
        public const int MaxFileLength = 64 << 10;

        /// <summary>The most shapes a profile may have (the bundled ones have two; each costs time in every finger solve).</summary>
        public const int MaxShapes = 64;

        /// <summary>The largest coordinate, radius or half extent, in metres: a controller is a hand-sized object.</summary>
        public const float MaxCoordinate = 1f;

        private ControllerProfile(string name, string displayName, SdfComposite shape, Vector3 trigger, Vector3 thumbRest)
        {
            Name = name;
            DisplayName = displayName;
            Shape = shape;
            Trigger = trigger;
            ThumbRest = thumbRest;
        }

        /// <summary>
        /// Short identifier, the profile's <c>name</c> member, e.g. <c>vive-wand</c> (the shipped profiles' file names match
        /// it; a profile loaded from another file keeps the name it declares).
        /// </summary>
        public string Name { get; }

        /// <summary>Human-readable name.</summary>
        public string DisplayName { get; }

        /// <summary>The grip surface.</summary>
        public SdfComposite Shape { get; }

        /// <summary>Where the index fingertip rests on the trigger.</summary>
        public Vector3 Trigger { get; }

        /// <summary>Where the thumb tip rests (thumbstick, trackpad or thumb rest).</summary>
        public Vector3 ThumbRest { get; }

        /// <summary>Parses a profile from JSON.</summary>
        /// <exception cref="FormatException">Not a controller profile, or a member is missing, malformed or out of range.</exception>
        public static ControllerProfile Parse(string json) => Parse(json, null);

        /// <summary>
        /// Parses a profile from JSON text read from <paramref name="sourceName"/> (a file name): every error reads
        /// <c>SOURCE:LINE: problem</c>.
        /// </summary>
        /// <exception cref="FormatException">Not a controller profile, or a member is missing, malformed or out of range.</exception>
        public static ControllerProfile Parse(string json, string sourceName)
        {
            if (json == null) throw new ArgumentNullException(nameof(json));
            if (json.Length > MaxFileLength)
                throw new FormatException($"{(sourceName == null ? "" : sourceName + ":1: ")}{json.Length} characters is more than a controller profile holds (at most {MaxFileLength})");
            JsonNode root = JsonNode.Parse(json, sourceName);
            if (root.Kind != JsonKind.Object || root["format"]?.String != FormatName) throw root.Error($"Not a controller profile (no \"format\": \"{FormatName}\").");
            double version = root.GetNumber("version");
            if (version != 1) throw root["version"].Error($"Controller profile version {version.ToString(CultureInfo.InvariantCulture)} is not supported (this package reads version 1).");
            JsonNode shapes = root["shapes"];
            if (shapes == null || shapes.Kind != JsonKind.Array || shapes.Items.Count == 0) throw (shapes ?? root).Error("'shapes' must be a non-empty array.");
            if (shapes.Items.Count > MaxShapes) throw shapes.Error($"{shapes.Items.Count} shapes; a profile has at most {MaxShapes}.");
            var list = new List<SdfShape>();
            foreach (JsonNode s in shapes.Items)
            {
                if (s.Kind != JsonKind.Object) throw s.Error("each shape must be an object with a 'type'.");
                string type = s.GetString("type");
                switch (type)
                {
                    case "capsule": list.Add(SdfShape.Capsule(Point(s, "a"), Point(s, "b"), Length(s, "radius"))); break;
                    case "sphere": list.Add(SdfShape.Sphere(Point(s, "centre"), Length(s, "radius"))); break;
                    case "box": list.Add(SdfShape.Box(Point(s, "centre"), HalfExtents(s), Rotation(s))); break;
                    case "roundedBox":
                        Vector3 half = HalfExtents(s);
                        float rounding = Length(s, "radius");
                        // The outer half extents are the box's: a rounding larger than the smallest would make it a sphere.
                        if (rounding > Math.Min(half.X, Math.Min(half.Y, half.Z)))
                            throw s["radius"].Error($"the rounding radius ({rounding.ToString(CultureInfo.InvariantCulture)} m) is larger than the box's smallest half extent ({Math.Min(half.X, Math.Min(half.Y, half.Z)).ToString(CultureInfo.InvariantCulture)} m).");
                        list.Add(SdfShape.RoundedBox(Point(s, "centre"), half, rounding, Rotation(s)));
                        break;
                    default: throw s["type"].Error($"Unknown shape type '{JsonNode.Printable(type)}' (capsule, sphere, box, roundedBox).");
                }
            }
            var shape = new SdfComposite(list);
            // The grip is built around the origin (the handle's axis): it must lie inside the controller, as a CAD export
            // with its origin at the handle's end does not (the hand then never reaches the surface and stays open).
            float origin = shape.Distance(Vector3.Zero);
            if (!(origin < 0f))
                throw shapes.Error($"the profile's origin must lie inside its shapes, on the handle's axis; it is {origin.ToString("0.000", CultureInfo.InvariantCulture)} m outside them.");
            return new ControllerProfile(root.GetString("name"), root.GetString("displayName"), shape, Point(root, "trigger"), Point(root, "thumbRest"));
        }

        /// <summary>Reads and parses a profile file; errors read <c>FILE:LINE: problem</c>.</summary>
        /// <exception cref="FormatException">The file is not a valid controller profile.</exception>
        /// <exception cref="IOException">The file cannot be read, or the path is a folder.</exception>
        /// <exception cref="UnauthorizedAccessException">The file may not be read (its permissions).</exception>
        public static ControllerProfile Load(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            InputFiles.ThrowIfFolder(path);
            string name = Path.GetFileName(path);
            long length = new FileInfo(path).Length;
            if (length > MaxFileLength * 4L) throw new FormatException($"{name}:1: {length} bytes is more than a controller profile holds (at most {MaxFileLength} characters)");
            return Parse(File.ReadAllText(path), name);
        }

        private static Vector3 Point(JsonNode n, string name) => Bounded(n, name, -MaxCoordinate, "within ±1 m of the controller's origin");

        private static Vector3 HalfExtents(JsonNode n) => Bounded(n, "halfExtents", 0f, "from 0 to 1 m");

        private static Vector3 Bounded(JsonNode n, string name, float min, string range)
        {
            double[] v = n.GetNumbers(name, 3);
            foreach (double x in v)
                if (!(x >= min && x <= MaxCoordinate)) throw n[name].Error($"'{name}' has a coordinate of {x.ToString("R", CultureInfo.InvariantCulture)}; it must be {range}.");
            return new Vector3((float)v[0], (float)v[1], (float)v[2]);
        }

        private static float Length(JsonNode n, string name)
        {
            double v = n.GetNumber(name);
            if (!(v >= 0) || v > MaxCoordinate) throw n[name].Error($"'{name}' is {v.ToString("R", CultureInfo.InvariantCulture)}; it must be from 0 to 1 m.");
            return (float)v;
        }

        private static Quaternion Rotation(JsonNode n)
        {
            if (n["eulerDegrees"] == null) return Quaternion.Identity;
            double[] d = n.GetNumbers("eulerDegrees", 3);
            foreach (double x in d)
                if (!(Math.Abs(x) <= 360)) throw n["eulerDegrees"].Error($"'eulerDegrees' has an angle of {x.ToString("R", CultureInfo.InvariantCulture)}; angles are within ±360°.");
            var e = new Vector3((float)d[0], (float)d[1], (float)d[2]);
            // Unity's order: Z, then X, then Y.
            return Rotations.AngleAxis(e.Y, Vector3.UnitY) * Rotations.AngleAxis(e.X, Vector3.UnitX) * Rotations.AngleAxis(e.Z, Vector3.UnitZ);
        }
    }
}
