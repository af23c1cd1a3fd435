// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's TrackedPoseDriver also implements ISerializationCallbackReceiver (from 1.1).

namespace UnityEngine.InputSystem.XR
{
    // com.unity.inputsystem@1.0.2 InputSystem/Plugins/XR/TrackedPoseDriver.cs
    public class TrackedPoseDriver : MonoBehaviour
    {
#if INPUT_SYSTEM_1_1_OR_NEWER
        // com.unity.inputsystem@1.1.1 InputSystem/Plugins/XR/TrackedPoseDriver.cs
        public InputActionProperty positionInput { get => throw null; set => throw null; }
#endif
    }
}
