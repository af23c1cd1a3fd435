using System;
using System.IO;
using System.Linq;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Controller profiles are range-checked where they are read (points, radii, half extents, angles, shape count,
    /// text length), so that a profile that parses gives a finite surface everywhere; errors read <c>FILE:LINE: problem</c>.
    /// </summary>
    public class ControllerProfileRangeTests
    {
        private static string Wand() => File.ReadAllText(TestData.InPackage("Runtime/ControllerProfiles/vive-wand.json"));

        private static int LineOf(string json, string text)
        {
            string[] lines = json.Split('\n');
            for (int i = 0; i < lines.Length; i++) if (lines[i].Contains(text)) return i + 1;
            throw new InvalidOperationException(text);
        }

        private static void AssertRefused(string json, string lineText, string contains)
        {
            var e = Assert.Throws<FormatException>(() => ControllerProfile.Parse(json, "wand.json"));
            StringAssert.StartsWith($"wand.json:{LineOf(json, lineText)}: ", e.Message);
            StringAssert.Contains(contains, e.Message);
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1));
        }

        [TestCase("1e39")]
        [TestCase("-1")]
        [TestCase("1.5")]
        public void RadiiOutsideZeroToOneMetreAreRefused(string radius)
        {
            string json = Wand().Replace("\"radius\": 0.019", "\"radius\": " + radius);
            AssertRefused(json, "\"radius\": " + radius, "'radius' is");
        }

        [TestCase("1e30")]
        [TestCase("3e38")]
        [TestCase("-2")]
        public void PointsBeyondAMetreAreRefused(string value)
        {
            string json = Wand().Replace("\"trigger\": [0, 0.025, 0.024]", $"\"trigger\": [0, {value}, 0.024]");
            AssertRefused(json, "\"trigger\"", "'trigger' has a coordinate");
            json = Wand().Replace("\"a\": [0, -0.075, -0.004]", $"\"a\": [{value}, -0.075, -0.004]");
            AssertRefused(json, "\"a\": [", "'a' has a coordinate");
        }

        /// <summary>
        /// A profile whose origin lies outside its shapes (a CAD export with the origin at the handle's end) is refused, as is a
        /// rounded box whose rounding exceeds its smallest half extent (it would be a sphere): found in review, both parsed,
        /// and the first left the hand open for good (its palm never reached the surface).
        /// </summary>
        [Test]
        public void AnOriginOutsideTheShapesAndAnOverRoundedBoxAreRefused()
        {
            string wand = Wand();
            string moved = wand.Replace("\"a\": [0, -0.075, -0.004]", "\"a\": [0.2, -0.075, -0.004]").Replace("\"b\": [0, 0.035, 0.004]", "\"b\": [0.2, 0.035, 0.004]")
                .Replace("\"centre\": [0, 0.06, 0.0]", "\"centre\": [0.2, 0.06, 0.0]");
            Assume.That(moved, Is.Not.EqualTo(wand));
            AssertRefused(moved, "\"shapes\"", "origin must lie inside its shapes");
            AssertRefused(wand.Replace("\"radius\": 0.012", "\"radius\": 0.05"), "\"radius\": 0.05", "larger than the box's smallest half extent");
        }

        [Test]
        public void BoxesNeedSmallPositiveHalfExtentsAndAnglesWithinAFullTurn()
        {
            string box = "{ \"type\": \"box\", \"centre\": [0, 0, 0], \"halfExtents\": [0.01, 0.01, 0.01], \"eulerDegrees\": [0, 0, 0] },";
            string Json(string b) => Wand().Replace("\"shapes\": [", "\"shapes\": [\n    " + b);
            Assert.That(ControllerProfile.Parse(Json(box)).Shape.Shapes.Count, Is.EqualTo(3));
            AssertRefused(Json(box.Replace("[0.01, 0.01, 0.01]", "[-0.01, 0.01, 0.01]")), "\"box\"", "'halfExtents' has a coordinate of -0.01");
            AssertRefused(Json(box.Replace("[0.01, 0.01, 0.01]", "[1e39, 0.01, 0.01]")), "\"box\"", "'halfExtents' has a coordinate");
            AssertRefused(Json(box.Replace("\"eulerDegrees\": [0, 0, 0]", "\"eulerDegrees\": [1e30, 0, 0]")), "\"box\"", "angles are within ±360°");
        }

        [Test]
        public void AProfileHasAtMost64Shapes()
        {
            string sphere = "{ \"type\": \"sphere\", \"centre\": [0, 0, 0], \"radius\": 0.01 },";
            string json = Wand().Replace("\"shapes\": [", "\"shapes\": [" + string.Concat(Enumerable.Repeat(sphere, 65)));
            AssertRefused(json, "\"shapes\"", "67 shapes; a profile has at most 64");
        }

        [Test]
        public void AShapeTypeWithANewlineIsQuotedOnOneLine()
        {
            string json = Wand().Replace("\"type\": \"capsule\"", "\"type\": \"cap\\nsule\"");
            AssertRefused(json, "cap\\nsule", "Unknown shape type 'cap\\nsule'");
        }

        [Test]
        public void EveryBundledProfileLoadsAndGivesAFiniteSurface()
        {
            foreach (string file in Directory.GetFiles(Path.GetDirectoryName(TestData.InPackage("Runtime/ControllerProfiles/vive-wand.json")), "*.json"))
            {
                ControllerProfile p = ControllerProfile.Load(file);
                float d = p.Shape.Evaluate(p.Trigger, out Vector3 gradient);
                Assert.That(Vectors.IsFinite(d) && Vectors.IsFinite(gradient), Is.True, file);
            }
        }

        [Test]
        public void AHugeProfileIsRefusedBeforeItIsParsed()
        {
            var e = Assert.Throws<FormatException>(() => ControllerProfile.Parse(Wand() + new string(' ', ControllerProfile.MaxFileLength), "big.json"));
            StringAssert.StartsWith("big.json:1: ", e.Message);
        }
    }
}
