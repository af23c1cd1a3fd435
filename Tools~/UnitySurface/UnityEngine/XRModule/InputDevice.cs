// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's InputDevice (a struct, not the Input System's InputDevice class) also implements IEquatable<InputDevice> and
// overrides Equals/GetHashCode; the package compares devices with == only.
#pragma warning disable CS0660, CS0661

using System.Collections.Generic;

namespace UnityEngine.XR
{
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    public struct InputDevice
    {
        public string name => throw null;

        public string serialNumber => throw null;

        public InputDeviceCharacteristics characteristics => throw null;

        public bool TryGetFeatureUsages(List<InputFeatureUsage> featureUsages) => throw null;

        public bool TryGetFeatureValue(InputFeatureUsage<bool> usage, out bool value) => throw null;

        public bool TryGetFeatureValue(InputFeatureUsage<float> usage, out float value) => throw null;

        public bool TryGetFeatureValue(InputFeatureUsage<Vector3> usage, out Vector3 value) => throw null;

        public bool TryGetFeatureValue(InputFeatureUsage<Quaternion> usage, out Quaternion value) => throw null;

        public bool TryGetFeatureValue(InputFeatureUsage<InputTrackingState> usage, out InputTrackingState value) => throw null;

        public static bool operator ==(InputDevice a, InputDevice b) => throw null;

        public static bool operator !=(InputDevice a, InputDevice b) => throw null;
    }
}
