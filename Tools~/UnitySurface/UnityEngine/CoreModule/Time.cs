// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.

namespace UnityEngine
{
    // a non-static class with static members
    // UnityCsReference@2021.3 Runtime/Export/Time/Time.bindings.cs
    public class Time
    {
        public static double unscaledTimeAsDouble => throw null;

        public static float deltaTime => throw null;

        public static float unscaledDeltaTime => throw null;

        public static int frameCount => throw null;
    }
}
