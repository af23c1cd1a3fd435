using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// What the components do on a setup error (one place for it): log it once with the component as context and disable
    /// the component; and their lookup of the calibrator they serve when none is assigned.
    /// </summary>
    internal static class SetupErrors
    {
        /// <summary>Logs <paramref name="error"/> with <paramref name="component"/> as context, then disables the component.</summary>
        internal static void Disable(Behaviour component, string error)
        {
            Debug.LogError(error, component);
            component.enabled = false;
        }

        /// <summary>
        /// A component's setup error: sets <paramref name="failed"/>, logs "Type on 'name': message. The component disables
        /// itself." with the component as context, and disables it. Returns false, for <c>return Fail(...)</c>.
        /// </summary>
        internal static bool Fail(Behaviour component, ref bool failed, string message)
        {
            failed = true;
            Disable(component, $"{component.GetType().Name} on '{component.name}': {message}. The component disables itself.");
            return false;
        }

        /// <summary>
        /// The calibrator a component serves: <paramref name="calibrator"/> as assigned, else the nearest in its parents
        /// (kept in <paramref name="calibrator"/>). Without one, a setup error (<see cref="Fail"/>) and false. Allocation-free.
        /// </summary>
        internal static bool FindCalibrator(Behaviour component, ref AvatarGoCalibrator calibrator, ref bool failed)
        {
            if (calibrator == null) calibrator = component.GetComponentInParent<AvatarGoCalibrator>();
            return calibrator != null || Fail(component, ref failed, "no calibrator is assigned or found in the parents");
        }
    }
}
