using System;

namespace AvatarGo.Core
{
    /// <summary>
    /// Steadies a limb held straight. Near full reach the middle joint's distance from the root-to-end line grows with the
    /// square root of the slack (reach − distance), so the devices' noise in that distance (1.4 mm with 1 mm devices) moves
    /// a straight knee or elbow by centimetres a frame where the wearer's hardly moves. The limb bends for this distance
    /// instead: the root-to-end distance through a One Euro filter (<see cref="DistanceFilter"/>: a cutoff that rises with
    /// the distance's speed, so a limb that bends or straightens lags little), used in full at and beyond full reach and
    /// blending to the distance itself at a share of the reach short of it (<see cref="LegGateOfReach"/>,
    /// <see cref="ArmGateOfReach"/>), where the middle joint moves no more than 2.2 (1.6) times the distance's change; and
    /// a soft reach (<see cref="SoftZoneOfReach"/>) so that what noise the filter leaves cannot swing a middle
    /// joint at full reach, where its slope has no bound. A leg's foot lands at the filtered distance; an arm's clavicle takes
    /// up the difference (<see cref="FullBodyIk.StraightArmCutoffHz"/>). Time-based (frame-rate independent); allocation-free.
    /// </summary>
    internal sealed class LimbReachFilter
    {
        /// <summary>
        /// Where a leg's filter fades out, as a share of its reach (1/40: 22 mm for a 0.9 m leg): for two bones of length l
        /// the middle joint lies about sqrt(l s) off the line at slack s, so it moves sqrt(l / s) / 2 times as far as the slack
        /// changes, 2.2 times at s = l / 20, and more the straighter the limb. The foot lands at the filtered distance, so
        /// a wider gate lags the foot in more of a step (1/20 measured: Mixamo's end effectors 0.1 mm further at the median,
        /// 0.3 mm at p95).
        /// </summary>
        public const float LegGateOfReach = 1f / 40f;

        /// <summary>
        /// Where an arm's filter fades out (1/20: 28 mm for a 0.55 m arm, the elbow moving 1.6 times the slack's change
        /// there). The clavicle takes up what the filter takes out and the hand stays on its goal, so the arm's gate is
        /// wider than the leg's (measured against 1/40: elbow jumps over 10 mm on MocapBank 1.3–1.7 → 0.5–0.9 % of frames, the
        /// hands and MPJPE within 0.02 mm).
        /// </summary>
        public const float ArmGateOfReach = 1f / 20f;

        /// <summary>
        /// The soft reach's zone either side of full reach, as a share of the limb's reach (1/450: 2 mm for a 0.9 m leg, a few
        /// times the filtered distance's own noise, 0.3–0.5 mm with 1 mm devices; a share, so that it bends every straight
        /// leg by the same angle whatever the body's size): the knee then moves at most sqrt(l / S) / 2 times the distance's
        /// change (7.5 times for 0.45 m bones, against 21 times at 1 mm of slack and without bound at none), and a leg held
        /// straight is bent by sqrt(l S) / 2 (15 mm at the knee, 4°), its foot at most S / 4 (0.5 mm) short of its target.
        /// </summary>
        private const float SoftZoneOfReach = 1f / 450f;

        private readonly float _reach;              // the limb's full reach: its two bones' lengths
        private readonly float _gate;               // where the filter fades out, as a share of the reach
        private readonly DistanceFilter _distance = new DistanceFilter();

        /// <summary>
        /// A filter for a limb whose two bones together are <paramref name="reach"/> long (metres), fading out
        /// <paramref name="gateOfReach"/> of that reach short of full reach.
        /// </summary>
        public LimbReachFilter(float reach, float gateOfReach)
        {
            _reach = reach;
            _gate = gateOfReach;
        }

        /// <summary>Forgets the history (the end was lost, or the solve starts over): the next distance is taken as it is.</summary>
        public void Reset() => _distance.Reset();

        /// <summary>
        /// The distance the limb is to bend for, this frame <paramref name="deltaSeconds"/> after the previous one (0: a
        /// repeated frame, which filters nothing) with cutoff <paramref name="cutoffHz"/> for a still limb. A distance that is
        /// not finite (or a reach that is not finite and positive) is returned as it is and leaves the history alone.
        /// </summary>
        public float Filter(float distance, float deltaSeconds, float cutoffHz)
        {
            float reach = _reach;
            if (!(distance >= 0f && distance < float.PositiveInfinity && reach > 0f && reach < float.PositiveInfinity)) return distance;
            float filtered = _distance.Filter(distance, deltaSeconds, cutoffHz);
            float weight = Math.Max(0f, Math.Min(1f, 1f - (reach - distance) / (reach * _gate)));
            float used = distance + weight * (filtered - distance);
            // The soft reach: within S of full reach the slack s becomes (s + S)² / 4S, so the middle joint's slope stays finite
            // there (its offset grew as the square root of the slack) and the filter's residual noise cannot swing it by
            // centimetres; 0 from S beyond full reach on.
            float slack = reach - used, soft = reach * SoftZoneOfReach;
            if (slack < soft) used = reach - (slack > -soft ? (slack + soft) * (slack + soft) / (4f * soft) : 0f);
            return used;
        }
    }
}
