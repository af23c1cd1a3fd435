namespace AvatarGo.Core
{
    /// <summary>Where the calibrator's refinement exercise is (<see cref="RefinementFlow"/>).</summary>
    public enum RefinementPhase
    {
        /// <summary>No exercise: off, not started yet, or its summary has been shown.</summary>
        Idle = 0,

        /// <summary>The wearer is doing the exercise; the pipeline records it (<see cref="SelfAvatarPipeline.IsRefining"/>).</summary>
        Exercising = 1,

        /// <summary>The exercise ended and was applied; its summary is shown for <see cref="RefinementFlow.SummarySeconds"/>.</summary>
        Summary = 2,
    }
}
