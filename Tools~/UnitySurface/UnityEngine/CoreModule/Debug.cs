// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Debug/Debug.bindings.cs
    public partial class Debug
    {
        public static void Log(object message, Object context) => throw null;

        public static void LogError(object message, Object context) => throw null;

        public static void LogException(System.Exception exception, Object context) => throw null;

        public static void LogWarning(object message, Object context) => throw null;
    }
}
