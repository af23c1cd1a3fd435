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

        /// <summary>
        /// The channels a reader refuses, and End Sites a BVH file cannot hold, are refused too (a second review: each of
        /// these was written over a good file, which then read back refused; an End Site's channels were dropped silently).
        /// </summary>
        [TestCase("a channel listed twice"), TestCase("seven channels"), TestCase("an End Site with a child"),
         TestCase("an End Site as the root"), TestCase("an End Site with a channel")]
        public void ChannelsAndEndSitesTheReaderRefusesAreRefused(string what)
        {
            string[] names = { "Hips", "Spine", "Head" };
            int[] parents = { -1, 0, 1 };
            bool[] ends = { false, false, true };
            var rot3 = new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            var channels = new[] { rot3, rot3, Array.Empty<BvhChannel>() };
            switch (what)
            {
                case "a channel listed twice": channels[1] = new[] { BvhChannel.Xrotation, BvhChannel.Xrotation, BvhChannel.Yrotation }; break;
                case "seven channels":
                    channels[0] = new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Xposition };
                    break;
                case "an End Site with a child": ends[1] = true; channels[1] = Array.Empty<BvhChannel>(); break;
                case "an End Site as the root": ends[0] = true; channels[0] = Array.Empty<BvhChannel>(); break;
                default: channels[2] = new[] { BvhChannel.Xrotation }; break;
            }
            int total = 0;
            foreach (BvhChannel[] c in channels) total += c.Length;
            var clip = new BvhClip(names, parents, ends, new[] { Vector3.Zero, new Vector3(0, 10, 0), new Vector3(0, 5, 0) }, channels, 2, 1f / 30f, new float[2 * total], 1f);
            string path = Path.Combine(Path.GetTempPath(), "avatargo-bvh-" + Guid.NewGuid().ToString("N") + ".bvh");
            try
            {
                File.WriteAllText(path, "a good file\n");
                Assert.Throws<ArgumentException>(() => BvhWriter.WriteFile(path, clip), what);
                Assert.That(File.ReadAllText(path), Is.EqualTo("a good file\n"), "the good file is kept");
            }
            finally { File.Delete(path); }
        }
    }
}
