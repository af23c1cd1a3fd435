using System;

namespace AvatarGo.Core
{
    /// <summary>What happened to the refinement exercise in a frame, as <see cref="RefinementFlow"/> reports it (any combination).</summary>
    [Flags]
    public enum RefinementFlowEvents
    {
        /// <summary>Nothing.</summary>
        None = 0,

        /// <summary>The exercise started (<see cref="SelfAvatarPipeline.BeginRefinement"/> was called).</summary>
        Began = 1 << 0,

        /// <summary>The pipeline refused to start it (<see cref="RefinementFlow.Explanation"/> says why); the calibration stays as it is.</summary>
        BeginRefused = 1 << 1,

        /// <summary>A trigger press came too early to end the exercise, or from a device that is not a controller (<see cref="RefinementFlow.Explanation"/>).</summary>
        PressIgnored = 1 << 2,

        /// <summary>The exercise ended and was applied (<see cref="SelfAvatarPipeline.EndRefinement"/>); <see cref="RefinementFlow.LastReport"/> is its report.</summary>
        Ended = 1 << 3,

        /// <summary>With <see cref="Ended"/>: the arms changed, so the pipeline has a new scaled avatar, pose and offsets.</summary>
        ArmsChanged = 1 << 4,

        /// <summary>With <see cref="Ended"/>: the calibration changed and is ready to be saved again.</summary>
        SaveProfile = 1 << 5,

        /// <summary>The exercise was dropped without being applied (a reset, new devices, a restored profile, or the pipeline's recording ended elsewhere).</summary>
        Cancelled = 1 << 6,
    }
}
