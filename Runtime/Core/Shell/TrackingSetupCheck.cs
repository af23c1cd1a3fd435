using System;
using System.Collections.Generic;

namespace AvatarGo.Core
{
    /// <summary>
    /// Checks the calibrator's tracking setup the way its inspector shows it: is there a source, and does the source
    /// track in the XR rig's space when the scene has an XR Origin. Engine-free, like <see cref="AvatarSetupCheck"/>: the
    /// inspector fills <see cref="TrackingSetupFacts"/> and draws the findings.
    /// </summary>
    public static class TrackingSetupCheck
    {
        /// <summary>The message when no source is assigned.</summary>
        public const string NoSource = "No tracking source is assigned: the calibrator reads no devices and disables itself. Assign Source (the prefab's Tracking child carries an XR Input Devices Tracking Source) or add a tracking source component and assign it.";

        /// <summary>The message when an XR Origin exists but the source's origin is empty and nothing will set it.</summary>
        public const string OriginNotConnected = "The scene has an XR Origin, but the source's Tracking Space Origin is empty: the devices are placed in world coordinates, so the avatar drifts from the rig as soon as the rig moves or its camera offset lifts the camera. Connect it (adds an XR Origin Tracking Setup, which uses the origin's Camera Offset).";

        /// <summary>The message when an XR Origin Tracking Setup will set the origin on <c>Start</c>.</summary>
        public const string OriginSetOnStart = "The source's Tracking Space Origin is empty; its XR Origin Tracking Setup sets it to the XR Origin's Camera Offset on Start.";

        /// <summary>The message when there is no XR Origin and no tracking-space origin.</summary>
        public const string WorldSpace = "The source's Tracking Space Origin is empty: the devices are placed in world coordinates (floor at y = 0). Assign the XR rig's camera offset if the rig is moved in the scene.";

        /// <summary>Checks <paramref name="facts"/>; errors first, then warnings, then information.</summary>
        public static IReadOnlyList<SetupFinding> Check(TrackingSetupFacts facts)
        {
            if (facts == null) throw new ArgumentNullException(nameof(facts));
            var findings = new List<SetupFinding>();
            if (!facts.HasSource)
                findings.Add(new SetupFinding(SetupSeverity.Error, NoSource));
            else if (!facts.HasTrackingSpaceOrigin)
            {
                if (facts.HasXROriginTrackingSetup) findings.Add(new SetupFinding(SetupSeverity.Info, OriginSetOnStart));
                else if (facts.SceneHasXROrigin) findings.Add(new SetupFinding(SetupSeverity.Warning, OriginNotConnected, SetupFix.ConnectXROrigin));
                else findings.Add(new SetupFinding(SetupSeverity.Info, WorldSpace));
            }
            return findings;
        }
    }
}
