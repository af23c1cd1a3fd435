using System.Collections.Generic;
using AvatarGo.Core;
using UnityEngine;
using UnityEngine.XR;
using XRCommonUsages = UnityEngine.XR.CommonUsages;
using XRInputDevice = UnityEngine.XR.InputDevice;

namespace AvatarGo
{
    /// <summary>
    /// The default tracking source: every device Unity's XR input reports (<c>UnityEngine.XR.InputDevices</c>, the built-in
    /// XR module, whatever XR plug-in runs: OpenXR, OpenVR, Oculus, ...): the HMD, the controllers and generic tracked devices
    /// such as VIVE Trackers (under the OpenVR XR plug-in, or under OpenXR with AvatarGo's VIVE tracker feature enabled).
    /// Which devices it keeps, their order, their class and runtime role, and what a reconnect does are decided by the core's
    /// <see cref="XrDeviceRegistry"/>; serials come from <c>InputDevice.serialNumber</c> (OpenXR gives none: the device's name
    /// and characteristics then identify it). Poses are read when <see cref="Read"/> is called, from the XR input state Unity
    /// updated at the start of the frame (see tracking-sources.md for the timing). Connects and disconnects allocate; reading
    /// a frame does not.
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/XR Input Devices Tracking Source")]
    [HelpURL(AvatarGoDocs.Manual + "tracking-sources.md#xr-input-devices-tracking-source")]
    [DisallowMultipleComponent]
    public sealed class XRInputDevicesTrackingSource : AvatarGoTrackingSource
    {
        private readonly XrDeviceRegistry _registry = new XrDeviceRegistry();
        private readonly List<XRInputDevice> _enumerated = new List<XRInputDevice>(16);
        private readonly List<InputFeatureUsage> _usages = new List<InputFeatureUsage>(32);
        private XRInputDevice[] _devices = new XRInputDevice[8];
        private bool[] _centerEye = new bool[8];
        private int _registryVersion = -1;
        private bool _listening;

        /// <inheritdoc/>
        public override SessionHeader Header
        {
            get
            {
                // A disabled source stays disabled: reading it does not subscribe to InputDevices again.
                if (!_listening && isActiveAndEnabled) Listen();
                return _registry.Header;
            }
        }

        /// <summary>The number of devices in <see cref="Header"/> that are connected now.</summary>
        public int ConnectedCount
        {
            get
            {
                int n = 0;
                for (int i = 0; i < _registry.Count; i++)
                    if (_registry.IsConnected(i)) n++;
                return n;
            }
        }

        private void OnEnable() => Listen();

        private void OnDisable() => StopListening();

        private void OnDestroy() => StopListening();

        private void StopListening()
        {
            if (!_listening) return;
            _listening = false;
            InputDevices.deviceConnected -= OnDeviceConnected;
            InputDevices.deviceDisconnected -= OnDeviceDisconnected;
            InputDevices.deviceConfigChanged -= OnDeviceConfigChanged;
            _registry.DisconnectAll();
            for (int i = 0; i < _devices.Length; i++) _devices[i] = default;
        }

        /// <inheritdoc/>
        public override void Read(SessionFrame frame)
        {
            if (frame == null) return;
            if (!_listening && isActiveAndEnabled) Listen();
            frame.Clear();
            frame.Time = Time.unscaledTimeAsDouble; // real time: a paused game (timeScale 0) still tracks and calibrates
            int count = System.Math.Min(frame.Samples.Length, _registry.Count);
            for (int i = 0; i < count; i++)
            {
                if (!_registry.IsConnected(i)) continue; // cleared: lost, no trigger
                XRInputDevice device = _devices[i];
                frame.Samples[i] = ReadSample(device, _centerEye[i]);
                if (_registry.Device(i).Class != DeviceClass.Controller) continue;
                float trigger = device.TryGetFeatureValue(XRCommonUsages.trigger, out float t) ? t : float.NaN;
                float grip = device.TryGetFeatureValue(XRCommonUsages.grip, out float g) ? g : float.NaN;
                bool button = device.TryGetFeatureValue(XRCommonUsages.triggerButton, out bool b) && b;
                frame.Trigger[i] = trigger;
                frame.Grip[i] = grip;
                _registry.FeedTrigger(i, trigger, button, frame.Events);
            }
        }

        private static DeviceSample ReadSample(XRInputDevice device, bool centerEye)
        {
            Vector3 position;
            Quaternion rotation;
            bool gotPosition = centerEye
                ? device.TryGetFeatureValue(XRCommonUsages.centerEyePosition, out position)
                : device.TryGetFeatureValue(XRCommonUsages.devicePosition, out position);
            bool gotRotation = centerEye
                ? device.TryGetFeatureValue(XRCommonUsages.centerEyeRotation, out rotation)
                : device.TryGetFeatureValue(XRCommonUsages.deviceRotation, out rotation);
            bool reportsIsTracked = device.TryGetFeatureValue(XRCommonUsages.isTracked, out bool isTracked);
            bool reportsState = device.TryGetFeatureValue(XRCommonUsages.trackingState, out InputTrackingState state);
            return XrPoseRules.IsTracked(gotPosition, gotRotation, reportsIsTracked, isTracked, reportsState, (uint)state)
                ? new DeviceSample(new RigidPose(position.ToCore(), rotation.ToCore()), true)
                : DeviceSample.Lost;
        }

        // Subscribes first, then lists what is there: a device connecting in between is reported twice and bound once.
        private void Listen()
        {
            if (_listening) return;
            _listening = true;
            InputDevices.deviceConnected += OnDeviceConnected;
            InputDevices.deviceDisconnected += OnDeviceDisconnected;
            InputDevices.deviceConfigChanged += OnDeviceConfigChanged;
            InputDevices.GetDevices(_enumerated);
            var reports = new XrDeviceReport[_enumerated.Count];
            for (int i = 0; i < reports.Length; i++) reports[i] = Report(_enumerated[i]);
            int[] index = _registry.ConnectAll(reports);
            for (int i = 0; i < index.Length; i++)
                if (index[i] >= 0) Bind(index[i], _enumerated[i]);
            _enumerated.Clear();
            NoteHeader();
        }

        private void OnDeviceConnected(XRInputDevice device)
        {
            if (IndexOf(device) >= 0) return;
            int index = _registry.Connect(Report(device));
            if (index >= 0) Bind(index, device);
            NoteHeader();
        }

        private void OnDeviceDisconnected(XRInputDevice device)
        {
            int index = IndexOf(device);
            if (index < 0) return;
            _registry.Disconnect(index);
            _devices[index] = default;
        }

        // A device whose characteristics changed (an OpenVR tracker given another role) is matched again.
        private void OnDeviceConfigChanged(XRInputDevice device)
        {
            OnDeviceDisconnected(device);
            OnDeviceConnected(device);
        }

        private int IndexOf(XRInputDevice device)
        {
            for (int i = 0; i < _registry.Count; i++)
                if (_registry.IsConnected(i) && _devices[i] == device) return i;
            return -1;
        }

        private void Bind(int index, XRInputDevice device)
        {
            if (index >= _devices.Length)
            {
                System.Array.Resize(ref _devices, System.Math.Max(2 * _devices.Length, index + 1));
                System.Array.Resize(ref _centerEye, _devices.Length);
            }
            _devices[index] = device;
            var names = new List<string>();
            _usages.Clear();
            if (device.TryGetFeatureUsages(_usages))
                for (int u = 0; u < _usages.Count; u++) names.Add(_usages[u].name);
            _centerEye[index] = XrPoseRules.UsesCenterEye(_registry.Device(index).Class, names);
        }

        private void NoteHeader()
        {
            if (_registry.Version == _registryVersion) return;
            _registryVersion = _registry.Version;
            HeaderVersion++;
        }

        private static XrDeviceReport Report(XRInputDevice device) =>
            new XrDeviceReport((uint)device.characteristics, device.name, device.serialNumber);
    }
}
