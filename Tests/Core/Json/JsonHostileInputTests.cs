using System;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>The JSON reader under hostile text: one-line errors naming source and line, surrogates, sizes.</summary>
    public class JsonHostileInputTests
    {
        [Test]
        public void ABackslashBeforeANewlineGivesAOneLineError()
        {
            // Found by the fuzzer: the message quoted the escaped character, a raw newline, and so spanned two lines.
            var e = Assert.Throws<FormatException>(() => JsonNode.Parse("{\"a\": \"x\\\ny\"}"));
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), e.Message);
            StringAssert.Contains("U+000A", e.Message);
            e = Assert.Throws<FormatException>(() => JsonNode.Parse("{\"a\\\n\": 1}", "x.json"));
            Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), e.Message);
        }

        [TestCase("[\"\\uD83D\"]")]
        [TestCase("[\"\\uDE00\"]")]
        [TestCase("[\"\\uD83Dx\"]")]
        [TestCase("[\"\\uD83D\\u0041\"]")]
        public void HalfASurrogatePairIsRefused(string text)
        {
            var e = Assert.Throws<FormatException>(() => JsonNode.Parse(text, "s.json"));
            StringAssert.StartsWith("s.json:1: ", e.Message);
            StringAssert.Contains("surrogate", e.Message);
        }

        [Test]
        public void HalfASurrogatePairInTheRawTextIsRefused()
        {
            // Built at run time: an attribute's string cannot hold half a pair (it would arrive as U+FFFD).
            foreach (char half in new[] { (char)0xD83D, (char)0xDE00 })
            {
                var e = Assert.Throws<FormatException>(() => JsonNode.Parse("[\"" + half + "\"]", "s.json"));
                StringAssert.StartsWith("s.json:1: half of a surrogate pair", e.Message);
            }
        }

        [Test]
        public void WholeSurrogatePairsAreKept()
        {
            Assert.That(JsonNode.Parse("[\"\\uD83D\\uDE00\", \"\U0001F600\"]").Items.Select(i => i.String), Is.EqualTo(new[] { "\U0001F600", "\U0001F600" }));
        }

        [Test]
        public void WithASourceNameErrorsAndTypedGettersNameSourceAndLine()
        {
            var e = Assert.Throws<FormatException>(() => JsonNode.Parse("{\n  \"a\": 1,\n  \"b\": tru\n}", "p.json"));
            Assert.That(e.Message, Is.EqualTo("p.json:3: unexpected character 't' (column 8)"));
            JsonNode n = JsonNode.Parse("{\n  \"a\": \"1\",\n  \"v\": [1,\n 2]\n}", "p.json");
            Assert.That(n["a"].Line, Is.EqualTo(2));
            Assert.That(Assert.Throws<FormatException>(() => n.GetNumber("a")).Message, Is.EqualTo("p.json:2: 'a' must be a number."));
            Assert.That(Assert.Throws<FormatException>(() => n.GetVector3("v")).Message, Is.EqualTo("p.json:3: 'v' must be an array of 3 numbers."));
            Assert.That(Assert.Throws<FormatException>(() => n.GetString("missing")).Message, Is.EqualTo("p.json:1: 'missing' must be a string."));
        }

        [Test]
        public void DeepNestingIsRefusedAtTheDepthLimit()
        {
            string deep = string.Concat(Enumerable.Repeat("{\"a\":", 100000)) + "1" + new string('}', 100000);
            StringAssert.Contains("nested too deeply", Assert.Throws<FormatException>(() => JsonNode.Parse(deep)).Message);
            string ok = new string('[', JsonNode.MaxDepth) + new string(']', JsonNode.MaxDepth);
            Assert.That(JsonNode.Parse(ok).Kind, Is.EqualTo(JsonKind.Array));
        }

        [Test]
        public void LargeDocumentsParseInLinearTime()
        {
            Scaling.AssertLinear(n => "{" + string.Join(",", Enumerable.Range(0, n).Select(i => $"\n\"k{i}\": [{i}, \"s{i}\"]")) + "}",
                text => JsonNode.Parse(text, "big.json"), 5000, "parsing members"); // 20,000 members: half a megabyte, a profile's limit
        }
    }
}
