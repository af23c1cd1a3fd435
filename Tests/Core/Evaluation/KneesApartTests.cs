using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The default knee hint (<see cref="KneeHintModel.OuterOfPelvisAndFoot"/>): where the pelvis's and the foot's flexion
    /// planes disagree, the knee lies near the one that puts it further out. A third of MocapBank kneels: the front knee
    /// straight ahead of its hip with the foot turned against it, the kneeling knee out to the side with the ankle under the
    /// body. The two planes added (the default before) put both knees 11–15 cm inside the wearer's for the whole kneel;
    /// Mixamo, which steps and turns, pays a fraction of a millimetre for the prior. Walk-in offsets for the hands,
    /// simulation seed 1 (Documentation~/solver.md, "Knees and elbows", has the curve over the prior's gain and seeds 1–3).
    /// </summary>
    public class KneesApartTests
    {
        private static readonly HumanoidBone[] Knees = { HumanoidBone.LeftLowerLeg, HumanoidBone.RightLowerLeg };

        // The shipped copy of a shared clip (Tests/Core/Data~, so that CI runs it too), evaluated with the default knee model
        // and with the two planes added.
        private static (EvaluationReport outer, EvaluationReport added) BothModels(string file)
        {
            BvhClip clip = RestConventionTests.Read(TestData.Mocap(file));
            EvaluationReport outer = RestConventionTests.Evaluate(clip, 1, false);
            EvaluationReport added = RestConventionTests.Evaluate(clip, 1, false, KneeHintModel.PelvisAndFoot);
            Assert.That(outer.Profile, Is.Not.Null, outer.CalibrationMessage);
            Assert.That(added.Profile, Is.Not.Null, added.CalibrationMessage);
            return (outer, added);
        }

        [Test]
        public void AKneelingWearersKneesStayWithinTheIssuesBound()
        {
            (EvaluationReport outer, EvaluationReport added) = BothModels("mocapbank_30fps.bvh");
            foreach (HumanoidBone knee in Knees)
            {
                Assert.That(added.JointPositionMm[knee].P95, Is.GreaterThan(120.0), $"{knee}, the planes added: p95 (mm)");
                Assert.That(outer.JointPositionMm[knee].P95, Is.LessThanOrEqualTo(100.0), $"{knee}, the outer plane: p95 (mm)");
            }
            Assert.That(outer.AllJointsMm.Mean, Is.LessThan(added.AllJointsMm.Mean - 2.0), "MPJPE (mm)");
        }

        [Test]
        public void AWalkingWearerPaysLittleForThePrior()
        {
            (EvaluationReport outer, EvaluationReport added) = BothModels("mixamo_fingers_30fps.bvh");
            Assert.That(outer.AllJointsMm.Mean, Is.LessThan(added.AllJointsMm.Mean + 0.5), "MPJPE (mm)");
            foreach (HumanoidBone knee in Knees)
                Assert.That(outer.JointPositionMm[knee].P95, Is.LessThanOrEqualTo(60.0), $"{knee}: p95 (mm)");
        }
    }
}
