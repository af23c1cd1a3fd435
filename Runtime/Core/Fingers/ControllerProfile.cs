using System;
using System.Collections.Generic;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>
    /// A controller's grip as data: its shape as signed-distance primitives and the points the hand cares about,
    /// in the controller's frame (x right, y up along the handle, z forward toward the trigger; origin on the
    /// handle axis where the palm centre holds it). Parsed from JSON (<see cref="Parse"/>): adding a controller
    /// needs a file, not code. See Documentation~/fingers.md for the bundled profiles and their measurements.
    /// </summary>
    public sealed class ControllerProfile
    {
        /// <summary>The <c>format</c> member every profile file carries.</summary>
        public const string FormatName = "avatargo-controller-profile";

        private ControllerProfile(string name, string displayName, SdfComposite shape, Vector3 trigger, Vector3 thumbRest)
        {
            Name = name;
            DisplayName = displayName;
            Shape = shape;
            Trigger = trigger;
            ThumbRest = thumbRest;
        }

        /// <summary>Short identifier (file name without extension), e.g. <c>vive-wand</c>.</summary>
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
        /// <exception cref="FormatException">Not a controller profile, or a member is missing or malformed.</exception>
        public static ControllerProfile Parse(string json)
        {
            JsonNode root = JsonNode.Parse(json);
            if (root.Kind != JsonKind.Object || root["format"]?.String != FormatName) throw new FormatException($"Not a controller profile (no \"format\": \"{FormatName}\").");
            if (root.GetNumber("version") != 1) throw new FormatException($"Controller profile version {root.GetNumber("version")} is not supported.");
            JsonNode shapes = root["shapes"];
            if (shapes == null || shapes.Kind != JsonKind.Array || shapes.Items.Count == 0) throw new FormatException("'shapes' must be a non-empty array.");
            var list = new List<SdfShape>();
            foreach (JsonNode s in shapes.Items)
            {
                string type = s.GetString("type");
                switch (type)
                {
                    case "capsule": list.Add(SdfShape.Capsule(Vec(s, "a"), Vec(s, "b"), Length(s, "radius"))); break;
                    case "sphere": list.Add(SdfShape.Sphere(Vec(s, "centre"), Length(s, "radius"))); break;
                    case "box": list.Add(SdfShape.Box(Vec(s, "centre"), Vec(s, "halfExtents"), Rotation(s))); break;
                    case "roundedBox": list.Add(SdfShape.RoundedBox(Vec(s, "centre"), Vec(s, "halfExtents"), Length(s, "radius"), Rotation(s))); break;
                    default: throw new FormatException($"Unknown shape type '{type}' (capsule, sphere, box, roundedBox).");
                }
            }
            return new ControllerProfile(root.GetString("name"), root.GetString("displayName"), new SdfComposite(list), Vec(root, "trigger"), Vec(root, "thumbRest"));
        }

        private static Vector3 Vec(JsonNode n, string name) => n.GetVector3(name);

        private static float Length(JsonNode n, string name)
        {
            double v = n.GetNumber(name);
            if (!(v >= 0) || v > 1) throw new FormatException($"'{name}' must be between 0 and 1 m.");
            return (float)v;
        }

        private static Quaternion Rotation(JsonNode n)
        {
            if (n["eulerDegrees"] == null) return Quaternion.Identity;
            Vector3 e = Vec(n, "eulerDegrees");
            // Unity's order: Z, then X, then Y.
            return Rotations.AngleAxis(e.Y, Vector3.UnitY) * Rotations.AngleAxis(e.X, Vector3.UnitX) * Rotations.AngleAxis(e.Z, Vector3.UnitZ);
        }
    }
}
