namespace AvatarGo.Core
{
    /// <summary>
    /// The humanoid bones, with the same names and numeric values as Unity's <c>HumanBodyBones</c>
    /// so the Unity shell can cast between them.
    /// </summary>
    public enum HumanoidBone
    {
        /// <summary>The hips: the root of the humanoid hierarchy.</summary>
        Hips = 0,
        /// <summary>The left upper leg bone.</summary>
        LeftUpperLeg = 1,
        /// <summary>The right upper leg bone.</summary>
        RightUpperLeg = 2,
        /// <summary>The left knee.</summary>
        LeftLowerLeg = 3,
        /// <summary>The right knee.</summary>
        RightLowerLeg = 4,
        /// <summary>The left ankle.</summary>
        LeftFoot = 5,
        /// <summary>The right ankle.</summary>
        RightFoot = 6,
        /// <summary>The first spine bone above the hips.</summary>
        Spine = 7,
        /// <summary>The chest bone.</summary>
        Chest = 8,
        /// <summary>The neck bone.</summary>
        Neck = 9,
        /// <summary>The head bone.</summary>
        Head = 10,
        /// <summary>The left shoulder bone.</summary>
        LeftShoulder = 11,
        /// <summary>The right shoulder bone.</summary>
        RightShoulder = 12,
        /// <summary>The left upper arm bone.</summary>
        LeftUpperArm = 13,
        /// <summary>The right upper arm bone.</summary>
        RightUpperArm = 14,
        /// <summary>The left elbow.</summary>
        LeftLowerArm = 15,
        /// <summary>The right elbow.</summary>
        RightLowerArm = 16,
        /// <summary>The left wrist.</summary>
        LeftHand = 17,
        /// <summary>The right wrist.</summary>
        RightHand = 18,
        /// <summary>The left toes bone.</summary>
        LeftToes = 19,
        /// <summary>The right toes bone.</summary>
        RightToes = 20,
        /// <summary>The left eye bone.</summary>
        LeftEye = 21,
        /// <summary>The right eye bone.</summary>
        RightEye = 22,
        /// <summary>The jaw bone.</summary>
        Jaw = 23,
        /// <summary>The left thumb proximal bone.</summary>
        LeftThumbProximal = 24,
        /// <summary>The left thumb intermediate bone.</summary>
        LeftThumbIntermediate = 25,
        /// <summary>The left thumb distal bone.</summary>
        LeftThumbDistal = 26,
        /// <summary>The left index proximal bone.</summary>
        LeftIndexProximal = 27,
        /// <summary>The left index intermediate bone.</summary>
        LeftIndexIntermediate = 28,
        /// <summary>The left index distal bone.</summary>
        LeftIndexDistal = 29,
        /// <summary>The left middle proximal bone.</summary>
        LeftMiddleProximal = 30,
        /// <summary>The left middle intermediate bone.</summary>
        LeftMiddleIntermediate = 31,
        /// <summary>The left middle distal bone.</summary>
        LeftMiddleDistal = 32,
        /// <summary>The left ring proximal bone.</summary>
        LeftRingProximal = 33,
        /// <summary>The left ring intermediate bone.</summary>
        LeftRingIntermediate = 34,
        /// <summary>The left ring distal bone.</summary>
        LeftRingDistal = 35,
        /// <summary>The left little proximal bone.</summary>
        LeftLittleProximal = 36,
        /// <summary>The left little intermediate bone.</summary>
        LeftLittleIntermediate = 37,
        /// <summary>The left little distal bone.</summary>
        LeftLittleDistal = 38,
        /// <summary>The right thumb proximal bone.</summary>
        RightThumbProximal = 39,
        /// <summary>The right thumb intermediate bone.</summary>
        RightThumbIntermediate = 40,
        /// <summary>The right thumb distal bone.</summary>
        RightThumbDistal = 41,
        /// <summary>The right index proximal bone.</summary>
        RightIndexProximal = 42,
        /// <summary>The right index intermediate bone.</summary>
        RightIndexIntermediate = 43,
        /// <summary>The right index distal bone.</summary>
        RightIndexDistal = 44,
        /// <summary>The right middle proximal bone.</summary>
        RightMiddleProximal = 45,
        /// <summary>The right middle intermediate bone.</summary>
        RightMiddleIntermediate = 46,
        /// <summary>The right middle distal bone.</summary>
        RightMiddleDistal = 47,
        /// <summary>The right ring proximal bone.</summary>
        RightRingProximal = 48,
        /// <summary>The right ring intermediate bone.</summary>
        RightRingIntermediate = 49,
        /// <summary>The right ring distal bone.</summary>
        RightRingDistal = 50,
        /// <summary>The right little proximal bone.</summary>
        RightLittleProximal = 51,
        /// <summary>The right little intermediate bone.</summary>
        RightLittleIntermediate = 52,
        /// <summary>The right little distal bone.</summary>
        RightLittleDistal = 53,
        /// <summary>The upper chest bone.</summary>
        UpperChest = 54,
        /// <summary>Not a bone: the number of values above, as Unity's <c>HumanBodyBones.LastBone</c>.</summary>
        LastBone = 55,
    }
}
