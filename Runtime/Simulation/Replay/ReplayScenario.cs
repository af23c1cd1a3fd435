using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// The sessions and the avatar the play-mode tests (<c>Tests/Runtime</c>) and their engine-free twins (<c>Tests/Core</c>)
    /// share: the bundled mocap clip worn as a synthetic VR session (with ground truth), the same session with one arm held
    /// low through the T-pose (a malformed T-pose) or with a tracker lost for a while, and the wearer's skeleton (rest pose) as
    /// the avatar's hierarchy, so that both sides run the same frames on the same avatar.
    /// </summary>
    public static class ReplayScenario
    {
        /// <summary>
        /// The clip, under the package's <c>Tests/Core/Data~</c>: the Mixamo-rigged one, whose hands have finger bones, so
        /// the fingers' bound is exercised (the prefab's Quest Touch profile in both hands).
        /// </summary>
        public const string Clip = "mixamo_fingers_30fps.bvh";

        /// <summary>The simulation's seed.</summary>
        public const int Seed = 1;

        /// <summary>How far the malformed T-pose holds one controller below the other (m).</summary>
        public const float LoweredArm = 0.4f;

        /// <summary>How long before the session's last frame the lost tracker comes back (s): the loss lies in the motion.</summary>
        public const double LossEndBeforeLastFrame = 0.5;

        /// <summary>How long the lost tracker stays lost (s).</summary>
        public const double LossDuration = 1.5;

        /// <summary>The clip's path under the package root.</summary>
        public static string ClipPath(string packageRoot) => Path.Combine(packageRoot, "Tests", "Core", "Data~", Clip);

        /// <summary>The clip worn as a session (session format v1 text), with the default simulation options and <see cref="Seed"/>.</summary>
        public static string Simulate(string clipPath)
        {
            BvhClip clip = BvhReader.ReadFile(clipPath, new BvhReadOptions { ToMetres = true });
            var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = Seed });
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
            return text.ToString();
        }

        /// <summary>The session with the first controller held <see cref="LoweredArm"/> lower in every frame: every T-pose press is refused.</summary>
        public static string WithOneArmLowered(string session) =>
            Edit(session, (header, frame) =>
            {
                int c = FirstOf(header, DeviceClass.Controller);
                DeviceSample s = frame.Samples[c];
                RigidPose p = s.Pose;
                frame.Samples[c] = new DeviceSample(new RigidPose(p.Position - new Vector3(0f, LoweredArm, 0f), p.Rotation), s.IsTracked);
            });

        /// <summary>
        /// The session with its first tracker reported lost for <see cref="LossDuration"/> seconds, ending
        /// <see cref="LossEndBeforeLastFrame"/> before the last frame (so it falls in the motion, after calibration).
        /// </summary>
        public static string WithATrackerLost(string session)
        {
            double last = LastFrameTime(session);
            double end = last - LossEndBeforeLastFrame, start = end - LossDuration;
            return Edit(session, (header, frame) =>
            {
                if (frame.Time < start || frame.Time >= end) return;
                int d = FirstOf(header, DeviceClass.Tracker);
                frame.Samples[d] = new DeviceSample(frame.Samples[d].Pose, false);
            });
        }

        private static double LastFrameTime(string session)
        {
            using var reader = new SessionReader(new StringReader(session), "replay scenario");
            SessionFrame frame = reader.CreateFrame();
            double last = double.NaN;
            while (reader.ReadFrame(frame)) last = frame.Time;
            return last;
        }

        /// <summary>
        /// The wearer's skeleton of <paramref name="map"/> in its rest pose as the hierarchy the components read from the scene:
        /// a root named <paramref name="rootName"/> at the origin, then the skeleton's joints (end sites too) depth-first in
        /// skeleton order, which is what <c>HumanoidBinding.Flatten</c> gives for GameObjects made from this list in its order.
        /// </summary>
        public static List<HierarchyNode> AvatarNodes(HumanoidMap map, string rootName = "Avatar")
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            Skeleton s = map.Skeleton;
            var children = new List<int>[s.JointCount + 1]; // 0: the root; joint j is j + 1
            for (int i = 0; i < children.Length; i++) children[i] = new List<int>();
            for (int j = 0; j < s.JointCount; j++) children[s.GetParent(j) + 1].Add(j + 1);
            var nodes = new List<HierarchyNode>();
            Add(s, rootName, children, 0, -1, nodes);
            return nodes;
        }

        private static void Add(Skeleton s, string rootName, List<int>[] children, int node, int parent, List<HierarchyNode> nodes)
        {
            int index = nodes.Count;
            if (node == 0) nodes.Add(new HierarchyNode(rootName, -1, Vector3.Zero, Quaternion.Identity, Vector3.One));
            else
            {
                RigidPose rest = s.GetRestLocal(node - 1);
                nodes.Add(new HierarchyNode(s.GetName(node - 1), parent, rest.Position, rest.Rotation, Vector3.One));
            }
            foreach (int c in children[node]) Add(s, rootName, children, c, index, nodes);
        }

        private static int FirstOf(SessionHeader header, DeviceClass kind)
        {
            for (int d = 0; d < header.Devices.Count; d++)
                if (header.Devices[d].Class == kind) return d;
            throw new ArgumentException($"The session has no {kind}.");
        }

        private static string Edit(string session, Action<SessionHeader, SessionFrame> edit)
        {
            using var reader = new SessionReader(new StringReader(session), "replay scenario");
            var text = new StringWriter();
            using (var writer = new SessionWriter(text, reader.Header))
            {
                SessionFrame frame = reader.CreateFrame();
                while (reader.ReadFrame(frame))
                {
                    edit(reader.Header, frame);
                    writer.WriteFrame(frame);
                }
            }
            return text.ToString();
        }
    }
}
