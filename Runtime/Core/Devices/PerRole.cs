using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// One value per body role (head, both hands, pelvis, both feet), indexed by <see cref="DeviceRole"/>: the one way
    /// the core stores per-role data. Indexing is a bounds-checked array read; nothing allocates after construction.
    /// </summary>
    /// <typeparam name="T">The value stored per role.</typeparam>
    public sealed class PerRole<T>
    {
        private readonly T[] _values = new T[BodyRoles.Count];

        /// <summary>Creates the storage with every role's value at <c>default</c>.</summary>
        public PerRole() { }

        /// <summary>Creates the storage with every role's value at <paramref name="value"/>.</summary>
        public PerRole(T value) => Fill(value);

        /// <summary>The value of <paramref name="role"/>.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="role"/> is <see cref="DeviceRole.None"/> or not a role.</exception>
        public T this[DeviceRole role]
        {
            get => _values[BodyRoles.IndexOf(role)];
            set => _values[BodyRoles.IndexOf(role)] = value;
        }

        /// <summary>Sets every role's value to <paramref name="value"/>.</summary>
        public void Fill(T value)
        {
            for (int i = 0; i < _values.Length; i++) _values[i] = value;
        }

        /// <summary>Copies every role's value from <paramref name="other"/>.</summary>
        public void CopyFrom(PerRole<T> other)
        {
            if (other == null) throw new ArgumentNullException(nameof(other));
            Array.Copy(other._values, _values, _values.Length);
        }
    }
}
