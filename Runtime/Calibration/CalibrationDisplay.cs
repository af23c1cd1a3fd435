using System;
using AvatarGo.Core;
using UnityEngine;
using Object = UnityEngine.Object;

namespace AvatarGo
{
    /// <summary>
    /// What the calibrator shows in the headset, with built-in objects only: the wearer's instructions as world-space
    /// <see cref="TextMesh"/> text floating in front of the head, a sphere on every device, a mirrored copy of the avatar
    /// (with mirrored markers) beyond a vertical mirror plane in front of it, and the avatar itself hidden until the T-pose
    /// step scales and places it. Every object it creates sits at the scene's root (never inside the avatar, whose
    /// hierarchy is bound) and is destroyed with it.
    /// </summary>
    internal sealed class CalibrationDisplay : IDisposable
    {
        // The built-in font: "Arial.ttf" until 2022.1, "LegacyRuntime.ttf" from 2022.2 (asking for the other throws).
#if UNITY_2022_2_OR_NEWER
        private const string BuiltinFont = "LegacyRuntime.ttf";
#else
        private const string BuiltinFont = "Arial.ttf";
#endif
        private const int LineCharacters = 42;

        private readonly AvatarGoCalibrator _owner;
        private readonly HumanoidBinding _binding;
        private readonly Renderer[] _avatarRenderers;
        private readonly bool[] _hiddenHere; // the renderers this display turned off (forceRenderingOff), to turn on again
        private readonly FollowingPanel _panel = new FollowingPanel();
        private bool _avatarHidden;
        private GameObject _text;
        private TextMesh _textMesh;
        private string _shownMessage;
        private bool _textFailed;
        private GameObject[] _markers = Array.Empty<GameObject>(), _mirrorMarkers = Array.Empty<GameObject>();
        private GameObject _mirrorHolder;
        private HumanoidBinding _mirror;
        private bool _mirrorFailed;

        public CalibrationDisplay(AvatarGoCalibrator owner, HumanoidBinding binding)
        {
            _owner = owner;
            _binding = binding;
            _avatarRenderers = binding.Root.GetComponentsInChildren<Renderer>(true);
            _hiddenHere = new bool[_avatarRenderers.Length];
        }

        /// <summary>
        /// Hides the avatar's renderers, or shows again those it hid. Hidden with <see cref="Renderer.forceRenderingOff"/>,
        /// never <c>enabled</c>: the application's own choice (a head mesh disabled for a first-person view,
        /// before or while the avatar is hidden) is never undone, and only a renderer this display turned off is turned on.
        /// </summary>
        public void ShowAvatar(bool show)
        {
            if (show == !_avatarHidden) return;
            _avatarHidden = !show;
            for (int i = 0; i < _avatarRenderers.Length; i++)
            {
                Renderer renderer = _avatarRenderers[i];
                if (renderer == null) continue;
                if (!show && !renderer.forceRenderingOff)
                {
                    renderer.forceRenderingOff = true;
                    _hiddenHere[i] = true;
                }
                else if (show && _hiddenHere[i])
                {
                    renderer.forceRenderingOff = false;
                    _hiddenHere[i] = false;
                }
            }
        }

        /// <summary>One marker per device (and its mirror image), made again when the devices change.</summary>
        public void SetDeviceCount(int count)
        {
            DestroyAll(_markers);
            DestroyAll(_mirrorMarkers);
            _markers = new GameObject[count];
            _mirrorMarkers = new GameObject[count];
        }

        /// <summary>Places the device markers (and their mirror images) from this frame's samples. Allocation-free once made.</summary>
        public void UpdateMarkers(SessionFrame frame, TrackingSpace space, bool show, bool mirrored, MirrorPlane mirror)
        {
            for (int d = 0; d < _markers.Length && d < frame.Samples.Length; d++)
            {
                DeviceSample s = frame.Samples[d];
                bool visible = show && s.IsUsable;
                Vector3 position = visible ? space.ToWorld(s.Pose.Position).ToUnity() : default;
                Place(ref _markers[d], "AvatarGo Device Marker", visible, position);
                Place(ref _mirrorMarkers[d], "AvatarGo Mirrored Device Marker", visible && mirrored,
                    visible && mirrored ? mirror.Reflect(space.ToWorld(s.Pose.Position)).ToUnity() : default);
            }
        }

        /// <summary>Shows <paramref name="message"/> in front of the head (tracking-space pose), or hides the text when empty.</summary>
        public void UpdateText(string message, bool show, DeviceSample head, TrackingSpace space, float dt)
        {
            bool visible = show && !string.IsNullOrEmpty(message);
            if (!visible)
            {
                if (_text != null) _text.SetActive(false);
                _panel.Reset();
                return;
            }
            if (_text == null && !CreateText()) return;
            _text.SetActive(true);
            if (!ReferenceEquals(message, _shownMessage))
            {
                _shownMessage = message;
                _textMesh.text = TextLines.Wrap(message, LineCharacters);
            }
            if (head.IsUsable)
            {
                RigidPose pose = space.ToWorld(_panel.Update(head.Pose, dt));
                _text.transform.SetWorldPose(pose);
            }
        }

        /// <summary>
        /// Poses the mirrored copy as the avatar is posed now (called once every bone is final, before rendering), or hides
        /// it. <paramref name="mirror"/> is the mirror plane in world space.
        /// </summary>
        public void UpdateMirror(bool show, MirrorPlane mirror)
        {
            if (!show)
            {
                if (_mirrorHolder != null) _mirrorHolder.SetActive(false);
                return;
            }
            if (_binding.Root == null) return; // the avatar is gone (the calibrator fails on its next Update)
            if (_mirror != null && (_mirrorHolder == null || _mirror.Root == null))
            {
                // Destroyed with the scene it was made in (the calibrator lives on in another): made again below.
                _mirror = null;
                _mirrorHolder = null;
            }
            if (_mirror == null && !CreateMirror()) return;
            _mirror.CopyLocalPoses(_binding);
            Transform root = _binding.Root, copy = _mirror.Root;
            copy.SetWorldPose(mirror.ReflectRoot(root.GetWorldPose()));
            Vector3 s = root.lossyScale;
            copy.localScale = new Vector3(-s.x, s.y, s.z);
            _mirrorHolder.SetActive(true);
        }

        /// <summary>Hides everything it shows and shows the avatar (the calibrator was disabled).</summary>
        public void HideAll()
        {
            ShowAvatar(true);
            for (int i = 0; i < _markers.Length; i++) if (_markers[i] != null) _markers[i].SetActive(false);
            for (int i = 0; i < _mirrorMarkers.Length; i++) if (_mirrorMarkers[i] != null) _mirrorMarkers[i].SetActive(false);
            if (_text != null) _text.SetActive(false);
            if (_mirrorHolder != null) _mirrorHolder.SetActive(false);
        }

        public void Dispose()
        {
            ShowAvatar(true);
            DestroyAll(_markers);
            DestroyAll(_mirrorMarkers);
            if (_text != null) Object.Destroy(_text);
            if (_mirrorHolder != null) Object.Destroy(_mirrorHolder);
            _text = null;
            _mirrorHolder = null;
            _mirror = null;
        }

        private bool CreateText()
        {
            if (_textFailed) return false;
            Font font;
            try
            {
                font = Resources.GetBuiltinResource<Font>(BuiltinFont);
            }
            catch (ArgumentException e)
            {
                font = null;
                Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the built-in font {BuiltinFont} is missing ({e.Message}); the instructions are shown in the console only.", _owner);
            }
            if (font == null)
            {
                _textFailed = true;
                return false;
            }
            _text = new GameObject("AvatarGo Instructions");
            _textMesh = _text.AddComponent<TextMesh>();
            // Made again after the last one was destroyed with its scene (the calibrator lives on in another): the message
            // shown there is written to this one too, though it is the same string.
            _shownMessage = null;
            _textMesh.font = font;
            _textMesh.fontSize = 64;
            _textMesh.characterSize = _owner.TextSize;
            _textMesh.anchor = TextAnchor.MiddleCenter;
            _textMesh.alignment = TextAlignment.Center;
            _text.GetComponent<MeshRenderer>().sharedMaterial = font.material;
            return true;
        }

        private void Place(ref GameObject marker, string name, bool visible, Vector3 position)
        {
            if (!visible)
            {
                if (marker != null) marker.SetActive(false);
                return;
            }
            if (marker == null)
            {
                marker = GameObject.CreatePrimitive(PrimitiveType.Sphere);
                marker.name = name;
                Collider collider = marker.GetComponent<Collider>();
                if (collider != null) Object.Destroy(collider); // a marker must not be hit by rays or bodies
                float size = _owner.MarkerSize;
                marker.transform.localScale = new Vector3(size, size, size);
            }
            marker.SetActive(true);
            marker.transform.position = position;
        }

        // The mirrored copy: the avatar instantiated under an inactive holder (so that none of its scripts wakes up), its
        // scripts and colliders removed and its Animators disabled, its renderers as the application has the avatar's.
        private bool CreateMirror()
        {
            if (_mirrorFailed) return false;
            _mirrorHolder = new GameObject("AvatarGo Mirror");
            _mirrorHolder.SetActive(false);
            GameObject copy = Object.Instantiate(_binding.Root.gameObject, _mirrorHolder.transform);
            copy.name = _binding.Root.name + " (mirror)";
            // Last first: a script that [RequireComponent]s another is added after it (AddComponent adds the required one
            // first), and Unity refuses to remove a component another one on its GameObject still requires. Destroyed in
            // the order found, the required script would stay on the copy and run when the holder is shown.
            MonoBehaviour[] scripts = copy.GetComponentsInChildren<MonoBehaviour>(true);
            for (int i = scripts.Length - 1; i >= 0; i--) Object.DestroyImmediate(scripts[i]);
            foreach (Animator animator in copy.GetComponentsInChildren<Animator>(true)) animator.enabled = false;
            // A picture, not a body: no collider (a CharacterController is one) for rays, hands or bodies to hit.
            foreach (Collider collider in copy.GetComponentsInChildren<Collider>(true)) Object.DestroyImmediate(collider);
            // Its renderers as the application has the avatar's (their enabled state is copied); none hidden by this display.
            Renderer[] renderers = copy.GetComponentsInChildren<Renderer>(true);
            for (int i = 0; i < renderers.Length && i < _hiddenHere.Length; i++)
                if (_hiddenHere[i]) renderers[i].forceRenderingOff = false;
            _mirror = _binding.OnCopy(copy.transform);
            if (_mirror != null) return true;
            Debug.LogWarning($"{nameof(AvatarGoCalibrator)}: the avatar's copy for the mirror does not have the avatar's hierarchy; no mirror is shown.", _owner);
            Object.Destroy(_mirrorHolder);
            _mirrorHolder = null;
            _mirrorFailed = true;
            return false;
        }

        private static void DestroyAll(GameObject[] objects)
        {
            for (int i = 0; i < objects.Length; i++)
                if (objects[i] != null) Object.Destroy(objects[i]);
        }
    }
}
