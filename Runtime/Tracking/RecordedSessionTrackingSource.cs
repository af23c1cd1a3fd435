using System;
using System.IO;
using AvatarGo.Core;
using UnityEngine;

namespace AvatarGo
{
    /// <summary>
    /// Plays a recorded session (session format v1, <c>.agsession</c>) as the tracking source: in real time (the playback
    /// clock advances by <c>Time.deltaTime</c> times <see cref="Speed"/>, and every trigger press of the frames it passes is
    /// delivered), or one recorded frame per <see cref="Step"/> (play-mode tests). The session comes from a
    /// <see cref="TextAsset"/> (shipped in the build: works on every platform, Quest included; the text is held in memory) or
    /// from a file path (absolute, or relative to <c>Application.persistentDataPath</c>, where <see cref="AvatarGoRecorder"/>
    /// writes; streamed from disk, never held whole). <c>Application.streamingAssetsPath</c> is not used: on Android it is
    /// inside the compressed APK, where file APIs cannot open it.
    /// <para>Disabled, it reports every device lost (as the live sources do), at the time of the frame last delivered: the
    /// playback clock does not advance and nothing recorded is skipped; enabled again, it goes on from there.</para>
    /// </summary>
    [AddComponentMenu("XR/AvatarGo/Recorded Session Tracking Source")]
    [HelpURL(AvatarGoDocs.Manual + "recorded-session-tracking-source.md")]
    [DisallowMultipleComponent]
    public sealed class RecordedSessionTrackingSource : AvatarGoTrackingSource
    {
        /// <summary>How the recording advances.</summary>
        public enum PlaybackMode
        {
            /// <summary>With the application's clock: each frame delivers the newest recorded frame at the playback time.</summary>
            RealTime = 0,

            /// <summary>Only when <see cref="Step"/> is called: one recorded frame per call.</summary>
            Stepped = 1,
        }

        [SerializeField]
        [Tooltip("The session as a text asset (rename 'name.agsession' to 'name.agsession.txt' so Unity imports it as one). Used when set.")]
        private TextAsset m_Session;

        [SerializeField]
        [Tooltip("Otherwise, a session file: an absolute path, or a path relative to Application.persistentDataPath (where AvatarGoRecorder writes).")]
        private string m_FilePath = "";

        [SerializeField]
        [Tooltip("RealTime: plays with the game's (scaled) clock, Time.deltaTime times Speed. Stepped: one recorded frame per Step() call (tests).")]
        private PlaybackMode m_Mode = PlaybackMode.RealTime;

        [SerializeField]
        [Tooltip("Playback speed in real time (1: as recorded).")]
        private float m_Speed = 1f;

        [SerializeField]
        [Tooltip("Start again after the last frame (times keep increasing) instead of holding it.")]
        private bool m_Loop;

        private SessionPlayback _playback;
        private string _text;
        private string _path;
        private int _lastAdvancedFrame = -1;
        private bool _stepPending;
        private bool _failed;

        /// <summary>
        /// The session as a text asset (used when set). Opened in <c>Awake</c> and by <see cref="Restart"/>: set from script
        /// (after <c>AddComponent</c>, whose <c>Awake</c> found none), it plays once <see cref="Restart"/> is called.
        /// </summary>
        public TextAsset Session { get => m_Session; set => m_Session = value; }

        /// <summary>
        /// The session file used when <see cref="Session"/> is empty: absolute, or relative to <c>Application.persistentDataPath</c>.
        /// Opened in <c>Awake</c> and by <see cref="Restart"/>, as <see cref="Session"/> is.
        /// </summary>
        public string FilePath { get => m_FilePath; set => m_FilePath = value; }

        /// <summary>Real time or stepped.</summary>
        public PlaybackMode Mode { get => m_Mode; set => m_Mode = value; }

        /// <summary>Playback speed in real time.</summary>
        public float Speed { get => m_Speed; set => m_Speed = value; }

        /// <summary>Start again after the last frame.</summary>
        public bool Loop
        {
            get => m_Loop;
            set
            {
                m_Loop = value;
                if (_playback != null) _playback.Loop = value;
            }
        }

        /// <inheritdoc/>
        public override SessionHeader Header => _playback?.Header;

        /// <summary>True when a session is loaded and can be played.</summary>
        public bool IsLoaded => _playback != null;

        /// <summary>True once the last frame was delivered (and the playback does not loop).</summary>
        public bool IsFinished => _playback == null || _playback.Finished;

        /// <summary>How many recorded frames have been delivered.</summary>
        public int FramesPlayed => _playback?.FramesPlayed ?? 0;

        /// <summary>
        /// Opens the session again from its start (from <see cref="Session"/> or <see cref="FilePath"/>). Returns false, with
        /// the error logged, when there is none or it cannot be read.
        /// </summary>
        public bool Restart()
        {
            Close();
            _failed = false;
            try
            {
                if (m_Session != null)
                {
                    _text = m_Session.text;
                    string name = m_Session.name;
                    _playback = new SessionPlayback(() => new SessionReader(new StringReader(_text), name), m_Loop);
                }
                else
                {
                    _path = AvatarGoFiles.Resolve(m_FilePath, Application.persistentDataPath);
                    if (_path == null)
                    {
                        Fail("no session is set: assign a TextAsset or a file path");
                        return false;
                    }
                    string path = _path;
                    _playback = new SessionPlayback(() => SessionReader.Open(path), m_Loop);
                }
            }
            catch (Exception e) when (e is IOException || e is FormatException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                Fail($"the session cannot be played: {e.Message}");
                return false;
            }
            HeaderVersion++;
            _lastAdvancedFrame = -1;
            _stepPending = false;
            return true;
        }

        /// <summary>
        /// Stepped mode: the next <see cref="Read"/> delivers the next recorded frame. Returns false when there is none left
        /// (the last frame stays) or nothing is loaded. Steps do not add up: a second call before that read asks for the
        /// same frame (one step per application frame, e.g. <c>Step(); yield return null;</c> in a play-mode test).
        /// </summary>
        public bool Step()
        {
            if (_playback == null || (_playback.Finished && !m_Loop)) return false;
            _stepPending = true;
            return true;
        }

        /// <inheritdoc/>
        public override void Read(SessionFrame frame)
        {
            if (frame == null) return;
            if (_playback == null || _failed || frame.Samples.Length != _playback.Header.Devices.Count)
            {
                frame.Clear();
                return;
            }
            if (!isActiveAndEnabled)
            {
                // Disabled: every device lost, as the live sources report it; the playback waits (its clock, a pending
                // Step and the next frames' presses are kept for when it is enabled again).
                _playback.Pause(frame);
                return;
            }
            try
            {
                if (m_Mode == PlaybackMode.Stepped)
                {
                    if (_stepPending) _playback.Step(frame);
                    else _playback.Repeat(frame);
                    _stepPending = false;
                }
                else if (_lastAdvancedFrame != Time.frameCount)
                {
                    _lastAdvancedFrame = Time.frameCount;
                    _playback.Advance(Math.Max(0f, Time.deltaTime * m_Speed), frame);
                }
                else _playback.Repeat(frame);
            }
            // A loop reopens the file at its end: deleted, locked or unreadable by then is a data error too, not one of this
            // frame's (which would stop the calibrator for good).
            catch (Exception e) when (e is FormatException || e is IOException || e is UnauthorizedAccessException)
            {
                Fail($"the session broke off: {e.Message}");
                frame.Clear();
            }
        }

        private void Awake()
        {
            if (m_Session != null || !string.IsNullOrWhiteSpace(m_FilePath)) Restart();
        }

        private void OnDestroy() => Close();

        private void Close()
        {
            _playback?.Dispose();
            _playback = null;
            _text = null;
        }

        // A setup or data error: logged once with this component as context; the devices read as lost from then on.
        private void Fail(string message)
        {
            _failed = true;
            Debug.LogError($"{nameof(RecordedSessionTrackingSource)} on '{name}': {message}", this);
        }
    }
}
