// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Application/Application.bindings.cs
    public partial class Application
    {
        // Read it in Awake or later, not in a field initializer.
        public static string persistentDataPath => throw null;

        // In the Editor: the project's Assets folder (<project>/Assets).
        public static string dataPath => throw null;

        // After LateUpdate, before rendering (XR pose drivers refresh the camera here too).
        // UnityCsReference@2021.3 Runtime/Export/Application/Application.cs
        public static event UnityEngine.Events.UnityAction onBeforeRender { add => throw null; remove => throw null; }
    }
}
