using System;
using System.IO;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>Synthetic sessions in memory: a shipped clip simulated to session text, and copies of it with frames edited.</summary>
    public static class Sessions
    {
        /// <summary>The session text of a clip of Tests/Core/Data~ worn with these options (defaults: seed 1, 90 Hz, 1 mm / 0.1° noise).</summary>
        public static string Simulate(string clip, SimulationOptions options = null) =>
            Simulate(BvhReader.ReadFile(TestData.Mocap(clip), new BvhReadOptions { ToMetres = true }), options);

        /// <summary>The session text of <paramref name="clip"/> (metres) worn with these options.</summary>
        public static string Simulate(BvhClip clip, SimulationOptions options = null)
        {
            var simulator = new SessionSimulator(clip, options ?? new SimulationOptions());
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            return text.ToString();
        }

        /// <summary>
        /// A copy of <paramref name="clip"/> whose every frame went through <paramref name="edit"/>: given the frame's index
        /// and a pose holding its local (and world) transforms, it changes the local ones.
        /// </summary>
        public static BvhClip Rewrite(BvhClip clip, Action<int, SkeletonPose> edit)
        {
            Skeleton s = clip.Skeleton;
            var frames = new System.Collections.Generic.List<RigidPose[]>(clip.FrameCount);
            var world = new RigidPose[s.JointCount];
            var pose = new SkeletonPose(s);
            for (int f = 0; f < clip.FrameCount; f++)
            {
                clip.GetWorldPoses(f, pose.Local, world);
                pose.UpdateWorld();
                edit(f, pose);
                frames.Add((RigidPose[])pose.Local.Clone());
            }
            return BvhClip.FromPoses(s, frames, clip.FrameTime);
        }

        /// <summary>A copy of <paramref name="session"/> whose frames went through <paramref name="edit"/> (given each frame and its index).</summary>
        public static string Edit(string session, Action<int, SessionFrame> edit)
        {
            using var reader = Read(session);
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, reader.Header))
            {
                SessionFrame frame = reader.CreateFrame();
                for (int i = 0; reader.ReadFrame(frame); i++)
                {
                    edit(i, frame);
                    writer.WriteFrame(frame);
                }
            }
            return text.ToString();
        }

        /// <summary>A reader over session text.</summary>
        public static SessionReader Read(string session) => new SessionReader(new StringReader(session), "test session");

        /// <summary>Runs every frame of <paramref name="session"/> through a new pipeline (the wearer's skeleton as the avatar) and returns it.</summary>
        public static SelfAvatarPipeline Replay(string session, PipelineSettings settings = null, Action<int, SelfAvatarPipeline, SessionFrame> afterFrame = null)
        {
            using var reader = Read(session);
            var pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid, settings);
            SessionFrame frame = reader.CreateFrame();
            for (int i = 0; reader.ReadFrame(frame); i++)
            {
                pipeline.Update(frame);
                afterFrame?.Invoke(i, pipeline, frame);
            }
            return pipeline;
        }
    }
}
