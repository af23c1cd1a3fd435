using System;
using System.IO;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Records every device's pose and tracking, every analog trigger and grip value and every trigger event to a session
    /// file (format v1, <c>.agsession</c>) as it happens, streamed through the core's <see cref="SessionRecorder"/> (never
    /// the whole session in memory), for replay without a headset (<see cref="RecordedSessionTrackingSource"/>) and
    /// play-mode tests. Started and stopped from script (<see cref="StartRecording"/>, <see cref="StopRecording"/>) or from
    /// the inspector (the <c>Record</c> toggle, also at run time).
    /// </summary>
    /// <remarks>
    /// <para>What is recorded: with a calibrator, the very frame its pipeline was fed (the source is read once a frame, by
    /// the calibrator); without one, the source is read here, in <c>Update</c> (then nothing else may read it).</para>
    /// <para>Files: <c>Application.persistentDataPath/AvatarGo/&lt;folder&gt;/&lt;prefix&gt;-yyyyMMdd-HHmmss.agsession</c>. Frames go
    /// to <c>&lt;file&gt;.partial</c>; stopping writes the end line, flushes it to disk and renames it onto the file in one step.
    /// After a crash the file does not exist and the <c>.partial</c> holds every frame written up to the last flush (about
    /// the last second is lost), without its end line: the session reader reads those frames, then reports it truncated.
    /// Stopping happens when the component is disabled or destroyed and when the application quits. When the source's
    /// devices change, the recording is stopped (a session has one device list) and a warning says so.</para>
    /// </remarks>
    [AddComponentMenu("XR/AvatarGo/Recorder")]
    [HelpURL(AvatarGoDocs.Manual + "recorder.md")]
    [DefaultExecutionOrder(AvatarGoExecutionOrder.Recorder)]
    public sealed class AvatarGoRecorder : MonoBehaviour
    {
        [SerializeField, Tooltip("Record the frames this calibrator reads (recommended). Empty: read the source below directly.")]
        private AvatarGoCalibrator m_Calibrator;

        [SerializeField, Tooltip("The source read when there is no calibrator (nothing else may read it then).")]
        private AvatarGoTrackingSource m_Source;

        [SerializeField, Tooltip("The folder under Application.persistentDataPath/AvatarGo.")]
        private string m_Folder = "Recordings";

        [SerializeField, Tooltip("The start of each file's name (a date and time follow).")]
        private string m_FilePrefix = "session";

        [SerializeField, Tooltip("Recording: switch on or off, in the inspector or from script, at run time too. On at start: records from the first frame.")]
        private bool m_Record;

        private SessionFileRecording _recording;
        private SessionFrame _frame;
        private int _frameHeaderVersion = int.MinValue;
        private int _recordingHeaderVersion;
        private AvatarGoTrackingSource _recordingSource, _frameSource; // the sources the recording and the own frame were made for
        private AvatarGoCalibrator _subscribed;
        private bool _toldWaiting;

        /// <summary>True while recording.</summary>
        public bool IsRecording => _recording != null && _recording.IsOpen;

        /// <summary>The frames recorded in the current (or last) recording.</summary>
        public int FramesRecorded { get; private set; }

        /// <summary>The file of the current or last recording (it exists once stopped).</summary>
        public string LastRecordingPath { get; private set; }

        /// <summary>The calibrator whose frames are recorded.</summary>
        public AvatarGoCalibrator Calibrator
        {
            get => m_Calibrator;
            set
            {
                if (value == m_Calibrator) return;
                m_Calibrator = value;
                if (!isActiveAndEnabled) return; // OnEnable subscribes
                if (_subscribed != null) _subscribed.FrameRead -= Record;
                _subscribed = m_Calibrator;
                if (_subscribed != null) _subscribed.FrameRead += Record;
            }
        }

        /// <summary>The source read when there is no calibrator.</summary>
        public AvatarGoTrackingSource Source { get => m_Source; set => m_Source = value; }

        /// <summary>
        /// Starts a new recording (stopping the current one). Returns false, with the reason logged, when there are no devices
        /// yet or the file cannot be created.
        /// </summary>
        public bool StartRecording()
        {
            StopRecording();
            m_Record = true;
            AvatarGoTrackingSource source = SourceRecorded();
            SessionHeader header = source != null ? source.Header : null;
            if (header == null)
            {
                if (!_toldWaiting) Debug.Log($"{nameof(AvatarGoRecorder)}: the source has no devices yet; recording starts when it has.", this);
                _toldWaiting = true;
                return false;
            }
            _toldWaiting = false;
            string path = null;
            // The path is made inside the try: Path.Combine throws an ArgumentException for characters a path cannot hold
            // (Mono, Windows), and outside it that came back on every frame's retry.
            try
            {
                string folder = Path.Combine(AvatarGoFiles.Folder(Application.persistentDataPath), m_Folder ?? "");
                // A name is taken by a finished recording or by one in progress (another recorder started in the same second)
                // or interrupted (a partial file the last failure's message points to, which must not be truncated).
                path = AvatarGoFiles.NewRecordingPath(folder, m_FilePrefix, DateTime.Now, p => File.Exists(p) || File.Exists(p + SessionFileRecording.PartialSuffix));
                _recording = new SessionFileRecording(path, header);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
            {
                Debug.LogError(path == null
                    ? $"{nameof(AvatarGoRecorder)}: cannot record: the folder '{m_Folder}' or the file prefix '{m_FilePrefix}' is not a valid path; recording is switched off ({e.Message})"
                    : $"{nameof(AvatarGoRecorder)}: cannot record to {path}; recording is switched off ({e.Message})", this);
                m_Record = false; // once: Update does not try again until recording is switched on again
                return false;
            }
            _recordingHeaderVersion = source.HeaderVersion;
            _recordingSource = source;
            FramesRecorded = 0;
            LastRecordingPath = path;
            Debug.Log($"{nameof(AvatarGoRecorder)}: recording {header.Devices.Count} devices to {path}", this);
            if (!ReferenceEquals(_recording.Header, header))
                Debug.LogWarning($"{nameof(AvatarGoRecorder)}: a device serial holds white space (or is \"-\"), which the session format cannot; it is recorded with '_' in its place.", this);
            return true;
        }

        /// <summary>Stops the recording: the file is completed and appears under its name. Does nothing when not recording.</summary>
        public void StopRecording()
        {
            m_Record = false;
            if (_recording == null) return;
            SessionFileRecording recording = _recording;
            _recording = null;
            try
            {
                recording.Complete();
                Debug.Log($"{nameof(AvatarGoRecorder)}: {FramesRecorded} frames recorded to {recording.Path}", this);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                Debug.LogError($"{nameof(AvatarGoRecorder)}: the recording could not be completed ({e.Message}); its frames are in {recording.PartialPath}", this);
            }
        }

        private void OnEnable()
        {
            if (m_Calibrator == null) return;
            _subscribed = m_Calibrator;
            _subscribed.FrameRead += Record;
        }

        private void OnDisable()
        {
            if (_subscribed != null) _subscribed.FrameRead -= Record;
            _subscribed = null;
            bool wanted = m_Record;
            StopRecording();
            m_Record = wanted;
        }

        private void OnApplicationQuit() => StopRecording();

        private void Update()
        {
            if (m_Record && !IsRecording) StartRecording();
            else if (!m_Record && IsRecording) StopRecording();
            if (m_Calibrator != null || m_Source == null) return;
            // No calibrator: this component reads the source itself.
            SessionHeader header = m_Source.Header;
            if (header == null) return;
            if (_frame == null || _frameHeaderVersion != m_Source.HeaderVersion || !ReferenceEquals(m_Source, _frameSource))
            {
                _frame = new SessionFrame(header);
                _frameHeaderVersion = m_Source.HeaderVersion;
                _frameSource = m_Source;
            }
            m_Source.Read(_frame);
            Record(_frame);
        }

        private void Record(SessionFrame frame)
        {
            // The calibrator raises its first frame before this component's Update has run: start here too, so that a
            // recording switched on at start holds that frame.
            if (m_Record && !IsRecording) StartRecording();
            if (!IsRecording) return;
            AvatarGoTrackingSource source = SourceRecorded();
            // Another source set at run time may report the same header version: the source itself is compared too.
            if (source == null || !ReferenceEquals(source, _recordingSource) || source.HeaderVersion != _recordingHeaderVersion || frame.Samples.Length != _recording.Header.Devices.Count)
            {
                Debug.LogWarning($"{nameof(AvatarGoRecorder)}: the source's devices changed; the recording is stopped (a session has one device list). Start a new one to record the new devices.", this);
                StopRecording();
                return;
            }
            try
            {
                _recording.Record(frame);
                FramesRecorded++;
            }
            catch (Exception e) when (e is IOException || e is ArgumentException)
            {
                Debug.LogError($"{nameof(AvatarGoRecorder)}: recording stopped: {e.Message}", this);
                StopRecording();
            }
        }

        private AvatarGoTrackingSource SourceRecorded() => m_Calibrator != null ? m_Calibrator.Source : m_Source;
    }
}
