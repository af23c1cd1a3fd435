using System;
using System.IO;
using AvatarGo;
using AvatarGo.Core;
using AvatarGo.Simulation;
using UnityEngine;

namespace AvatarGo.Samples
{
    /// <summary>
    /// The headset-free sample: a synthetic session made from the bundled mocap clip plays through the package's real
    /// components (<see cref="RecordedSessionTrackingSource"/>, <see cref="AvatarGoCalibrator"/> and the Animator IK
    /// driver it adds) on a mannequin built at run time, with the devices drawn, the calibration's messages on screen,
    /// exact or fixed offsets to switch between, and the error against the wearer's true joints.
    /// </summary>
    /// <remarks>
    /// Runs in the Editor's Play mode: the session is synthesised with the package's simulation assembly, which is
    /// Editor-only. The same components play a recording from a headset in a build (see the manual's recording page).
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Samples/Headset-Free Demo")]
    [HelpURL("https://github.com/avatargo/com.avatargo.selfavatar/blob/main/Documentation~/samples.md#headset-free-demo")]
    [DisallowMultipleComponent]
    public sealed class HeadsetFreeDemo : MonoBehaviour
    {
        [SerializeField, Tooltip("The motion the simulated wearer performs: a BVH clip imported as a text asset (.bvh.txt).")]
        private TextAsset m_Motion = null;

        [SerializeField, Tooltip("Where the devices sit on the wearer and the sensor noise (the same seed gives the same session).")]
        private int m_Seed = 1;

        [SerializeField, Tooltip("Exact offsets (the paper's method) or the fixed-offset baseline; switchable while playing.")]
        private OffsetMode m_Offsets = OffsetMode.Exact;

        [SerializeField, Tooltip("Diameter of the cube drawn at each device (m).")]
        private float m_DeviceSize = 0.05f;

        [SerializeField, Tooltip("A camera that keeps the mannequin in view (empty: the camera stays where it is).")]
        private Transform m_Camera = null;

        [SerializeField, Tooltip("Where the camera stands relative to the mannequin's hips, in world axes (m).")]
        private Vector3 m_CameraOffset = new Vector3(1.6f, 0.4f, 2.4f);

        private RecordedSessionTrackingSource _source;
        private AvatarGoCalibrator _calibrator;
        private readonly TruthErrorMeter _meter = new TruthErrorMeter();
        private Transform[] _devices = Array.Empty<Transform>();
        private Transform _hips;
        private string _problem;

        private void Start()
        {
            if (m_Motion == null)
            {
                Fail("assign the Motion clip (Motion/mixamo_fingers_30fps.bvh.txt)");
                return;
            }
            HumanoidMap wearer;
            string session = Path.Combine(AvatarGoFiles.Folder(Application.persistentDataPath), "headset-free-sample" + AvatarGoFiles.SessionExtension);
            try
            {
                wearer = HeadsetFreeSession.Write(m_Motion.text, m_Motion.name, session, new SimulationOptions { Seed = m_Seed });
            }
            catch (Exception e) when (e is FormatException || e is ArgumentException || e is IOException || e is UnauthorizedAccessException)
            {
                Fail($"the session could not be made from {m_Motion.name}: {e.Message}");
                return;
            }

            Animator mannequin = MannequinBuilder.Build(MannequinBlueprint.Create(wearer), transform, this);
            if (mannequin == null)
            {
                Fail("the mannequin is not a valid humanoid");
                return;
            }

            _hips = mannequin.GetBoneTransform(HumanBodyBones.Hips);

            // The components, configured while their object is inactive so that they start with their settings.
            var rig = new GameObject("AvatarGo");
            rig.SetActive(false);
            rig.transform.SetParent(transform, false);
            _source = rig.AddComponent<RecordedSessionTrackingSource>();
            _source.FilePath = session;
            _source.Mode = RecordedSessionTrackingSource.PlaybackMode.RealTime;
            _calibrator = rig.AddComponent<AvatarGoCalibrator>();
            _calibrator.Source = _source;
            _calibrator.Animator = mannequin;
            _calibrator.Offsets = m_Offsets;
            _calibrator.RestoresSavedProfileOnStart = false; // always calibrate from the session's own T-pose and walk-in
            _calibrator.SavesProfile = false;
            _calibrator.FrameRead += OnFrame;
            rig.SetActive(true);
        }

        private void OnDestroy()
        {
            if (_calibrator != null) _calibrator.FrameRead -= OnFrame;
        }

        // Every frame the calibrator ran: draw the devices where the session has them, and measure the error.
        private void OnFrame(SessionFrame frame)
        {
            if (_devices.Length != frame.Samples.Length) MakeDeviceCubes(frame.Samples.Length);
            TrackingSpace space = _calibrator.TrackingSpace;
            for (int d = 0; d < _devices.Length; d++)
            {
                DeviceSample sample = frame.Samples[d];
                _devices[d].gameObject.SetActive(sample.IsUsable);
                if (sample.IsUsable) _devices[d].SetWorldPose(space.ToWorld(sample.Pose));
            }
            SelfAvatarPipeline pipeline = _calibrator.Pipeline;
            if (pipeline != null) _meter.Measure(pipeline.ScaledAvatar, pipeline.Pose, frame, pipeline.State);
        }

        private void MakeDeviceCubes(int count)
        {
            foreach (Transform old in _devices) Destroy(old.gameObject);
            _devices = new Transform[count];
            for (int d = 0; d < count; d++)
            {
                GameObject cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
                cube.name = "Device " + d;
                Destroy(cube.GetComponent<Collider>());
                cube.transform.SetParent(transform, false);
                cube.transform.localScale = new Vector3(m_DeviceSize, m_DeviceSize, m_DeviceSize);
                _devices[d] = cube.transform;
            }
        }

        // After the driver posed the mannequin: the camera looks at its hips from the same side all along.
        private void LateUpdate()
        {
            if (m_Camera == null || _hips == null) return;
            RigidPose hips = _hips.GetWorldPose();
            System.Numerics.Vector3 eye = hips.Position + m_CameraOffset.ToCore();
            System.Numerics.Quaternion look = Rotations.LookRotation(hips.Position - eye, System.Numerics.Vector3.UnitY);
            m_Camera.SetWorldPose(new RigidPose(eye, look));
        }

        // Replays the session from its start with the other offset mode: the calibration runs again on the same motion.
        private void Switch(OffsetMode offsets)
        {
            m_Offsets = offsets;
            _calibrator.Offsets = offsets;
            _meter.Reset();
            _source.Restart();
            _calibrator.ResetCalibration();
        }

        private void OnGUI()
        {
            GUILayout.BeginArea(new Rect(10f, 10f, 460f, 320f));
            GUILayout.Label("AvatarGo: headset-free demo (a synthetic session through the real components)");
            if (_problem != null)
            {
                GUILayout.Label("Not running: " + _problem);
                GUILayout.EndArea();
                return;
            }
            if (_calibrator != null)
            {
                GUILayout.Label($"Calibration: {_calibrator.Flow.State}  |  offsets: {m_Offsets}");
                if (_calibrator.Flow.ShowsMessage) GUILayout.Label(_calibrator.Flow.Message);
                GUILayout.Label(_meter.Frames == 0 ? "Error against the true joints: after calibration"
                    : $"Error against the true joints (mm): all {_meter.LastMeanMm:0.0} (mean {_meter.MeanMm:0.0}), " +
                      $"hands/feet/hips/head {_meter.LastEndEffectorMm:0.0} (mean {_meter.MeanEndEffectorMm:0.0}), " +
                      $"elbows/knees {_meter.LastMidJointMm:0.0} (mean {_meter.MeanMidJointMm:0.0})");
                if (GUILayout.Button(m_Offsets == OffsetMode.Exact ? "Replay with fixed offsets (the baseline)" : "Replay with exact offsets (the paper's)"))
                    Switch(m_Offsets == OffsetMode.Exact ? OffsetMode.Fixed : OffsetMode.Exact);
                if (_source != null && _source.IsFinished && GUILayout.Button("Replay")) Switch(m_Offsets);
            }
            GUILayout.EndArea();
        }

        private void Fail(string problem)
        {
            _problem = problem;
            Debug.LogError($"{nameof(HeadsetFreeDemo)}: {problem}.", this);
        }
    }
}
