using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Replays the fuzzing corpus (<c>Tests/Core/Data~/fuzz-corpus</c>): inputs that once failed (`avatargo fuzz` saves
    /// them there, minimised). Each must parse or be refused with the documented one-line <see cref="FormatException"/>,
    /// within a second. The parser is chosen by the file's extension: .bvh, .agsession, .profile.json, .controller.json,
    /// and .json for the JSON reader itself. (`avatargo fuzz` and its tests also run what the package does next with
    /// what parses.)
    /// </summary>
    public class FuzzCorpusTests
    {
        private const string Folder = "Tests/Core/Data~/fuzz-corpus";

        public static IEnumerable<string> CorpusFiles()
        {
            string dir = TestData.PackageRoot == null ? null : Path.Combine(TestData.PackageRoot, Folder);
            if (dir == null || !Directory.Exists(dir)) yield break;
            string[] files = Directory.GetFiles(dir);
            Array.Sort(files, StringComparer.Ordinal);
            foreach (string f in files) yield return Path.GetFileName(f);
        }

        [Test]
        public void TheCorpusShipsWithThePackage()
        {
            Assert.That(new List<string>(CorpusFiles()), Is.Not.Empty, $"{Folder} is missing or empty");
        }

        [TestCaseSource(nameof(CorpusFiles))]
        public void ParsesOrIsRefusedWithAFormatErrorWithinASecond(string file)
        {
            string text = File.ReadAllText(TestData.InPackage(Folder + "/" + file));
            Action parse = Parser(file);
            var clock = Stopwatch.StartNew();
            try
            {
                parse.Invoke();
            }
            catch (FormatException e)
            {
                Assert.That(e.Message.Split('\n').Length, Is.EqualTo(1), "a one-line message: " + e.Message);
            }
            Assert.That(clock.ElapsedMilliseconds, Is.LessThan(1000), file);

            Action Parser(string name)
            {
                if (name.EndsWith(".bvh", StringComparison.Ordinal)) return () => BvhReader.Read(new StringReader(text), name);
                if (name.EndsWith(".agsession", StringComparison.Ordinal)) return () =>
                {
                    using var reader = new SessionReader(new StringReader(text), name);
                    SessionFrame frame = reader.CreateFrame();
                    while (reader.ReadFrame(frame)) { }
                };
                if (name.EndsWith(".profile.json", StringComparison.Ordinal)) return () => CalibrationProfileStore.FromJson(text, name);
                if (name.EndsWith(".controller.json", StringComparison.Ordinal)) return () => ControllerProfile.Parse(text, name);
                if (name.EndsWith(".json", StringComparison.Ordinal)) return () => JsonNode.Parse(text, name);
                Assert.Fail($"{name}: not a corpus file (.bvh, .agsession, .profile.json, .controller.json, .json)");
                return null;
            }
        }
    }
}
