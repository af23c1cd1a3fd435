using System.Numerics;
using NUnit.Framework;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// The sample gate's speed limits are the documented ones at every frame rate (found in review: a frame's worth of
    /// time added to every interval made 20 m/s and 3000 °/s into 40 m/s and 6000 °/s at 90 Hz, 52 m/s at 144 Hz).
    /// </summary>
    public class SampleSanitizerTests
    {
        // One device moving steadily for `seconds`, sampled at `rate`: how many samples are rejected.
        private static int Rejected(int rate, double seconds, System.Func<double, RigidPose> poseAt)
        {
            var sanitizer = new SampleSanitizer(1, 0, new[] { -1f }, new TrackingSettings());
            var samples = new DeviceSample[1];
            var accepted = new DeviceSample[1];
            int rejected = 0;
            for (int i = 0; i <= (int)(rate * seconds); i++)
            {
                double t = i / (double)rate;
                samples[0] = new DeviceSample(poseAt(t), true);
                rejected += sanitizer.Filter(t, samples, accepted);
            }
            return rejected;
        }

        private static RigidPose Moving(double metresPerSecond, double t) => new RigidPose(new Vector3((float)(metresPerSecond * t), 1.6f, 0f), Quaternion.Identity);

        private static RigidPose Turning(double degreesPerSecond, double t) => new RigidPose(new Vector3(0f, 1.6f, 0f), Rotations.AngleAxis((float)(degreesPerSecond * t), Vector3.UnitY));

        [TestCase(30), TestCase(90), TestCase(144)]
        public void ASpeedOverTheLimitIsRejectedAndOneUnderItIsNotAtEveryFrameRate(int rate)
        {
            // 26 m/s and 4000 °/s: 30 % over the limits (20 m/s, 3000 °/s); 15 m/s and 2250 °/s: 25 % under them.
            // Every sample after the first is a jump, and none is taken back (that takes 0.5 s): over 0.1 s, and over 0.04 s
            // for the turn (160°: the angle between two rotations is at most 180°).
            Assert.That(Rejected(rate, 0.1, t => Moving(26, t)), Is.EqualTo((int)(rate * 0.1)), "26 m/s");
            Assert.That(Rejected(rate, 0.04, t => Turning(4000, t)), Is.EqualTo((int)(rate * 0.04)), "4000 °/s");
            Assert.That(Rejected(rate, 1.0, t => Moving(15, t)), Is.EqualTo(0), "15 m/s");
            Assert.That(Rejected(rate, 1.0, t => Turning(2250, t)), Is.EqualTo(0), "2250 °/s");
        }

        [Test]
        public void ASampleWithTheSameTimestampIsNoJumpForTheDevicesNoise()
        {
            var sanitizer = new SampleSanitizer(1, 0, new[] { -1f }, new TrackingSettings());
            var accepted = new DeviceSample[1];
            Assert.That(sanitizer.Filter(1.0, new[] { new DeviceSample(Moving(0, 0), true) }, accepted), Is.EqualTo(0));
            var moved = new RigidPose(new Vector3(0.005f, 1.6f, 0f), Rotations.AngleAxis(0.5f, Vector3.UnitX));
            Assert.That(sanitizer.Filter(1.0, new[] { new DeviceSample(moved, true) }, accepted), Is.EqualTo(0), "5 mm and 0.5° at the same time");
            var jumped = new RigidPose(new Vector3(0.1f, 1.6f, 0f), Quaternion.Identity);
            Assert.That(sanitizer.Filter(1.0, new[] { new DeviceSample(jumped, true) }, accepted), Is.EqualTo(1), "10 cm at the same time");
        }

        [Test]
        public void WithTheFramesStepAFrameWithoutTimeCarriesOneFramesMotion()
        {
            var sanitizer = new SampleSanitizer(1, 0, new[] { -1f }, new TrackingSettings());
            var accepted = new DeviceSample[1];
            Assert.That(sanitizer.Filter(1.0, 1 / 90.0, new[] { new DeviceSample(Moving(0, 0), true) }, accepted), Is.EqualTo(0));
            // 5 cm in a frame stamped at the same time: 4.5 m/s at 90 Hz, a hand's swing.
            var swung = new RigidPose(new Vector3(0.05f, 1.6f, 0f), Quaternion.Identity);
            Assert.That(sanitizer.Filter(1.0, 1 / 90.0, new[] { new DeviceSample(swung, true) }, accepted), Is.EqualTo(0), "one frame's motion");
            // 40 cm is beyond 20 m/s over one frame (22 cm + 2 cm).
            var jumped = new RigidPose(new Vector3(0.45f, 1.6f, 0f), Quaternion.Identity);
            Assert.That(sanitizer.Filter(1.0, 1 / 90.0, new[] { new DeviceSample(jumped, true) }, accepted), Is.EqualTo(1), "a jump");
        }
    }
}
