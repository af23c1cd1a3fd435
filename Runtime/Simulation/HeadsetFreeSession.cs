using System;
using System.IO;
using AvatarGo.Core;

namespace AvatarGo.Simulation
{
    /// <summary>
    /// The session the headset-free sample plays: a mocap clip (BVH text, as a Unity text asset holds it) worn by a
    /// simulated wearer with six virtual devices, from the T-pose and walk-in through the motion, with the wearer's true
    /// joints, written to a session file the package's recorded-session source plays. The sample's avatar is a mannequin
    /// of the same skeleton (<see cref="MannequinBlueprint"/>), so its error is the pipeline's own.
    /// </summary>
    public static class HeadsetFreeSession
    {
        /// <summary>
        /// Reads the clip <paramref name="bvhText"/> (named <paramref name="sourceName"/> in errors), simulates it with
        /// <paramref name="options"/> and writes the session to <paramref name="path"/> (atomically: a failure leaves any
        /// earlier file as it was). Returns the wearer as simulated (<see cref="SessionSimulator.Wearer"/>): the clip's skeleton in
        /// metres, mirrored when its knees bent backward, and its humanoid bones.
        /// </summary>
        /// <exception cref="FormatException">The clip is not valid BVH (the message names the line).</exception>
        /// <exception cref="ArgumentException">The clip's skeleton lacks a humanoid bone the simulation needs.</exception>
        /// <exception cref="IOException">The session cannot be written.</exception>
        public static HumanoidMap Write(string bvhText, string sourceName, string path, SimulationOptions options = null)
        {
            if (bvhText == null) throw new ArgumentNullException(nameof(bvhText));
            if (path == null) throw new ArgumentNullException(nameof(path));
            BvhClip clip = BvhReader.Read(new StringReader(bvhText), sourceName ?? "clip", new BvhReadOptions { ToMetres = true });
            HumanoidMap wearer = HumanoidDetection.Detect(clip, null, out string note);
            if (!wearer.IsComplete && note != null)
                throw new ArgumentException($"The rig lacks required humanoid bones: {string.Join(", ", wearer.MissingRequired())}; {note}.", nameof(bvhText));
            wearer.RequireComplete(nameof(bvhText));
            var simulator = new SessionSimulator(clip, options ?? new SimulationOptions(), wearer);
            string folder = Path.GetDirectoryName(Path.GetFullPath(path));
            if (!string.IsNullOrEmpty(folder)) Directory.CreateDirectory(folder);
            SessionWriter.WriteFile(path, simulator.CreateHeader(), writer => simulator.Run(writer)); // whole or not at all
            return simulator.Wearer;
        }
    }
}
