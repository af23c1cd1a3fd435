using System;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The error the headset-free sample shows is the evaluator's: measured frame by frame on the pipeline's own solve of a
    /// synthetic session, its running means equal the report's MPJPE, end-effector and mid-joint means; and measuring
    /// allocates nothing.
    /// </summary>
    public class TruthErrorMeterTests
    {
        [TestCase("mocapbank_30fps.bvh", OffsetMode.Exact)]
        [TestCase("mixamo_fingers_30fps.bvh", OffsetMode.Fixed)]
        public void TheLiveMeansAreTheEvaluatorsMeans(string clip, OffsetMode mode)
        {
            string session = Sessions.Simulate(clip, new SimulationOptions { Seed = 11 });
            var meter = new TruthErrorMeter();
            double largestFrameMean = 0;
            using SessionReader reader = Sessions.Read(session);
            EvaluationReport report = SessionEvaluator.EvaluateWithTruth(reader, new PipelineSettings { Offsets = mode }, null, (p, f) =>
            {
                Assert.That(meter.Measure(p.ScaledAvatar, p.Pose, f, p.State), Is.True, "every solved frame of a synthetic session has truth");
                largestFrameMean = Math.Max(largestFrameMean, meter.LastMeanMm);
            });
            Assert.That(meter.Frames, Is.EqualTo(report.Frames));
            Assert.That(meter.MeanMm, Is.EqualTo(report.AllJointsMm.Mean).Within(1e-9).Percent);
            Assert.That(meter.MeanEndEffectorMm, Is.EqualTo(report.EndEffectorMm.Mean).Within(1e-9).Percent);
            Assert.That(meter.MeanMidJointMm, Is.EqualTo(report.MidJointMm.Mean).Within(1e-9).Percent);
            Assert.That(largestFrameMean, Is.GreaterThanOrEqualTo(meter.MeanMm));
            meter.Reset();
            Assert.That(meter.MeanMm, Is.NaN);
            Assert.That(meter.Frames, Is.Zero);
        }

        [Test]
        public void NothingIsMeasuredBeforeCalibrationOrWithoutTruth()
        {
            string session = Sessions.Simulate("mocapbank_30fps.bvh", new SimulationOptions { Seed = 2 });
            var meter = new TruthErrorMeter();
            int allocatedFrames = 0;
            long allocated = 0;
            Sessions.Replay(session, null, (i, p, f) =>
            {
                if (p.State != CalibrationState.Calibrated)
                {
                    Assert.That(meter.Measure(p.Avatar, p.Pose, f, p.State), Is.False);
                    return;
                }
                long before = GC.GetAllocatedBytesForCurrentThread();
                meter.Measure(p.ScaledAvatar, p.Pose, f, p.State);
                // The first measured frame initialises the meter's static tables; every later one must allocate nothing.
                if (meter.Frames > 1) { allocated += GC.GetAllocatedBytesForCurrentThread() - before; allocatedFrames++; }
                Array.Clear(f.HasTruth, 0, f.HasTruth.Length);
                Assert.That(meter.Measure(p.ScaledAvatar, p.Pose, f, p.State), Is.False, "a frame without truth");
            });
            Assert.That(allocatedFrames, Is.GreaterThan(100));
            Assert.That(allocated, Is.Zero, "bytes allocated by Measure after its first frame");
            Assert.That(meter.MeanMm, Is.GreaterThan(0).And.LessThan(60));
        }
    }
}
