using System;
using System.Numerics;

namespace AvatarGo.Core
{
    /// <summary>Which way a knee bends: the one reading of it that the clip conventions and the structural detection share.</summary>
    public static class KneeBend
    {
        /// <summary>A knee counts as bent from this angle between thigh and shin (degrees).</summary>
        public const float BentDegrees = 20f;

        // A hinge axis more than 60° from the hip line counts neither way.
        private const float HingeOnHipLine = 0.5f;

        private static readonly float BentCosine = MathF.Cos(BentDegrees * MathF.PI / 180f);

        /// <summary>
        /// +1 when the knee bends forward, -1 when it bends backward, 0 when it is not bent <see cref="BentDegrees"/> or
        /// more or its hinge axis (the thigh crossed with the shin) lies more than 60° from <paramref name="hipLine"/>, the
        /// unit direction from the left hip to the right. A knee bending forward turns the shin back under the thigh, so its
        /// hinge axis points to the body's right.
        /// </summary>
        public static int Direction(Vector3 hip, Vector3 knee, Vector3 ankle, Vector3 hipLine)
        {
            Vector3 thigh = knee - hip, shin = ankle - knee;
            if (!(thigh.LengthSquared() > 1e-12f && shin.LengthSquared() > 1e-12f)) return 0;
            thigh = Vector3.Normalize(thigh);
            shin = Vector3.Normalize(shin);
            if (Vector3.Dot(thigh, shin) > BentCosine) return 0;
            float along = Vector3.Dot(Vector3.Normalize(Vector3.Cross(thigh, shin)), hipLine);
            return along > HingeOnHipLine ? 1 : along < -HingeOnHipLine ? -1 : 0;
        }
    }
}
