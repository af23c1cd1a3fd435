// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// The nested types are "protected internal": an interaction feature in another assembly sees them as protected.
// Unity's ActionConfig gains "isAdditive" in later versions; not used.

using System.Collections.Generic;

namespace UnityEngine.XR.OpenXR.Features
{
    // com.unity.xr.openxr@1.0.2 Runtime/Features/OpenXRInteractionFeature.cs
    public abstract class OpenXRInteractionFeature : OpenXRFeature
    {
        protected internal enum ActionType
        {
            Binary,
            Axis1D,
            Axis2D,
            Pose,
            Vibrate,
            Count,
        }

        protected internal class ActionBinding
        {
            public string interactionProfileName;

            public string interactionPath;
        }

        protected internal class ActionConfig
        {
            public string name;

            public ActionType type;

            public string localizedName;

            public List<ActionBinding> bindings;

            public List<string> usages;
        }

        protected internal class DeviceConfig
        {
            public InputDeviceCharacteristics characteristics;

            public string userPath;
        }

        protected internal class ActionMapConfig
        {
            public string name;

            public string localizedName;

            public List<DeviceConfig> deviceInfos;

            public List<ActionConfig> actions;

            public string desiredInteractionProfile;

            public string manufacturer;

            public string serialNumber;
        }

        protected virtual void RegisterDeviceLayout() => throw null;

        protected virtual void UnregisterDeviceLayout() => throw null;

        protected virtual void RegisterActionMapsWithRuntime() => throw null;

        protected internal override bool OnInstanceCreate(ulong xrSession) => throw null;

        protected void AddActionMap(ActionMapConfig map) => throw null;

#if OPENXR_1_9_OR_NEWER
        // com.unity.xr.openxr@1.9.1 Runtime/Features/OpenXRInteractionFeature.cs
        public enum InteractionProfileType
        {
            Device,
            XRController,
        }

        // com.unity.xr.openxr@1.9.1 Runtime/Features/OpenXRInteractionFeature.cs
        protected virtual InteractionProfileType GetInteractionProfileType() => throw null;

        // com.unity.xr.openxr@1.9.1 Runtime/Features/OpenXRInteractionFeature.cs
        protected virtual string GetDeviceLayoutName() => throw null;
#endif
    }
}
