using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// One frame of a session, as a reusable buffer: <see cref="SessionReader.ReadFrame"/> fills it and
    /// <see cref="SessionWriter.WriteFrame"/> writes it. Sized once for a header; reuse it for every frame.
    /// </summary>
    public sealed class SessionFrame
    {
        /// <summary>Creates a frame buffer for the devices of <paramref name="header"/>.</summary>
        public SessionFrame(SessionHeader header)
        {
            if (header == null) throw new ArgumentNullException(nameof(header));
            Samples = new DeviceSample[header.Devices.Count];
            Trigger = new float[header.Devices.Count];
            Grip = new float[header.Devices.Count];
            Truth = new RigidPose[HumanoidBones.Count];
            HasTruth = new bool[HumanoidBones.Count];
            Clear();
        }

        /// <summary>Time of the frame in seconds from the start of the session.</summary>
        public double Time { get; set; }

        /// <summary>Each device's sample, in header order.</summary>
        public DeviceSample[] Samples { get; }

        /// <summary>Input events of this frame (trigger presses and releases).</summary>
        public List<DeviceEvent> Events { get; } = new List<DeviceEvent>(4);

        /// <summary>Analog trigger value 0..1 per device, NaN when the frame does not give it.</summary>
        public float[] Trigger { get; }

        /// <summary>Analog grip value 0..1 per device, NaN when the frame does not give it.</summary>
        public float[] Grip { get; }

        /// <summary>Synthetic sessions: the wearer's true world pose per <see cref="HumanoidBone"/> (valid where <see cref="HasTruth"/>).</summary>
        public RigidPose[] Truth { get; }

        /// <summary>Which entries of <see cref="Truth"/> this frame has.</summary>
        public bool[] HasTruth { get; }

        /// <summary>Resets to an empty frame: time 0, devices untracked, no events, no analog input, no truth.</summary>
        public void Clear()
        {
            Time = 0;
            for (int i = 0; i < Samples.Length; i++)
            {
                Samples[i] = DeviceSample.Lost;
                Trigger[i] = float.NaN;
                Grip[i] = float.NaN;
            }
            Events.Clear();
            Array.Clear(HasTruth, 0, HasTruth.Length);
        }
    }
}
