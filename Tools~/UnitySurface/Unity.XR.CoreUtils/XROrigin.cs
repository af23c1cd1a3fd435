// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

using UnityEngine;

namespace Unity.XR.CoreUtils
{
    // com.unity.xr.core-utils@2.0.0 Runtime/XROrigin.cs
    public class XROrigin : MonoBehaviour
    {
        public Camera Camera { get => throw null; set => throw null; }

        public GameObject CameraFloorOffsetObject { get => throw null; set => throw null; }
    }
}
