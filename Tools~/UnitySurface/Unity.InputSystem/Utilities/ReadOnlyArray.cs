// Compile-only Unity API surface (see Tools~/UnitySurface/README.md): only what the package uses, as Unity declares it.
// Unity's ReadOnlyArray<TValue> also implements IReadOnlyList<TValue> (and so IEnumerable); the package indexes it.

namespace UnityEngine.InputSystem.Utilities
{
    // com.unity.inputsystem@1.0.2 InputSystem/Utilities/ReadOnlyArray.cs
    public struct ReadOnlyArray<TValue>
    {
        public int Count => throw null;

        public TValue this[int index] => throw null;
    }
}
