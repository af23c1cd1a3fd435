namespace AvatarGo.Core
{
    /// <summary>What the fingers do with the controller.</summary>
    public enum GripMode
    {
        /// <summary>All fingers closed on the controller; thumb on its rest, index on the trigger.</summary>
        Hold = 0,

        /// <summary>All fingers open: the pose the hand model was built from (in the pipeline the calibration T-pose's relaxed fingers).</summary>
        Open = 1,

        /// <summary>Index finger pointing, the others holding.</summary>
        Point = 2,

        /// <summary>Driven by the controller's analog values: grip closes middle, ring, little and thumb; trigger closes the index.</summary>
        InputDriven = 3,
    }
}
