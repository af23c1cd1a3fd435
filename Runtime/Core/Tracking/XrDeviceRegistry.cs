using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// The devices an XR runtime has reported during a session, in a stable order, with the rules a tracking source needs
    /// and that can be decided without Unity:
    /// <list type="bullet">
    /// <item>which devices the body uses, their class and runtime role (<see cref="XrDeviceKind.TryClassify"/>);</item>
    /// <item>what identifies a device (<see cref="IdentityOf"/>): its serial when the runtime gives one, otherwise its name and
    /// the characteristics bits that say what and where it is (OpenXR gives no serials);</item>
    /// <item>the order in the header: the devices present at start sorted (HMD, controllers left then right, trackers
    /// pelvis, left foot, right foot, then the rest by serial and name), every later one appended, and an index never
    /// changes, so per-device state and recorded frames keep their meaning;</item>
    /// <item>a device that disconnects keeps its place and its id (it reports lost); one that reconnects, even with a new
    /// runtime handle (Unity gives it a new <c>InputDevice</c>), takes back the first disconnected place with its
    /// identity, and only a device never seen before adds a place (a new <see cref="Header"/>, <see cref="Version"/>
    /// incremented). A reconnecting device whose class or runtime role changed (an OpenVR tracker given another role)
    /// keeps its place and id, with the header rebuilt.</item>
    /// </list>
    /// Ids are the header indices. Connecting allocates (a new header); reading state and feeding triggers do not.
    /// </summary>
    public sealed class XrDeviceRegistry
    {
        private const uint IdentityBits = XrDeviceKind.HeadMounted | XrDeviceKind.HeldInHand | XrDeviceKind.Controller | XrDeviceKind.TrackedDevice
            | XrDeviceKind.Left | XrDeviceKind.Right | XrDeviceKind.TrackerWaist | XrDeviceKind.TrackerLeftFoot | XrDeviceKind.TrackerRightFoot;

        private readonly float _rate;
        private readonly List<DeviceInfo> _devices = new List<DeviceInfo>(8);
        private readonly List<string> _identities = new List<string>(8);
        private readonly List<bool> _connected = new List<bool>(8);
        private TriggerEdges _edges;
        private SessionHeader _header;

        /// <summary>Creates an empty registry whose headers give <paramref name="rate"/> Hz as the nominal frame rate.</summary>
        public XrDeviceRegistry(float rate = 90f, float pressAt = 0.75f, float releaseAt = 0.25f)
        {
            if (!(rate > 0f) || float.IsInfinity(rate)) throw new ArgumentOutOfRangeException(nameof(rate), rate, "The rate must be positive.");
            _rate = rate;
            _edges = new TriggerEdges(8, pressAt, releaseAt);
            _header = new SessionHeader(rate, Array.Empty<DeviceInfo>());
        }

        /// <summary>The devices seen so far, connected or not, in header order.</summary>
        public SessionHeader Header => _header;

        /// <summary>Incremented whenever <see cref="Header"/> is replaced.</summary>
        public int Version { get; private set; }

        /// <summary>The number of devices in the header.</summary>
        public int Count => _devices.Count;

        /// <summary>The device at header index <paramref name="index"/>.</summary>
        public DeviceInfo Device(int index) => _devices[index];

        /// <summary>True while the device at <paramref name="index"/> is connected.</summary>
        public bool IsConnected(int index) => _connected[index];

        /// <summary>
        /// What identifies a device across disconnections: <c>serial:</c> and its serial when it has one; otherwise <c>name:</c>,
        /// its name and the bits of its characteristics that say what and where it is (head, hand, side, tracker role).
        /// Two devices with neither a serial nor a difference in name and bits (two OpenXR devices of one profile and side)
        /// cannot be told apart: the first disconnected place is taken.
        /// </summary>
        public static string IdentityOf(XrDeviceReport report) =>
            report.Serial.Length > 0 ? "serial:" + report.Serial : "name:" + report.Name + "|0x" + (report.Characteristics & IdentityBits).ToString("x");

        /// <summary>
        /// A device connected: returns its header index, or -1 for a device the body does not use (base stations, eye gaze,
        /// hand tracking, trackers with another body role).
        /// </summary>
        public int Connect(XrDeviceReport report)
        {
            if (!XrDeviceKind.TryClassify(report.Characteristics, out DeviceClass cls, out DeviceRole role)) return -1;
            string identity = IdentityOf(report);
            for (int i = 0; i < _devices.Count; i++)
            {
                if (_connected[i] || _identities[i] != identity) continue;
                _connected[i] = true;
                if (_devices[i].Class != cls || _devices[i].RuntimeRole != role)
                {
                    _devices[i] = new DeviceInfo(i, cls, report.Serial, role);
                    Rebuild();
                }
                return i;
            }
            int index = _devices.Count;
            _devices.Add(new DeviceInfo(index, cls, report.Serial, role));
            _identities.Add(identity);
            _connected.Add(true);
            if (_edges.DeviceCount < _devices.Count) _edges = _edges.Resized(Math.Max(2 * _edges.DeviceCount, _devices.Count));
            Rebuild();
            return index;
        }

        /// <summary>
        /// The devices present when a source starts (or is enabled again): each is matched to its old place first, then the new
        /// ones are added in the header order described on the class, whatever order the runtime listed them in. Returns
        /// each report's header index (-1 for devices the body does not use), in the order given.
        /// </summary>
        public int[] ConnectAll(IReadOnlyList<XrDeviceReport> reports)
        {
            if (reports == null) throw new ArgumentNullException(nameof(reports));
            var result = new int[reports.Count];
            var order = new List<int>(reports.Count);
            for (int r = 0; r < reports.Count; r++) order.Add(r);
            order.Sort((a, b) =>
            {
                int c = Rank(reports[a]).CompareTo(Rank(reports[b]));
                if (c == 0) c = string.CompareOrdinal(reports[a].Serial, reports[b].Serial);
                if (c == 0) c = string.CompareOrdinal(reports[a].Name, reports[b].Name);
                return c != 0 ? c : a.CompareTo(b);
            });
            // Known devices take back their places before any new one could take a place with the same identity.
            var placed = new bool[reports.Count];
            foreach (int r in order)
            {
                if (!IsKnownAndFree(reports[r])) continue;
                result[r] = Connect(reports[r]);
                placed[r] = true;
            }
            foreach (int r in order)
                if (!placed[r]) result[r] = Connect(reports[r]);
            return result;
        }

        /// <summary>The device at <paramref name="index"/> disconnected: it stays in the header, lost, its trigger released (no event).</summary>
        public void Disconnect(int index)
        {
            _connected[index] = false;
            _edges.Forget(index);
        }

        /// <summary>Every device disconnected (the source was disabled).</summary>
        public void DisconnectAll()
        {
            for (int i = 0; i < _devices.Count; i++) Disconnect(i);
        }

        /// <summary>
        /// Feeds the trigger of the device at <paramref name="index"/> (<see cref="TriggerEdges.Feed"/>): analog 0..1 or NaN,
        /// and the runtime's trigger button. Press and release events go to <paramref name="events"/>. Allocation-free.
        /// </summary>
        public void FeedTrigger(int index, float analog, bool button, List<DeviceEvent> events) =>
            _edges.Feed(index, _devices[index].Id, analog, button, events);

        private bool IsKnownAndFree(XrDeviceReport report)
        {
            string identity = IdentityOf(report);
            for (int i = 0; i < _devices.Count; i++)
                if (!_connected[i] && _identities[i] == identity) return true;
            return false;
        }

        // HMD, then controllers (left, right, unsided), then trackers (pelvis, left foot, right foot, unassigned), then unused.
        private static int Rank(XrDeviceReport report)
        {
            if (!XrDeviceKind.TryClassify(report.Characteristics, out DeviceClass cls, out DeviceRole role)) return 100;
            switch (cls)
            {
                case DeviceClass.Hmd: return 0;
                case DeviceClass.Controller:
                    return (report.Characteristics & XrDeviceKind.Left) != 0 ? 10 : (report.Characteristics & XrDeviceKind.Right) != 0 ? 11 : 12;
                default:
                    return role == DeviceRole.Pelvis ? 20 : role == DeviceRole.LeftFoot ? 21 : role == DeviceRole.RightFoot ? 22 : 23;
            }
        }

        private void Rebuild()
        {
            _header = new SessionHeader(_rate, _devices.ToArray());
            Version++;
        }
    }
}
