// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // UnityCsReference@2021.3 Runtime/Export/Time/Time.bindings.cs (a non-static class with static members)
    public class Time
    {
        public static double timeAsDouble => throw null;
    }
}
