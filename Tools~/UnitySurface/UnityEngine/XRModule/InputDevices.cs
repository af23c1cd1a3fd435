// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Field-like events, as Unity declares them: nothing here raises them.
#pragma warning disable CS0067

using System;
using System.Collections.Generic;

namespace UnityEngine.XR
{
    // Declared "public partial class" (not static): it has an implicit public constructor.
    // UnityCsReference@2021.3 Modules/XR/ScriptBindings/XRInput.bindings.cs
    public class InputDevices
    {
        public static void GetDevices(List<InputDevice> inputDevices) => throw null;

        public static event Action<InputDevice> deviceConnected;

        public static event Action<InputDevice> deviceDisconnected;

        public static event Action<InputDevice> deviceConfigChanged;
    }
}
