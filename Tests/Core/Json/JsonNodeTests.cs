using System;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    public class JsonNodeTests
    {
        [Test]
        public void ParsesEveryKindOfValue()
        {
            JsonNode n = JsonNode.Parse(" {\"a\": [1, -2.5e2, 0, 0.125, 1E-3], \"s\": \"x\\\"\\\\\\/\\b\\f\\n\\r\\t\\u00e9\\uD83D\\uDE00\", \"t\": true, \"f\": false, \"n\": null, \"o\": {}} \n");
            Assert.That(n.Kind, Is.EqualTo(JsonKind.Object));
            Assert.That(n.Keys, Is.EqualTo(new[] { "a", "s", "t", "f", "n", "o" }), "members in document order");
            Assert.That(n["a"].Items.Count, Is.EqualTo(5));
            Assert.That(n["a"].Items[1].Number, Is.EqualTo(-250.0));
            Assert.That(n["a"].Items[4].Number, Is.EqualTo(0.001));
            Assert.That(n.GetString("s"), Is.EqualTo("x\"\\/\b\f\n\r\t\u00e9\U0001F600"), "escapes, surrogate pair included");
            Assert.That(n["t"].Bool, Is.True);
            Assert.That(n["f"].Bool, Is.False);
            Assert.That(n["n"].Kind, Is.EqualTo(JsonKind.Null));
            Assert.That(n["o"].Keys.Count, Is.EqualTo(0));
            Assert.That(n["missing"], Is.Null);
        }

        [Test]
        public void WriterOutputParsesBackToTheSameValues()
        {
            var w = new JsonWriter();
            w.BeginObject()
                .Name("name").Value("quote \" backslash \\ newline \n tab \t bell \u0007")
                .Name("pi").Value(Math.PI)
                .Name("third").Value(1f / 3f)
                .Name("tiny").Value(1e-300)
                .Name("flag").Value(true)
                .Name("id").Value(16777217)
                .Name("max").Value(int.MaxValue)
                .Name("nothing").Null()
                .Name("v").Values(0.1f, -2f, 3.5e-7f)
                .Name("list").BeginArray().Value(1.0).BeginObject().EndObject().BeginArray().EndArray().EndArray()
                .EndObject();
            JsonNode n = JsonNode.Parse(w.ToString());
            Assert.That(n.GetString("name"), Is.EqualTo("quote \" backslash \\ newline \n tab \t bell \u0007"));
            Assert.That(n.GetNumber("pi"), Is.EqualTo(Math.PI), "round-trip precision, bit for bit");
            Assert.That((float)n.GetNumber("third"), Is.EqualTo(1f / 3f));
            Assert.That(n.GetNumber("tiny"), Is.EqualTo(1e-300));
            Assert.That(n["flag"].Bool, Is.True);
            Assert.That(n.GetNumber("id"), Is.EqualTo(16777217), "an int exactly (through a float it became 16777216)");
            Assert.That(n.GetNumber("max"), Is.EqualTo(int.MaxValue));
            Assert.That(n["nothing"].Kind, Is.EqualTo(JsonKind.Null));
            Assert.That(n.GetVector3("v").Z, Is.EqualTo(3.5e-7f));
            Assert.That(n["list"].Items.Count, Is.EqualTo(3));
        }

        [Test]
        public void WriterRefusesNumbersJsonCannotHold()
        {
            Assert.Throws<ArgumentOutOfRangeException>(() => new JsonWriter().Value(double.NaN));
            Assert.Throws<ArgumentOutOfRangeException>(() => new JsonWriter().Value(float.PositiveInfinity));
            Assert.Throws<ArgumentOutOfRangeException>(() => new JsonWriter().Values(1f, float.NaN));
        }

        // Each malformed text, and where (line, column, 1-based) the parser must say the problem is.
        [TestCase("", 1, 1)]
        [TestCase("{", 1, 2)]
        [TestCase("{\"a\": 1,}", 1, 9)]
        [TestCase("[1, 2,]", 1, 7)]
        [TestCase("{\n  \"a\": 1\n  \"b\": 2\n}", 3, 3)]
        [TestCase("{\"a\" 1}", 1, 6)]
        [TestCase("{'a': 1}", 1, 2)]
        [TestCase("{\"a\": 1, \"a\": 2}", 1, 13)]
        [TestCase("[01]", 1, 2)]
        [TestCase("[1.]", 1, 2)]
        [TestCase("[.5]", 1, 2)]
        [TestCase("[+1]", 1, 2)]
        [TestCase("[-]", 1, 2)]
        [TestCase("[1e]", 1, 2)]
        [TestCase("[1e999]", 1, 2)]
        [TestCase("[NaN]", 1, 2)]
        [TestCase("[tru]", 1, 2)]
        [TestCase("[\"a\nb\"]", 1, 4)]
        [TestCase("[\"\\x\"]", 1, 3)]
        [TestCase("[\"\\u12G4\"]", 1, 5)]
        [TestCase("[\"\\u 123\"]", 1, 5)]
        [TestCase("[\"abc", 1, 6)]
        [TestCase("[1] [2]", 1, 5)]
        [TestCase("// comment\n[1]", 1, 1)]
        [TestCase("[1]\n\n  x", 3, 3)]
        public void MalformedTextThrowsFormatExceptionWithLineAndColumn(string text, int line, int column)
        {
            var e = Assert.Throws<FormatException>(() => JsonNode.Parse(text));
            Assert.That(e.Message, Does.StartWith($"JSON line {line}, column {column}:"), e.Message);
        }

        [Test]
        public void DeepNestingIsRefusedNotAStackOverflow()
        {
            string deep = new string('[', 100000) + new string(']', 100000);
            var e = Assert.Throws<FormatException>(() => JsonNode.Parse(deep));
            Assert.That(e.Message, Does.Contain("nested too deeply"));
            string ok = new string('[', 60) + new string(']', 60);
            Assert.That(JsonNode.Parse(ok).Kind, Is.EqualTo(JsonKind.Array));
        }

        [Test]
        public void TypedGettersExplainWhatIsWrong()
        {
            JsonNode n = JsonNode.Parse("{\"a\": \"1\", \"v\": [1, 2], \"w\": [1, 2, \"3\"]}");
            Assert.That(Assert.Throws<FormatException>(() => n.GetNumber("a")).Message, Does.Contain("'a' must be a number"));
            Assert.That(Assert.Throws<FormatException>(() => n.GetString("b")).Message, Does.Contain("'b' must be a string"));
            Assert.Throws<FormatException>(() => n.GetVector3("v"));
            Assert.Throws<FormatException>(() => n.GetVector3("w"));
        }
    }
}
