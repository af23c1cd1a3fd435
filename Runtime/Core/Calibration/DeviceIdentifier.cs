using System;
using System.Collections.Generic;
using System.Numerics;
using System.Text;

namespace AvatarGo.Core
{
    /// <summary>
    /// Which device plays which body role, from the devices' classes, the roles the runtime assigned and where the
    /// devices are in the T-pose. First <see cref="Select"/> picks the HMD, two controllers and three trackers (the one
    /// at waist height under the head is the pelvis, the two lowest near the body are the feet; extra devices are
    /// ignored, with an explanation); then, once the body plane is known, <see cref="AssignSides"/> tells left from right
    /// along the plane and checks every runtime role against the geometry, which is trusted over any runtime claim.
    /// </summary>
    public sealed class DeviceIdentifier
    {
        private readonly DeviceInfo[] _devices;
        private readonly CalibrationSettings _settings;

        /// <summary>Creates an identifier for these devices (in the order averages will come).</summary>
        public DeviceIdentifier(IReadOnlyList<DeviceInfo> devices, CalibrationSettings settings)
        {
            if (devices == null) throw new ArgumentNullException(nameof(devices));
            _settings = settings ?? throw new ArgumentNullException(nameof(settings));
            _devices = new DeviceInfo[devices.Count];
            for (int i = 0; i < _devices.Length; i++) _devices[i] = devices[i] ?? throw new ArgumentException($"Device {i} is null.", nameof(devices));
        }

        /// <summary>
        /// Picks the six devices of the body from their averages over the window. Fails with
        /// <see cref="CalibrationError.DeviceMissing"/> (too few of a class connected), <see cref="CalibrationError.DeviceNotTracked"/>
        /// (the detail names which), <see cref="CalibrationError.RoleConflict"/> (runtime roles claimed twice) or
        /// <see cref="CalibrationError.PelvisNotBetweenHeadAndFeet"/> (no tracker at waist height).
        /// </summary>
        /// <param name="averages">Every device's window average, in device order.</param>
        /// <param name="selection">The devices chosen, the floor and the eye height, when the result is <see cref="CalibrationError.None"/>.</param>
        /// <param name="detail">What failed, for the wearer's message; null on success.</param>
        /// <param name="explanation">Receives notes on choices made (ignored extra devices).</param>
        public CalibrationError Select(ReadOnlySpan<WindowAverage> averages, out DeviceSelection selection, out string detail, StringBuilder explanation)
        {
            if (averages.Length != _devices.Length) throw new ArgumentException($"Expected {_devices.Length} averages, got {averages.Length}.", nameof(averages));
            selection = default;
            detail = null;
            var hmds = new List<int>();
            var controllers = new List<int>();
            var trackers = new List<int>();
            for (int d = 0; d < _devices.Length; d++)
                (_devices[d].Class == DeviceClass.Hmd ? hmds : _devices[d].Class == DeviceClass.Controller ? controllers : trackers).Add(d);
            if (hmds.Count < 1 || controllers.Count < 2 || trackers.Count < 3)
            {
                detail = $"found {hmds.Count} HMD, {controllers.Count} controllers, {trackers.Count} trackers";
                return CalibrationError.DeviceMissing;
            }

            var tracked = new bool[_devices.Length];
            for (int d = 0; d < _devices.Length; d++) tracked[d] = averages[d].IsTracked;
            int hmd = hmds.FindIndex(d => tracked[d]);
            if (hmd < 0)
            {
                detail = "the headset";
                return CalibrationError.DeviceNotTracked;
            }
            hmd = hmds[hmd];
            var liveControllers = controllers.FindAll(d => tracked[d]);
            if (liveControllers.Count < 2)
            {
                detail = controllers.Count - liveControllers.Count == 1 ? "a controller" : "both controllers";
                return CalibrationError.DeviceNotTracked;
            }
            var liveTrackers = trackers.FindAll(d => tracked[d]);
            if (liveTrackers.Count < 3)
            {
                detail = $"{3 - liveTrackers.Count} tracker(s)";
                return CalibrationError.DeviceNotTracked;
            }
            if (hmds.Count > 1) explanation.Append($"Using the first tracked of {hmds.Count} headsets. ");

            RigidPose head = averages[hmd].Mean;
            float floor = _settings.FloorHeight;
            if (float.IsNaN(floor))
            {
                float lowest = float.MaxValue;
                foreach (int t in liveTrackers) lowest = Math.Min(lowest, averages[t].Position.Y);
                floor = lowest - _settings.FootTrackerHeight;
            }
            float eyeHeight = head.Position.Y - floor;
            (int handA, int handB) = liveControllers.Count == 2 ? (liveControllers[0], liveControllers[1]) : HandsOfATPose(liveControllers, averages, head.Position, floor + 0.82f * eyeHeight);
            if (liveControllers.Count > 2)
                explanation.Append($"{liveControllers.Count} controllers are tracked: the two that stand as hands in a T-pose (widest apart, level, at shoulder height, either side of the head) are used; the others are ignored. ");

            // Trackers: runtime roles first; otherwise the pelvis is the one nearest waist height (0.57 × eye height) close to
            // the head, the feet the two lowest close to the body (a spare tracker on a table or the floor nearby scores badly).
            int pelvis = -1, footA = -1, footB = -1, runtimeFeet = 0;
            foreach (int t in liveTrackers)
            {
                DeviceRole r = _devices[t].RuntimeRole;
                if (r == DeviceRole.Pelvis)
                {
                    if (pelvis >= 0) { detail = "two trackers are assigned the waist role"; return CalibrationError.RoleConflict; }
                    pelvis = t;
                }
                if (r == DeviceRole.LeftFoot || r == DeviceRole.RightFoot) runtimeFeet++;
            }
            if (runtimeFeet > 2) { detail = "more than two trackers are assigned a foot role"; return CalibrationError.RoleConflict; }
            if (pelvis < 0)
            {
                float best = float.MaxValue;
                foreach (int t in liveTrackers)
                {
                    float height = averages[t].Position.Y - floor;
                    float score = Math.Abs(height - 0.57f * eyeHeight) + Vectors.HorizontalDistance(averages[t].Position, head.Position);
                    if (height > 0.25f * eyeHeight && score < best) { best = score; pelvis = t; }
                }
                if (pelvis < 0) { detail = "no tracker is at waist height"; return CalibrationError.PelvisNotBetweenHeadAndFeet; }
            }
            foreach (int t in liveTrackers)
            {
                if (t == pelvis) continue;
                float score = FootScore(t, averages, floor, head.Position);
                if (footA < 0 || score < FootScore(footA, averages, floor, head.Position)) { footB = footA; footA = t; }
                else if (footB < 0 || score < FootScore(footB, averages, floor, head.Position)) footB = t;
            }
            if (liveTrackers.Count > 3)
                explanation.Append($"{liveTrackers.Count} trackers are tracked: the one nearest waist height under the head is the pelvis, the two lowest near the body are the feet; the others are ignored. ");
            selection = new DeviceSelection(hmd, handA, handB, pelvis, footA, footB, floor, eyeHeight);
            return CalibrationError.None;
        }

        // Of more than two controllers (a spare one on a desk, listed first), the pair that stands most like the hands of a
        // T-pose: widest apart horizontally, less what they differ in height (twice), how far their mean height is from the
        // shoulders' and how far they are from lying either side of the head. Taken in device order, a spare controller made
        // the calibration impossible ("raise both arms") with nothing to tell why.
        private static (int, int) HandsOfATPose(List<int> controllers, ReadOnlySpan<WindowAverage> averages, Vector3 head, float shoulderHeight)
        {
            int bestA = controllers[0], bestB = controllers[1];
            float best = float.NegativeInfinity;
            for (int i = 0; i < controllers.Count; i++)
                for (int j = i + 1; j < controllers.Count; j++)
                {
                    Vector3 a = averages[controllers[i]].Position, b = averages[controllers[j]].Position;
                    float spread = Vectors.HorizontalDistance(a, b);
                    float astride = Vectors.HorizontalDistance(a, head) + Vectors.HorizontalDistance(b, head) - spread;
                    float score = spread - 2f * Math.Abs(a.Y - b.Y) - Math.Abs(0.5f * (a.Y + b.Y) - shoulderHeight) - astride;
                    if (score > best) { best = score; bestA = controllers[i]; bestB = controllers[j]; }
                }
            return (bestA, bestB);
        }

        /// <summary>
        /// Assigns every role: the controller and the foot tracker farther along the body's <paramref name="right"/> axis
        /// are the right ones. Fails with <see cref="CalibrationError.RoleConflict"/> (both controllers or both feet on one
        /// side) or <see cref="CalibrationError.RuntimeRoleMismatch"/> (a runtime role disagrees with where the device is).
        /// </summary>
        /// <param name="selection">The devices from <see cref="Select"/>.</param>
        /// <param name="averages">Every device's window average.</param>
        /// <param name="right">The body's horizontal right axis (from the body plane).</param>
        /// <param name="roles">Receives the device index of every role when the result is <see cref="CalibrationError.None"/>.</param>
        /// <param name="detail">What failed, for the wearer's message; null on success.</param>
        public CalibrationError AssignSides(in DeviceSelection selection, ReadOnlySpan<WindowAverage> averages, Vector3 right, PerRole<int> roles, out string detail)
        {
            if (roles == null) throw new ArgumentNullException(nameof(roles));
            detail = null;
            // Each device's coordinate along the body's right axis, from the head.
            Vector3 head = averages[selection.Hmd].Position;
            int left = selection.ControllerA, rightHand = selection.ControllerB;
            float xLeft = Vector3.Dot(averages[left].Position - head, right), xRight = Vector3.Dot(averages[rightHand].Position - head, right);
            if (xLeft > xRight) { (left, rightHand) = (rightHand, left); (xLeft, xRight) = (xRight, xLeft); }
            if (xLeft > 0f || xRight < 0f) { detail = "both controllers are on the same side"; return CalibrationError.RoleConflict; }
            int footA = selection.FootA, footB = selection.FootB;
            float xA = Vector3.Dot(averages[footA].Position - head, right), xB = Vector3.Dot(averages[footB].Position - head, right);
            if (xA > xB) { (footA, footB) = (footB, footA); (xA, xB) = (xB, xA); }
            if (xA > xB - 0.05f) { detail = "both foot trackers are on the same side"; return CalibrationError.RoleConflict; }

            var assigned = new PerRole<int>(-1);
            assigned[DeviceRole.Head] = selection.Hmd;
            assigned[DeviceRole.LeftHand] = left;
            assigned[DeviceRole.RightHand] = rightHand;
            assigned[DeviceRole.Pelvis] = selection.Pelvis;
            assigned[DeviceRole.LeftFoot] = footA;
            assigned[DeviceRole.RightFoot] = footB;
            foreach (DeviceRole role in BodyRoles.All)
            {
                DeviceRole runtime = _devices[assigned[role]].RuntimeRole;
                if (runtime != DeviceRole.None && runtime != role)
                {
                    detail = $"{_devices[assigned[role]]} is worn as {role}";
                    return CalibrationError.RuntimeRoleMismatch;
                }
            }
            roles.CopyFrom(assigned);
            return CalibrationError.None;
        }

        // Lower is better: height above the floor plus horizontal distance from the head; trackers the runtime calls feet first.
        private float FootScore(int t, ReadOnlySpan<WindowAverage> averages, float floor, Vector3 head) =>
            averages[t].Position.Y - floor + Vectors.HorizontalDistance(averages[t].Position, head)
            - (_devices[t].RuntimeRole == DeviceRole.LeftFoot || _devices[t].RuntimeRole == DeviceRole.RightFoot ? 100f : 0f);

    }
}
