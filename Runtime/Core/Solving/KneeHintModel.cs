namespace AvatarGo.Core
{
    /// <summary>
    /// Which way the knees bend (the knee hint of <see cref="BodyTargetMapper"/>): the swivel of the knee about the hip-to-ankle
    /// axis, which the six devices do not observe. Documentation~/solver.md compares them on recorded motion.
    /// </summary>
    public enum KneeHintModel
    {
        /// <summary>
        /// The pelvis's and the foot's flexion planes added. The pelvis's: square to the hip-to-ankle axis and
        /// to the pelvis tracker's hip line (the way the hip flexes); the foot's: square to that axis and to the foot
        /// tracker's lateral axis (the ankle's flexion axis, toward the toes whatever their pitch). Each is weighted by how
        /// square its lateral axis is to the leg, so either takes over where the other's lateral axis lies along the leg.
        /// </summary>
        PelvisAndFoot = 0,

        /// <summary>In the pelvis's flexion plane alone (square to the leg's axis and to the hip line).</summary>
        Pelvis = 1,

        /// <summary>In the foot's flexion plane alone (square to the leg's axis and to the foot tracker's lateral axis).</summary>
        Foot = 2,

        /// <summary>
        /// Toward the toes: the foot's current toe direction off the leg's axis, with the pelvis's flexion plane (weight
        /// <see cref="BodyTargetMapper.FallbackWeight"/>, fading where the leg lies within 15° of the hip line) where the toes
        /// point along the leg.
        /// </summary>
        Toes = 3,

        /// <summary>
        /// The shin stays in the foot's sagittal plane (the ankle is a hinge about the foot's lateral axis, and the knee's
        /// axial rotation turns the thigh, not the shin, against the foot): the knee is where that plane meets the circle of
        /// knees the hip and ankle allow, of the two the one nearer the pelvis's flexion plane (which also takes over where
        /// the foot's lateral axis lies along the leg).
        /// </summary>
        AnkleHinge = 4,

        /// <summary>
        /// The first implementation: where the knee was relative to the foot at calibration, pushed one leg length forward,
        /// carried by the foot tracker (it rolls with the foot, and flipped with a rest pose whose feet do not lie flat).
        /// </summary>
        CalibrationFrame = 5,

        /// <summary>
        /// The default: the pelvis's and the foot's flexion planes (as <see cref="PelvisAndFoot"/>), the one that puts the
        /// knee further out weighted most (<see cref="BodyTargetMapper.OuterPlaneGain"/>): where the two disagree, the hip has
        /// turned the thigh or the shin has turned against the foot, and a knee kneeling, squatting or lunging lies near the
        /// outer of the two planes, not between them. Equally far out (most of walking), they are added, as in
        /// <see cref="PelvisAndFoot"/>.
        /// </summary>
        OuterOfPelvisAndFoot = 6,
    }
}
