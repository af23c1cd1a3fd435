using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Turns each controller's trigger (its analog value, its button, or both) into press and release events, with
    /// hysteresis so a trigger held near a threshold does not chatter: pressed at <see cref="PressAt"/>, released at
    /// <see cref="ReleaseAt"/>. One state per device; allocation-free (the caller's list receives the events).
    /// </summary>
    public sealed class TriggerEdges
    {
        private readonly bool[] _pressed;

        /// <summary>Creates the state for <paramref name="devices"/> devices.</summary>
        public TriggerEdges(int devices, float pressAt = 0.75f, float releaseAt = 0.25f)
        {
            if (devices < 0) throw new ArgumentOutOfRangeException(nameof(devices));
            if (!(releaseAt >= 0f && releaseAt < pressAt && pressAt <= 1f)) throw new ArgumentOutOfRangeException(nameof(pressAt), "Need 0 <= release < press <= 1.");
            _pressed = new bool[devices];
            PressAt = pressAt;
            ReleaseAt = releaseAt;
        }

        /// <summary>The analog value at which a trigger counts as pressed.</summary>
        public float PressAt { get; }

        /// <summary>The analog value at which a pressed trigger counts as released.</summary>
        public float ReleaseAt { get; }

        /// <summary>True while device <paramref name="device"/>'s trigger is pressed.</summary>
        public bool IsPressed(int device) => _pressed[device];

        /// <summary>
        /// Feeds device <paramref name="device"/>'s trigger this frame: <paramref name="analog"/> (0..1, NaN when the device
        /// has none) and <paramref name="button"/> (the runtime's trigger button). Adds a press or release event for
        /// <paramref name="deviceId"/> to <paramref name="events"/> when the state changes.
        /// </summary>
        public void Feed(int device, int deviceId, float analog, bool button, List<DeviceEvent> events)
        {
            if (events == null) throw new ArgumentNullException(nameof(events));
            bool was = _pressed[device];
            // Hysteresis: a released trigger needs PressAt to be pressed, a pressed one falls below ReleaseAt to be released.
            bool analogDown = !float.IsNaN(analog) && (was ? analog > ReleaseAt : analog >= PressAt);
            bool now = button || analogDown;
            if (now == was) return;
            _pressed[device] = now;
            events.Add(new DeviceEvent(deviceId, now ? DeviceEventKind.TriggerPressed : DeviceEventKind.TriggerReleased));
        }

        /// <summary>The number of devices this state is for.</summary>
        public int DeviceCount => _pressed.Length;

        /// <summary>
        /// A copy for <paramref name="devices"/> devices with the same thresholds, each device both have keeping its pressed
        /// state (a source whose device list grows keeps a trigger held across the change without a second press).
        /// </summary>
        public TriggerEdges Resized(int devices)
        {
            var copy = new TriggerEdges(devices, PressAt, ReleaseAt);
            Array.Copy(_pressed, copy._pressed, Math.Min(devices, _pressed.Length));
            return copy;
        }

        /// <summary>Device <paramref name="device"/> disconnected: its trigger counts as released, without an event.</summary>
        public void Forget(int device) => _pressed[device] = false;
    }
}
