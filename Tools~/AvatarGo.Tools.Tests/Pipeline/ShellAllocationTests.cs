using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AvatarGo.Core;
using AvatarGo.Simulation;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests.Pipeline;

/// <summary>
/// What the Unity components compute every frame on the core's side allocates nothing, exactly, over a recorded motion
/// after calibration: the Animator IK driver's targets, body and effector compensation, tracking space and foot soles;
/// the binding's local positions; the calibrator's flow, panel and mirror; the recorded source's playback and the
/// recorder's file writing. (The pipeline itself: <see cref="PipelineAllocationTests"/>.) The components add only
/// Unity's own setters to these.
/// </summary>
public class ShellAllocationTests
{
    [Test]
    public void TheComponentsPerFrameCoreWorkAllocatesNothing()
    {
        BvhClip clip = BvhReader.ReadFile(Paths.Mocap("mocapbank_30fps.bvh"), new BvhReadOptions { ToMetres = true });
        var simulator = new SessionSimulator(clip, new SimulationOptions { Seed = 3 });
        var text = new StringWriter();
        using (var writer = new SessionWriter(text, simulator.CreateHeader())) simulator.Run(writer);
        string session = text.ToString();

        using var reader = new SessionReader(new StringReader(session), "shell-allocation");
        var pipeline = new SelfAvatarPipeline(reader.Header.Devices, reader.Header.TruthHumanoid, new PipelineSettings());
        SessionFrame frame = reader.CreateFrame();
        while (pipeline.State != CalibrationState.Calibrated && reader.ReadFrame(frame)) pipeline.Update(frame);
        Assume.That(pipeline.State, Is.EqualTo(CalibrationState.Calibrated), pipeline.LastCalibrationStep.Message);

        HumanoidMap avatar = pipeline.ScaledAvatar;
        Skeleton skeleton = avatar.Skeleton;
        var nodes = new List<HierarchyNode>();
        for (int j = 0; j < skeleton.JointCount; j++)
        {
            RigidPose rest = skeleton.GetRestLocal(j);
            nodes.Add(new HierarchyNode(skeleton.GetName(j), skeleton.GetParent(j), rest.Position, rest.Rotation, Vector3.One));
        }
        Assume.That(HumanoidHierarchy.TryFromNames(nodes, 1f, out HumanoidHierarchy hierarchy, out string error), Is.True, error);

        var targets = new AnimatorIkTargets(avatar);
        var body = new BodyPoseCompensation(avatar);
        var effectors = new EffectorRotationOffsets();
        var flow = new CalibrationFlow();
        var panel = new FollowingPanel();
        var space = new TrackingSpace(new RigidPose(new Vector3(1f, 0f, -2f), Quaternion.CreateFromYawPitchRoll(0.7f, 0f, 0f)), 1.1f);
        var bodySet = RigidPose.Identity;
        int joints = Math.Min(hierarchy.JointCount, pipeline.Pose.Local.Length);
        var sink = new Vector3[1];
        var frames = new List<(double Time, DeviceSample[] Samples)>();
        while (reader.ReadFrame(frame)) frames.Add((frame.Time, (DeviceSample[])frame.Samples.Clone()));
        Assume.That(frames.Count, Is.GreaterThan(250));
        double dt = (frames[frames.Count - 1].Time - frames[0].Time) / (4.0 * frames.Count);

        string partial = Path.Combine(Path.GetTempPath(), "avatargo-shell-alloc-" + Guid.NewGuid().ToString("N") + ".agsession");
        // Played at a quarter of the recorded rate so that both passes stay inside the session (a loop reopens it, which
        // allocates a reader: once per loop, not per frame).
        using var playback = new SessionPlayback(() => new SessionReader(new StringReader(session), "playback"), loop: false);
        var played = new SessionFrame(playback.Header);
        using var recording = new SessionFileRecording(partial, playback.Header);
        try
        {
            long Frame(int i)
            {
                (double time, DeviceSample[] samples) = frames[i];
                pipeline.Update(time, samples, null, null, null); // measured elsewhere; here it only moves the pose
                SkeletonPose pose = pipeline.Pose;
                long before = GC.GetAllocatedBytesForCurrentThread();

                // AvatarGoAnimatorIKDriver.OnAnimatorIK
                body.Observe(bodySet, space.ToTracking(space.ToWorld(pose.World[avatar[HumanoidBone.Hips]])));
                targets.Update(pose);
                bodySet = body.BodyFor(targets.Hips);
                RigidPose world = space.ToWorld(bodySet);
                for (int g = 0; g < 4; g++)
                {
                    RigidPose goal = targets.Goal((IkGoal)g);
                    effectors.Observe((IkGoal)g, goal.Rotation, goal.Rotation);
                    Quaternion rotation = effectors.IsKnown((IkGoal)g) ? effectors.EffectorFor((IkGoal)g, goal.Rotation) : goal.Rotation;
                    Vector3 position = g < 2 ? FootSoles.KeepAboveFloor(goal.Position, rotation, 0.08f, 0f) : goal.Position;
                    world = space.ToWorld(new RigidPose(position, rotation));
                    sink[0] = space.ToWorld(targets.Hint((IkHint)g)) + world.Position;
                }
                for (int b = 0; b < targets.TurnedBoneCount; b++) sink[0].X += (int)targets.TurnedBone(b) + targets.TurnedLocalRotation(b).W;

                // HumanoidBinding.ApplyPose (AvatarGoTransformDriver)
                sink[0].Y += hierarchy.RootScaleFactor(pipeline.Profile.AvatarScale, space.Scale);
                for (int j = 1; j < joints; j++) sink[0] += hierarchy.ToLocalPosition(j, pose.Local[j].Position, pipeline.Profile.AvatarScale);

                // AvatarGoCalibrator.Update / ShowFrame
                flow.Update(time, pipeline.LastCalibrationStep, pipeline.State);
                MirrorPlane mirror = MirrorPlane.InFrontOf(pipeline.Profile.Placement, 1.5f);
                sink[0] += mirror.Reflect(pose.World[0].Position);
                sink[0] += panel.Update(pose.World[avatar[HumanoidBone.Head]], 1f / 90f).Position;

                // RecordedSessionTrackingSource.Read, AvatarGoRecorder.Record
                playback.Advance(dt, played);
                recording.Record(played);
                return GC.GetAllocatedBytesForCurrentThread() - before;
            }
            long Run()
            {
                long bytes = 0;
                for (int i = 0; i < frames.Count; i++) bytes += Frame(i);
                return bytes;
            }
            Run(); // warm up: the JIT, lazily filled caches, the writer's buffers
            Assert.That(Run(), Is.EqualTo(0), $"bytes allocated by {frames.Count} frames of the components' core work");
            Assert.That(effectors.IsKnown(IkGoal.LeftHand), Is.True, "the effector frames were measured (the measuring path ran too)");
            Assert.That(body.HasMeasurement, Is.True);
            Assert.That(playback.Finished, Is.False, "the playback stayed inside the session");
            recording.Complete();
            using var back = new SessionReader(new StreamReader(partial), "read back");
            SessionFrame r = back.CreateFrame();
            int count = 0;
            while (back.ReadFrame(r)) count++;
            Assert.That(count, Is.EqualTo(2 * frames.Count), "every recorded frame reads back");
        }
        finally
        {
            if (File.Exists(partial)) File.Delete(partial);
            if (File.Exists(partial + SessionFileRecording.PartialSuffix)) File.Delete(partial + SessionFileRecording.PartialSuffix);
        }
    }
}
