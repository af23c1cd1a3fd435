namespace AvatarGo.Core
{
    /// <summary>What the calibrator's inspector reads from the scene about the tracking setup, for <see cref="TrackingSetupCheck"/>.</summary>
    public sealed class TrackingSetupFacts
    {
        /// <summary>The calibrator has a tracking source assigned.</summary>
        public bool HasSource { get; set; }

        /// <summary>The source's Tracking Space Origin is set.</summary>
        public bool HasTrackingSpaceOrigin { get; set; }

        /// <summary>The scene has an XR Origin (<c>Unity.XR.CoreUtils.XROrigin</c>; false when XR Core Utilities is not installed).</summary>
        public bool SceneHasXROrigin { get; set; }

        /// <summary>An XR Origin Tracking Setup on the source's object sets the source's origin on <c>Awake</c>.</summary>
        public bool HasXROriginTrackingSetup { get; set; }
    }
}
