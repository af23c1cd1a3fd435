using System;
using System.IO;
using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// <see cref="BvhWriter"/> refuses, before writing a line, a clip that <see cref="BvhReader"/> would refuse or read
    /// otherwise, so that <see cref="BvhWriter.WriteFile"/> never replaces a good file with one that cannot be read back
    /// (found in review: a frame time of 1e-5 s, a second root or a name with two spaces in a row were written, and read
    /// back refused or renamed).
    /// </summary>
    public class BvhWriterReadabilityTests
    {
        private static BvhClip Clip(string[] names, int[] parents, float frameTime = 1f / 30f, bool[] endSites = null)
        {
            var rest = new RigidPose[names.Length];
            for (int j = 0; j < rest.Length; j++) rest[j] = RigidPose.FromPosition(new Vector3(0f, j == 0 ? 0f : 0.1f, 0f));
            var skeleton = new Skeleton(names, parents, rest, endSites);
            var frame = new RigidPose[names.Length];
            for (int j = 0; j < frame.Length; j++) frame[j] = rest[j];
            return BvhClip.FromPoses(skeleton, new[] { frame, frame }, frameTime);
        }

        [TestCase("too short a frame time")]
        [TestCase("two roots")]
        [TestCase("two spaces in a name")]
        [TestCase("a tab in a name")]
        [TestCase("a joint named like an End Site")]
        public void AClipTheReaderWouldNotReadBackIsRefusedAndTheOldFileKept(string what)
        {
            BvhClip clip = what switch
            {
                "too short a frame time" => Clip(new[] { "Hips", "Spine" }, new[] { -1, 0 }, 1e-5f),
                "two roots" => Clip(new[] { "Hips", "Prop" }, new[] { -1, -1 }),
                "two spaces in a name" => Clip(new[] { "Hips", "Left  Arm" }, new[] { -1, 0 }),
                "a tab in a name" => Clip(new[] { "Hips", "Left\tArm" }, new[] { -1, 0 }),
                _ => Clip(new[] { "Hips", "Tip", "Hips_End" }, new[] { -1, 0, 0 }, endSites: new[] { false, true, false }),
            };
            string path = Path.Combine(Path.GetTempPath(), "avatargo-bvh-" + Guid.NewGuid().ToString("N") + ".bvh");
            try
            {
                BvhClip good = Clip(new[] { "Hips", "Left Arm" }, new[] { -1, 0 });
                BvhWriter.WriteFile(path, good);
                byte[] before = File.ReadAllBytes(path);
                Assert.Throws<ArgumentException>(() => BvhWriter.WriteFile(path, clip), what);
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(before), "the good file is kept");
                // The control: the good clip, a name with one space included, reads back as it was written.
                BvhClip read = BvhReader.ReadFile(path);
                Assert.That(read.Skeleton.GetName(1), Is.EqualTo("Left Arm"));
            }
            finally { File.Delete(path); }
        }
    }
}
