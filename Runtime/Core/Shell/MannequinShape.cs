namespace AvatarGo.Core
{
    /// <summary>The primitive shapes of a mannequin.</summary>
    public enum MannequinShape
    {
        /// <summary>A capsule along its local +Y axis, <see cref="MannequinPart.Length"/> long from cap to cap.</summary>
        Capsule,
        /// <summary>A sphere of <see cref="MannequinPart.Radius"/>.</summary>
        Sphere,
    }
}
