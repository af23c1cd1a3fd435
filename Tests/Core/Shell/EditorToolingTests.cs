using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The Editor tooling's decisions, taken engine-free: the calibrator inspector's tracking-setup findings
    /// (<see cref="TrackingSetupCheck"/>) and the Import Session or BVH menu's plan (<see cref="RecordingImport"/>).
    /// </summary>
    public class EditorToolingTests
    {
        private const string SmallBvh =
            "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" +
            "\tJOINT Spine\n\t{\n\t\tOFFSET 0 10 0\n\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n" +
            "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 10 0\n\t\t}\n\t}\n}\nMOTION\nFrames: 2\nFrame Time: 0.0333333\n" +
            "0 90 0 0 0 0 0 0 0\n0 90 1 0 0 0 5 0 0\n";

        private static string _session;

        private static string Session => _session ??= Sessions.Simulate("mocapbank_30fps.bvh");

        [Test]
        public void NoSourceIsAnErrorWithoutAFix()
        {
            IReadOnlyList<SetupFinding> findings = TrackingSetupCheck.Check(new TrackingSetupFacts { HasSource = false, SceneHasXROrigin = true });
            Assert.That(findings.Count, Is.EqualTo(1));
            Assert.That(findings[0].Severity, Is.EqualTo(SetupSeverity.Error));
            Assert.That(findings[0].Fix, Is.EqualTo(SetupFix.None));
            Assert.That(findings[0].Message, Is.EqualTo(TrackingSetupCheck.NoSource));
        }

        [Test]
        public void AnEmptyOriginWithAnXROriginInTheSceneIsAWarningTheButtonConnects()
        {
            var facts = new TrackingSetupFacts { HasSource = true, SceneHasXROrigin = true };
            SetupFinding finding = TrackingSetupCheck.Check(facts).Single();
            Assert.That(finding.Severity, Is.EqualTo(SetupSeverity.Warning));
            Assert.That(finding.Fix, Is.EqualTo(SetupFix.ConnectXROrigin));

            facts.HasXROriginTrackingSetup = true;
            finding = TrackingSetupCheck.Check(facts).Single();
            Assert.That(finding.Severity, Is.EqualTo(SetupSeverity.Info), "the setup component fills it on Start");
            Assert.That(finding.Fix, Is.EqualTo(SetupFix.None));
            Assert.That(finding.Message, Is.EqualTo(TrackingSetupCheck.OriginSetOnStart));
        }

        [Test]
        public void WithoutAnXROriginAnEmptyOriginMeansWorldSpaceAndASetOriginIsFine()
        {
            SetupFinding finding = TrackingSetupCheck.Check(new TrackingSetupFacts { HasSource = true }).Single();
            Assert.That(finding.Severity, Is.EqualTo(SetupSeverity.Info));
            Assert.That(finding.Message, Is.EqualTo(TrackingSetupCheck.WorldSpace));
            Assert.That(TrackingSetupCheck.Check(new TrackingSetupFacts { HasSource = true, HasTrackingSpaceOrigin = true, SceneHasXROrigin = true }), Is.Empty);
            Assert.That(TrackingSetupCheck.Check(new TrackingSetupFacts { HasSource = true, HasTrackingSpaceOrigin = true }), Is.Empty);
        }

        [Test]
        public void WithoutAHeadBoneTheInspectorShowsNoHeightWarning()
        {
            // The inspector cannot measure a height without the head (it leaves HeadAboveFeet unset): only the missing bone is reported.
            var facts = new AvatarFacts { HasAnimator = true, HasAvatar = true, AvatarIsValid = true, AvatarIsHuman = true, HeadAboveFeet = float.NaN };
            foreach (HumanoidBone bone in HumanoidBones.Required)
                if (bone != HumanoidBone.Head) facts.Bones.Add(bone);
            IReadOnlyList<SetupFinding> findings = AvatarSetupCheck.Check(facts);
            Assert.That(findings.Any(f => f.Message.Contains("above its feet")), Is.False, string.Join("\n", findings));
            Assert.That(findings.Single(f => f.Severity == SetupSeverity.Error).Message, Does.Contain("Head"));
        }

        [TestCase("walk.agsession", RecordingFileKind.Session, "walk.agsession.txt")]
        [TestCase("walk.AGSESSION.txt", RecordingFileKind.Session, "walk.agsession.txt")]
        [TestCase("Take 01.bvh", RecordingFileKind.Bvh, "Take 01.bvh.txt")]
        [TestCase("clip.bvh.txt", RecordingFileKind.Bvh, "clip.bvh.txt")]
        [TestCase("a:b*c.bvh", RecordingFileKind.Bvh, "a_b_c.bvh.txt")]
        [TestCase(".bvh", RecordingFileKind.Bvh, "clip.bvh.txt")]
        [TestCase("motion", RecordingFileKind.Session, "motion.agsession.txt")]
        public void TheTextAssetIsNamedFromTheStemAndTheKind(string fileName, RecordingFileKind kind, string expected)
        {
            Assert.That(RecordingImport.TargetFileName(fileName, kind), Is.EqualTo(expected));
        }

        [Test]
        public void AValidBvhIsPlannedAsABvhTextAsset()
        {
            RecordingImportPlan plan = RecordingImport.Plan("dance.bvh", new StringReader(SmallBvh));
            Assert.That(plan.Error, Is.Null);
            Assert.That(plan.IsValid, Is.True);
            Assert.That(plan.Kind, Is.EqualTo(RecordingFileKind.Bvh));
            Assert.That(plan.TargetFileName, Is.EqualTo("dance.bvh.txt"));
            Assert.That(plan.Summary, Does.Contain("2 frames"));
        }

        [Test]
        public void AValidSessionIsReadToItsEndAndPlannedAsASessionTextAsset()
        {
            RecordingImportPlan plan = RecordingImport.Plan("walk-in.agsession", new StringReader(Session));
            Assert.That(plan.Error, Is.Null);
            Assert.That(plan.IsValid, Is.True);
            Assert.That(plan.Kind, Is.EqualTo(RecordingFileKind.Session));
            Assert.That(plan.TargetFileName, Is.EqualTo("walk-in.agsession.txt"));
            using (SessionReader reader = Sessions.Read(Session))
            {
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame)) { }
                Assert.That(plan.Summary, Does.Contain(reader.FrameCount + " frames"));
                Assert.That(plan.Summary, Does.Contain(reader.Header.Devices.Count + " devices"));
            }
        }

        [Test]
        public void WithoutAKnownExtensionTheFirstWordDecides()
        {
            Assert.That(RecordingImport.Plan("export", new StringReader(SmallBvh)).Kind, Is.EqualTo(RecordingFileKind.Bvh));
            Assert.That(RecordingImport.Plan("export", new StringReader(SmallBvh)).TargetFileName, Is.EqualTo("export.bvh.txt"));
            Assert.That(RecordingImport.Plan("export.txt", new StringReader(Session)).TargetFileName, Is.EqualTo("export.agsession.txt"));
            RecordingImportPlan neither = RecordingImport.Plan("notes.txt", new StringReader("hello\n"));
            Assert.That(neither.IsValid, Is.False);
            Assert.That(neither.TargetFileName, Is.Null);
            Assert.That(neither.Error, Does.StartWith("notes.txt: not a recorded session"));
        }

        [Test]
        public void AFormatErrorIsNotImportedAndItsMessageNamesTheFileAndTheLine()
        {
            string broken = SmallBvh.Replace("0 90 1 0 0 0 5 0 0", "0 90 1 0 zero 0 5 0 0");
            RecordingImportPlan plan = RecordingImport.Plan("broken.bvh", new StringReader(broken));
            Assert.That(plan.IsValid, Is.False);
            Assert.That(plan.TargetFileName, Is.Null);
            Assert.That(plan.Error, Does.StartWith("broken.bvh:20:"), plan.Error);

            string[] lines = Session.Split('\n');
            string truncated = string.Join("\n", lines.Take(lines.Length / 2)) + "\n";
            plan = RecordingImport.Plan("cut.agsession", new StringReader(truncated));
            Assert.That(plan.IsValid, Is.False);
            Assert.That(plan.Error, Does.StartWith("cut.agsession:"), plan.Error);
            Assert.That(plan.Error, Does.Contain("truncated"), plan.Error);
        }

        [Test]
        public void AFileThatCannotBeReadIsNotImportedAndSaysWhy()
        {
            string missing = Path.Combine(Path.GetTempPath(), "avatargo-missing-" + System.Guid.NewGuid().ToString("N") + ".bvh");
            RecordingImportPlan plan = RecordingImport.PlanFile(missing);
            Assert.That(plan.IsValid, Is.False);
            Assert.That(plan.Kind, Is.EqualTo(RecordingFileKind.Bvh));
            Assert.That(plan.Error, Does.Contain("cannot be read"));
        }

        [Test]
        public void TheAssetPathNeverOverwritesAnother()
        {
            var taken = new HashSet<string> { "Assets/AvatarGo/Recordings/walk.agsession.txt", "Assets/AvatarGo/Recordings/walk 1.agsession.txt" };
            Assert.That(RecordingImport.UniqueAssetPath(RecordingImport.DefaultFolder, "run.agsession.txt", taken.Contains), Is.EqualTo("Assets/AvatarGo/Recordings/run.agsession.txt"));
            Assert.That(RecordingImport.UniqueAssetPath(RecordingImport.DefaultFolder + "/", "walk.agsession.txt", taken.Contains), Is.EqualTo("Assets/AvatarGo/Recordings/walk 2.agsession.txt"));
            taken.Add("Assets/x.bvh.txt");
            Assert.That(RecordingImport.UniqueAssetPath("Assets", "x.bvh.txt", taken.Contains), Is.EqualTo("Assets/x 1.bvh.txt"));
        }
    }
}
