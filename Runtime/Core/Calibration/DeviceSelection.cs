namespace AvatarGo.Core
{
    /// <summary>
    /// The six devices a T-pose uses, before left and right are known (<see cref="DeviceIdentifier.Select"/>): the HMD,
    /// two controllers, the pelvis tracker and two foot trackers, as indices into the device list; and the floor and eye
    /// height they give.
    /// </summary>
    public readonly struct DeviceSelection
    {
        /// <summary>The HMD.</summary>
        public readonly int Hmd;

        /// <summary>One controller (which hand is decided by <see cref="DeviceIdentifier.AssignSides"/>).</summary>
        public readonly int ControllerA;

        /// <summary>The other controller.</summary>
        public readonly int ControllerB;

        /// <summary>The tracker at waist height.</summary>
        public readonly int Pelvis;

        /// <summary>One foot tracker.</summary>
        public readonly int FootA;

        /// <summary>The other foot tracker.</summary>
        public readonly int FootB;

        /// <summary>The floor height in tracking space (metres).</summary>
        public readonly float Floor;

        /// <summary>The wearer's eye height above the floor (metres): the HMD's.</summary>
        public readonly float EyeHeight;

        /// <summary>Creates a selection.</summary>
        public DeviceSelection(int hmd, int controllerA, int controllerB, int pelvis, int footA, int footB, float floor, float eyeHeight)
        {
            Hmd = hmd;
            ControllerA = controllerA;
            ControllerB = controllerB;
            Pelvis = pelvis;
            FootA = footA;
            FootB = footB;
            Floor = floor;
            EyeHeight = eyeHeight;
        }

        /// <summary>The six device indices: HMD, controllers, pelvis, feet.</summary>
        public int this[int i] => i switch { 0 => Hmd, 1 => ControllerA, 2 => ControllerB, 3 => Pelvis, 4 => FootA, 5 => FootB, _ => throw new System.ArgumentOutOfRangeException(nameof(i)) };
    }
}
