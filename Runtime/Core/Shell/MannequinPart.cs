using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>One primitive of a <see cref="MannequinBlueprint"/>, in the frame of the joint that carries it.</summary>
    public readonly struct MannequinPart
    {
        /// <summary>Creates a part.</summary>
        public MannequinPart(int joint, MannequinShape shape, Vector3 centre, Quaternion rotation, float length, float radius)
        {
            Joint = joint;
            Shape = shape;
            Centre = centre;
            Rotation = rotation;
            Length = length;
            Radius = radius;
        }

        /// <summary>The index in <see cref="MannequinBlueprint.Joints"/> of the joint the part moves with.</summary>
        public int Joint { get; }

        /// <summary>The part's shape.</summary>
        public MannequinShape Shape { get; }

        /// <summary>The part's centre in the joint's frame.</summary>
        public Vector3 Centre { get; }

        /// <summary>The part's rotation in the joint's frame (a capsule's axis is this rotation's +Y).</summary>
        public Quaternion Rotation { get; }

        /// <summary>The length along the axis in metres (a segment's length; a sphere's diameter).</summary>
        public float Length { get; }

        /// <summary>The radius in metres.</summary>
        public float Radius { get; }

        /// <summary>
        /// The local scale that gives Unity's built-in primitive this size: the capsule mesh is 2 tall with radius 0.5
        /// along +Y, the sphere mesh has radius 0.5.
        /// </summary>
        public Vector3 PrimitiveScale => Shape == MannequinShape.Sphere
            ? new Vector3(2f * Radius)
            : new Vector3(2f * Radius, 0.5f * Length, 2f * Radius);
    }
}
