using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using AvatarGo.Simulation;

namespace AvatarGo.Core.Tests
{
    /// <summary>
    /// Which trigger presses run a calibration step: one step per frame and per averaging window (the walk-in can never be
    /// skipped), only a controller's trigger unless a setting says otherwise, and an untracked HMD named as such whatever
    /// the device order.
    /// </summary>
    public class TriggerRulesTests
    {
        private static readonly DeviceEvent[] None = new DeviceEvent[0];

        // Stands the mocapbank wearer in T-pose and feeds frames at 90 Hz; `events(frame)` gives each frame's events.
        private static Calibrator Run(Func<int, IReadOnlyList<DeviceEvent>> events, int frames, CalibrationSettings settings = null,
            Func<Wearer, IReadOnlyList<DeviceInfo>> devices = null, Action<DeviceSample[]> samples = null, Func<int, double> time = null)
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 11, DeviceMountings.Default());
            wearer.StandInTPose(RigidPose.Identity);
            IReadOnlyList<DeviceInfo> list = devices?.Invoke(wearer) ?? wearer.Devices;
            var calibrator = new Calibrator(list, wearer.Map, settings);
            var truth = new DeviceSample[wearer.Devices.Length];
            var fed = new DeviceSample[list.Count];
            for (int i = 0; i < frames; i++)
            {
                wearer.Sample(truth, 0.001f, 0.1f);
                samples?.Invoke(truth);
                for (int d = 0; d < fed.Length; d++) fed[d] = truth[Array.IndexOf(wearer.Devices, list[d])];
                calibrator.Update(time != null ? time(i) : i / 90.0, fed, events(i));
            }
            return calibrator;
        }

        private static DeviceEvent Press(int deviceId) => new DeviceEvent(deviceId, DeviceEventKind.TriggerPressed);

        // Wearer's device ids: 1 and 2 are the controllers, 0 the HMD, 4, 7 and 9 the trackers.
        [Test]
        public void BothTriggersInOneFrameRunOneStep()
        {
            Calibrator c = Run(i => i == 89 ? new[] { Press(1), Press(2) } : None, 400);
            Assert.That(c.State, Is.EqualTo(CalibrationState.WalkIn), "the second press of the frame must not compute the offsets");
            // The step that ran is what the frame did (found in review: the ignored press replaced it, so the flow never
            // announced the T-pose, nor saved the calibration at the walk-in); the ignored press is told in its explanation.
            Assert.That(c.LastStep.Outcome, Is.EqualTo(CalibrationStepOutcome.Advanced));
            Assert.That(c.LastStep.Explanation, Does.Contain("same frame"));
        }

        /// <summary>
        /// Both triggers pressed together at each step, as wearers do: the flow sees the T-pose accepted and the calibration
        /// to save, as with one trigger.
        /// </summary>
        [Test]
        public void BothTriggersAtEachStepAreAnnouncedAndSaved()
        {
            var wearer = new Wearer("mocapbank_30fps.bvh", 11, DeviceMountings.Default());
            var pipeline = new SelfAvatarPipeline(wearer.Devices, wearer.Map);
            var flow = new CalibrationFlow();
            var samples = new DeviceSample[6];
            var both = new List<DeviceEvent> { new DeviceEvent(1, DeviceEventKind.TriggerPressed), new DeviceEvent(2, DeviceEventKind.TriggerPressed) };
            var seen = CalibrationFlowEvents.None;
            double t = 0;
            void Hold()
            {
                for (int i = 0; i < 90; i++)
                {
                    wearer.Sample(samples, 0.001f, 0.1f);
                    t += 1.0 / 90;
                    CalibrationStep step = pipeline.Update(t, samples, default, default, i == 89 ? both : null);
                    seen |= flow.Update(t, step, pipeline.State);
                }
            }
            wearer.StandInTPose(RigidPose.Identity);
            Hold();
            wearer.StandInTPose(pipeline.Profile.Placement);
            Hold();
            Assert.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated));
            Assert.That(seen & CalibrationFlowEvents.TPoseAccepted, Is.EqualTo(CalibrationFlowEvents.TPoseAccepted), seen.ToString());
            Assert.That(seen & CalibrationFlowEvents.SaveProfile, Is.EqualTo(CalibrationFlowEvents.SaveProfile), seen.ToString());
            Assert.That(pipeline.LastCalibrationStep.Explanation, Does.Contain("same frame"));
        }

        [Test]
        public void TheOtherTriggerAFrameLaterDoesNotSkipTheWalkIn()
        {
            // Two hands pressing almost together: the second press lands within the averaging window of the first step.
            Calibrator c = Run(i => i == 89 ? new[] { Press(1) } : i == 91 ? new[] { Press(2) } : None, 400);
            Assert.That(c.State, Is.EqualTo(CalibrationState.WalkIn));
            Assert.That(c.LastStep.Explanation, Does.Contain("after the previous step"));
        }

        [Test]
        public void APressAWindowLaterRunsTheWalkInStep()
        {
            // The control: the same wearer pressing again once the window has passed is calibrated.
            Calibrator c = Run(i => i == 89 || i == 180 ? new[] { Press(2) } : None, 200);
            Assert.That(c.State, Is.EqualTo(CalibrationState.Calibrated), c.LastStep.ToString());
        }

        /// <summary>
        /// Frames without a time (NaN) are frames in which no time passed, for the calibrator too: the other trigger a frame
        /// after the T-pose's press does not skip the walk-in (found in review: NaN made the half-second rule and the
        /// averaging window never apply, and the calibrator ended calibrated without a walk-in); a clock that never gives a
        /// time measures nothing and calibrates nothing.
        /// </summary>
        [Test]
        public void FramesWithoutATimeDoNotLetASecondPressSkipTheWalkIn()
        {
            Calibrator c = Run(i => i == 89 ? new[] { Press(1) } : i == 90 ? new[] { Press(2) } : None, 120, time: i => i < 80 ? i / 90.0 : double.NaN);
            Assert.That(c.State, Is.EqualTo(CalibrationState.WalkIn), c.LastStep.ToString());
            Assert.That(c.LastStep.Explanation, Does.Contain("after the previous step"));

            // With no time at all nothing is measured over the half second: the T-pose's press asks the wearer to hold still.
            Calibrator never = Run(i => i == 89 ? new[] { Press(1) } : i == 90 ? new[] { Press(2) } : None, 120, time: i => double.NaN);
            Assert.That(never.State, Is.EqualTo(CalibrationState.WaitingForTPose), never.LastStep.ToString());
            Assert.That(never.LastStep.Error, Is.EqualTo(CalibrationError.DevicesMoving));
        }

        /// <summary>
        /// A clock that restarts after the T-pose's press (a replay started again, a runtime that reset its clock) does not
        /// ignore the walk-in's press (found in review: "came -981.00 s after the previous step" until the clock passed its
        /// old time).
        /// </summary>
        [Test]
        public void AClockThatRestartsDoesNotIgnoreTheNextPress()
        {
            Calibrator c = Run(i => i == 89 || i == 300 ? new[] { Press(2) } : None, 320, time: i => i < 100 ? 1000.0 + i / 90.0 : (i - 100) / 90.0);
            Assert.That(c.State, Is.EqualTo(CalibrationState.Calibrated), c.LastStep.ToString());
        }

        [Test]
        public void APressFromATrackerOrTheHmdIsIgnoredWithTheReason()
        {
            foreach (int id in new[] { 4, 0 })
            {
                Calibrator c = Run(i => i == 89 ? new[] { Press(id) } : None, 100);
                Assert.That(c.State, Is.EqualTo(CalibrationState.WaitingForTPose), $"device {id}");
                Assert.That(c.LastStep.Outcome, Is.EqualTo(CalibrationStepOutcome.PressIgnored));
                Assert.That(c.LastStep.Explanation, Does.Contain("only a controller's trigger"));
            }
        }

        [Test]
        public void ASettingAcceptsPressesFromAnyDevice()
        {
            Calibrator c = Run(i => i == 89 ? new[] { Press(4) } : None, 100, new CalibrationSettings { AcceptTriggerFromAnyDevice = true });
            Assert.That(c.State, Is.EqualTo(CalibrationState.WalkIn), c.LastStep.ToString());
        }

        [Test]
        public void APressFromAnUnknownDeviceIsIgnored()
        {
            Calibrator c = Run(i => i == 89 ? new[] { Press(42) } : None, 100);
            Assert.That(c.State, Is.EqualTo(CalibrationState.WaitingForTPose));
            Assert.That(c.LastStep.Explanation, Does.Contain("unknown device id 42"));
        }

        [Test]
        public void AnUntrackedHmdIsNamedWhateverTheDeviceOrder()
        {
            // Every rotation of the device list: the HMD first, last, and everywhere between.
            for (int shift = 0; shift < 6; shift++)
            {
                Calibrator c = Run(i => i == 89 ? new[] { Press(1) } : None, 90,
                    devices: w => { var d = new DeviceInfo[6]; for (int k = 0; k < 6; k++) d[k] = w.Devices[(k + shift) % 6]; return d; },
                    samples: s => s[Array.IndexOf(Wearer.TrueRoles, DeviceRole.Head)] = DeviceSample.Lost);
                Assert.That(c.LastStep.Error, Is.EqualTo(CalibrationError.DeviceNotTracked), $"shift {shift}");
                Assert.That(c.LastStep.Message, Does.Contain("headset"), $"shift {shift}");
            }
        }

        [Test]
        public void WaitingFramesRepeatTheLastMessage()
        {
            Calibrator c = Run(i => i == 89 ? new[] { Press(1) } : None, 95, samples: s => s[Array.IndexOf(Wearer.TrueRoles, DeviceRole.Head)] = DeviceSample.Lost);
            CalibrationStep waiting = c.Update(2.0, new DeviceSample[6], null);
            Assert.That(waiting.Outcome, Is.EqualTo(CalibrationStepOutcome.Waiting));
            Assert.That(waiting.Error, Is.EqualTo(CalibrationError.DeviceNotTracked), "the refusal is still what the wearer is told");
        }
    }
}
